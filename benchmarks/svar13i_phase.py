"""Issue 13 point 1, helper svar13i: rings p2 (tiles 14, radius 20, hub 8, spacing 52)
fails g[tile,hub] for synth AND for a perfect continuation (``svar13i_oracle.py``). Is
it the exemplar frame's phase against the ring lattice?

The generator is drawn larger (8 x 8 hubs, variant seed 7) and cropped by centres, as
``make.py`` crops, to frames of the exemplar's size (4 x 4 periods) at other offsets
(in periods of the lattice); one oracle (the generator at 14 x 14 hubs, seed 101) is
judged against each frame by ``strew.metrics.fidelity``. Printed per offset: the metric
against its tolerance and the ring peak of g[tile,hub] (exemplar vs oracle). Baseline:
none (the figures are the spread over phases). JSON: ``benchmarks/results/svar13i_phase.json``.

    python benchmarks/svar13i_phase.py
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import fidelity_suite  # noqa: E402

from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402

KW = dict(tiles=14, radius=20.0, hub=8.0, spacing=52.0)
OFFSETS = [(0.0, 0.0), (0.25, 0.0), (0.5, 0.0), (0.0, 0.5), (0.25, 0.5), (0.5, 0.5), (0.125, 0.25)]


def main() -> None:
    mk = fidelity_suite()
    sp, hh = KW["spacing"], KW["spacing"] * np.sqrt(3) / 2
    big = mk.make_exemplar("rings", rng=7, nx=8, ny=8, **KW)
    oracle = mk.make_exemplar("rings", rng=101, nx=14, ny=14, **KW)
    rows = []
    frames = [("make.py frame", mk.make_exemplar("rings", rng=7, **KW))]
    w, h = 4 * sp, 4 * hh
    for fx, fy in OFFSETS:
        x0, y0 = sp + fx * sp, 2 * hh + fy * hh
        ex = big.select((big.x >= x0) & (big.x < x0 + w) & (big.y >= y0) & (big.y < y0 + h))
        frames.append((f"offset ({fx:.3f}, {fy:.3f})", ex.replace(x=ex.x - x0, y=ex.y - y0, region=Region.rectangle(w, h))))
    for label, ex in frames:
        rep = fidelity(ex, oracle, eq5=False, local=False)
        m = rep.metrics["g[tile,hub]"]
        row = {"frame": label, "n": len(ex), "g_tile_hub": round(m.value, 4), "tolerance": round(m.tolerance, 4), "faithful": rep.faithful,
               "peak_exemplar": round(float(np.nanmax(rep.g_exemplar["tile,hub"])), 3), "peak_oracle": round(float(np.nanmax(rep.g_result["tile,hub"])), 3)}
        rows.append(row)
        print(f"  {label:24s} n={len(ex)} g[tile,hub]={m.value:.3f}/{m.tolerance:.3f} faithful={rep.faithful} peak exemplar {row['peak_exemplar']:.2f} oracle {row['peak_oracle']:.2f}", flush=True)
    out = Path(__file__).resolve().parent / "results" / "svar13i_phase.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"benchmark": "svar13i_phase", "params": KW, "rows": rows}, indent=1) + "\n")
    print(f"figures written to {out}")


if __name__ == "__main__":
    main()

"""Issue 13 point 1, helper anchor13k: what synth makes of one audit case (counts per kind,
anchors, fidelity failures), to find the cause of a stall or of clumps before a fix.

    python benchmarks/anchor13k_diag.py [--harder] NAME INDEX VSEED [--seeds 1,2] [--scale 3.5]
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite  # noqa: E402
from synth_variants import _harder  # noqa: E402
import _variants  # noqa: E402

from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402
from strew.synth import synthesize  # noqa: E402
from strew.synth._prepare import prepare  # noqa: E402
from strew.synth._api import as_selection  # noqa: E402


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("name")
    ap.add_argument("index", type=int)
    ap.add_argument("vseed", type=int)
    ap.add_argument("--harder", action="store_true")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--scale", type=float, default=3.5)
    a = ap.parse_args()
    mk = _harder_suite()
    kw = (_harder() if a.harder else {k: v for k, v in {}.items()})[a.name][a.index] if a.harder else _variants.VARIED[a.name][a.index]
    ex = mk.make_exemplar(a.name, rng=a.vseed, **kw)
    print(a.name, kw, "exemplar", len(ex), "per kind", np.bincount(ex.kind))
    prep = prepare(as_selection(ex))
    for k in np.unique(ex.kind):
        m = ex.kind == k
        print(f"  kind {k}: n={m.sum()} class={np.unique(prep.size_class[:len(ex)][m])} children={np.sum(np.isin(prep.parent[:len(ex)], np.flatnonzero(m)))} parent-kinds={np.unique(ex.kind[prep.parent[:len(ex)][m][prep.parent[:len(ex)][m] >= 0]])}")
    x0, y0, x1, y1 = ex.region.bounds
    for seed in [int(s) for s in a.seeds.split(",")]:
        t0 = time.process_time()
        out = synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=seed, measure=False)
        dt = time.process_time() - t0
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        print(f"seed {seed}: n={len(out)} per kind {np.bincount(out.kind)} {dt:.1f}s faithful={rep.faithful} {' '.join(fails)}", flush=True)


if __name__ == "__main__":
    main()

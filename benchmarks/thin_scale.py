"""Cost of synth's ``thin_small`` (issue 13 point 6: speed; the pass of helper syn13z)
against the whole synthesis, over a range of region sizes.

``PYTHONPATH=src python benchmarks/thin_scale.py [--scales 1.5,3.5,8,16] [--json F]``
grows the one-kind stones exemplar with scales 1 +- 0.35 (``--harder`` h2s7: variant seed
7, 120 stones) in square regions ``scale`` times the exemplar's side, seeds 1-2, and prints
per run the element count, the number thinned, the CPU seconds of ``thin_small`` and of the
whole run, and the output's digest (equal digests on two trees: the same output).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))


def main() -> None:
    from strew_testing import fidelity_suite

    import strew.synth._thin as T
    from strew import Region
    from strew.synth import synthesize

    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scales", default="1.5,3.5,8,16")
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    orig, stat = T.thin_small, {}

    def timed(state, since=0):
        t = time.process_time()
        stat["removed"] = orig(state, since=since)
        stat["thin_s"] = time.process_time() - t
        return stat["removed"]

    T.thin_small = timed
    ex = fidelity_suite().make_exemplar("stones", rng=7, count=120, spread=0.35)
    x0, y0, x1, y1 = ex.region.bounds
    rows = []
    for f in [float(v) for v in a.scales.split(",")]:
        for seed in (1, 2):
            t = time.process_time()
            out = synthesize(ex, Region.rectangle(f * (x1 - x0), f * (y1 - y0)), rng=seed, measure=False)
            tot = time.process_time() - t
            h = hashlib.sha1(np.ascontiguousarray(np.asarray(out.xy)).tobytes()).hexdigest()[:16]
            rows.append({"scale": f, "seed": seed, "n": len(out), "removed": stat["removed"], "thin_s": stat["thin_s"], "total_s": tot, "digest": h})
            print(f"scale {f:5.1f} seed {seed}: n={len(out):6d} thinned {stat['removed']:5d}  thin {stat['thin_s']:6.2f} s of {tot:6.2f} s CPU  {h}", flush=True)
    if len(rows) >= 4:
        lo, hi = rows[0], rows[-1]
        if lo["thin_s"] > 0 and hi["n"] > lo["n"]:
            e = np.log(max(hi["thin_s"], 1e-6) / max(lo["thin_s"], 1e-6)) / np.log(hi["n"] / lo["n"])
            print(f"thin_small cost exponent over n {lo['n']} -> {hi['n']}: {e:.2f}")
    if a.json:
        Path(a.json).write_text(json.dumps({"benchmark": "thin_scale", "rows": rows}, indent=1))
        print("figures written to", a.json)


if __name__ == "__main__":
    main()

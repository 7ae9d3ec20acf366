"""Helper seam13m: ``tests/synth/test_synth_context.py::test_region_grown_against_context_has_no_seam``
over many seeds. The test checks one seed pair (first output rng=1, the output grown
against its left half rng=101); a rule that changes the first output anywhere changes
the second everywhere (growth starts from other context elements), so its single
density ratio is a draw, not a measure of the rule. Printed per seed pair (s, 100 + s):
the strip-over-interior density ratio (the test: within 0.1 of 1), the worst kind
fraction difference over its bound, whether the union is faithful, the worst local
window and the overlaps with the context.

    python benchmarks/seam13m_context_sweep.py [--seeds 1-16] [--json PATH]

Figures (02:0x UTC, seeds 1-16, ``benchmarks/results/seam13m_context_sweep_*.json``): on
61d61c7 the ratio is 1.065 +- 0.075 (mean +- sd), outside 1 +- 0.1 at 7 of 16 seeds, and
the whole test fails at 7 of 16 seeds (s4, 5, 6, 8, 9, 13, 14; seed 1, the test's, reads
1.011). With the rejected clip-before-holes rule (``seam13m_clip_before_holes.diff``):
1.064 +- 0.045, outside at 4 of 16, the test fails at 5 of 16 (s1 at 1.111, 5, 7, 8, 16).
The single-seed test is a coin flip for any change to the first output; the seam strip
is about 6 % denser than the new half's interior on both trees.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import SKIPPED, fidelity_suite  # noqa: E402

from strew import Region  # noqa: E402
from strew.arrangement import concat  # noqa: E402
from strew.metrics import fidelity, overlaps  # noqa: E402
from strew.synth import synthesize  # noqa: E402


def _strip_stats(arr, xa, xb, y0, y1):
    m = (arr.x >= xa) & (arr.x < xb) & (arr.y >= y0) & (arr.y < y1)
    frac = np.bincount(np.asarray(arr.kind)[m], minlength=len(arr.kinds)) / max(int(m.sum()), 1)
    return m.sum() / ((xb - xa) * (y1 - y0)), frac


def one(ex, seed: int) -> dict:
    x0, y0, x1, y1 = ex.region.bounds
    w, h = 3 * (x1 - x0), 3 * (y1 - y0)
    region = Region.rectangle(w, h)
    first = synthesize(ex, region, rng=seed, measure=False)
    ctx = first.select(first.x < w / 2)
    new = synthesize(ex, region, rng=100 + seed, measure=False, context=ctx)
    both = concat([ctx, new])
    band = 0.5 * (x1 - x0)
    d_in, f_in = _strip_stats(new, w / 2 + band, w - band / 2, 0.1 * h, 0.9 * h)
    d_seam, f_seam = _strip_stats(both, w / 2 - band / 2, w / 2 + band / 2, 0.1 * h, 0.9 * h)
    rep = fidelity(ex, both, region, eq5=False)
    score = np.asarray(rep.local["score"], float)
    return dict(seed=seed, ratio=float(d_seam / d_in), frac=float(np.max(np.abs(f_seam - f_in) / (0.1 * f_in + 0.02))),
                faithful=bool(rep.faithful), worst=float(np.nanmax(score)), overlaps=int(len(overlaps(both)[0])))


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("seam13m_context_sweep: skipped (minutes)")
        sys.exit(SKIPPED)
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="1-16")
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    lo, hi = (int(v) for v in a.seeds.split("-"))
    ex = fidelity_suite().make_exemplar("two_sizes")
    rows = []
    for seed in range(lo, hi + 1):
        r = one(ex, seed)
        rows.append(r)
        ok = abs(r["ratio"] - 1) < 0.1 and r["frac"] <= 1 and r["faithful"] and r["worst"] <= 1 and r["overlaps"] == 0
        print(f"s{seed:<3d} ratio {r['ratio']:.3f} frac/bound {r['frac']:.2f} faithful {r['faithful']} worst {r['worst']:.3f} overlaps {r['overlaps']}  {'pass' if ok else 'FAIL'}", flush=True)
    rr = np.array([r["ratio"] for r in rows])
    print(f"ratio over {len(rr)} seeds: mean {rr.mean():.3f} sd {rr.std():.3f}; outside 1 +- 0.1: {int((np.abs(rr - 1) >= 0.1).sum())}")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"benchmark": "seam13m_context_sweep", "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()

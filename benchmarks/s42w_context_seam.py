"""s42w (issue 13 point 2, s39w's figure): seam/interior density ratio of two sizes grown
against a context, as ``tests/synth/test_synth_context.py::
test_region_grown_against_context_has_no_seam`` measures it, at seed pairs k / 100 + k.

    PYTHONPATH=src:tests python benchmarks/s42w_context_seam.py 1-7

Prints each pair's ratio (the test asks |ratio - 1| < 0.1) and how many pairs are within.
"""

from __future__ import annotations

import sys

from strew import Region
from strew.arrangement import concat
from strew.synth import synthesize
from strew_testing import fidelity_suite


def _strip_density(arr, xa: float, xb: float, y0: float, y1: float) -> float:
    m = (arr.x >= xa) & (arr.x < xb) & (arr.y >= y0) & (arr.y < y1)
    return m.sum() / ((xb - xa) * (y1 - y0))


def ratio(k: int) -> float:
    ex = fidelity_suite().make_exemplar("two_sizes")
    x0, y0, x1, y1 = ex.region.bounds
    w, h = 3 * (x1 - x0), 3 * (y1 - y0)
    region = Region.rectangle(w, h)
    first = synthesize(ex, region, rng=k, measure=False)
    ctx = first.select(first.x < w / 2)
    new = synthesize(ex, region, rng=100 + k, measure=False, context=ctx)
    both = concat([ctx, new])
    band = 0.5 * (x1 - x0)
    d_in = _strip_density(new, w / 2 + band, w - band / 2, 0.1 * h, 0.9 * h)
    d_seam = _strip_density(both, w / 2 - band / 2, w / 2 + band / 2, 0.1 * h, 0.9 * h)
    return float(d_seam / d_in)


if __name__ == "__main__":
    a, _, b = sys.argv[1].partition("-")
    ks = range(int(a), int(b or a) + 1)
    rs = []
    for k in ks:
        rs.append(ratio(k))
        print(f"pair {k}/{100 + k}: seam/interior {rs[-1]:.3f}", flush=True)
    print(f"within 0.1: {sum(abs(r - 1) < 0.1 for r in rs)}/{len(rs)}")

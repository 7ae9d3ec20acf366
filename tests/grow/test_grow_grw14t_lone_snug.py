"""Issue 14 point 1 on untuned exemplars (helper grw14t): three sizes 30:60:60
(``--harder`` three_sizes h9, exemplar drawn with seed 8).

The lone-larger swap (``grow/_lone_larger.py``) put a smaller element at the centre of the
large stone it took out, where no ring proposes a spot: the small stone sat as lone in the
large one's hole as the large one had been. The audit's row (3.5x) failed nn[small>large]
(0.095-0.099 against 0.087, seeds 1-2; 3/6 at seeds 1-6). The seed now goes snug against a
remaining larger neighbour, at a spot the reference has (6/6).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow


def _seen_nearest(arr, a, c):
    """Distances from each element of kind ``a`` to its nearest ``c``, for those that see it
    within the frame (the fidelity judge's edge rule)."""
    ka, kc = arr.kinds.index(a), arr.kinds.index(c)
    ia = np.flatnonzero(arr.kind == ka)
    d = cKDTree(arr.xy[arr.kind == kc]).query(arr.xy[ia])[0]
    return d[d <= np.asarray(arr.region.distance_to_boundary(arr.xy[ia]), dtype=float)]


def test_swapped_small_stones_not_left_lone():
    ex = fidelity_suite().make_exemplar("three_sizes", rng=8, counts=(30, 60, 60))
    farthest = float(_seen_nearest(ex, "small", "large").max())
    x0, y0, x1, y1 = ex.region.bounds
    shares = []
    for seed in (1, 2):
        out = grow(ex, region=Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed)
        d = _seen_nearest(out, "small", "large")
        assert len(d) >= 50
        shares.append(float(np.mean(d > farthest)))
    # small stones farther from every large one than the exemplar ever has one, seeds 1-2:
    # dd7c483 0.151, 0.140 (mean 0.146); now 0.110, 0.102 (mean 0.106)
    assert float(np.mean(shares)) <= 0.125

"""Issue 14 point 1 on untuned exemplars (helper grw14u): three sizes 30:60:60
(``--harder`` three_sizes h9, exemplar drawn with seed 7).

The exemplar's medium stones come in pairs (nearest medium 13.5-15.7 units away up to the
80th percentile). The growth left medium stones alone among large ones: the medium slots
of their rings were held by large or small stones grown first (§5.1's size priority),
and the audit's row (3.5x) failed nn[medium>medium] (0.22-0.30 against 0.184, seeds 1-6).
A lone element now gets a second of its kind beside it (``grow/_lone_kin.py``).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow


def _seen_kin(arr, a):
    """Distances from each element of kind ``a`` to its nearest other ``a``, for those that
    see it within the frame (the fidelity judge's edge rule)."""
    ia = np.flatnonzero(arr.kind == arr.kinds.index(a))
    d = cKDTree(arr.xy[ia]).query(arr.xy[ia], k=2)[0][:, 1]
    return d[d <= np.asarray(arr.region.distance_to_boundary(arr.xy[ia]), dtype=float)]


def test_medium_stones_not_left_lone():
    ex = fidelity_suite().make_exemplar("three_sizes", rng=7, counts=(30, 60, 60))
    upper = float(np.quantile(_seen_kin(ex, "medium"), 0.9))
    x0, y0, x1, y1 = ex.region.bounds
    shares = []
    for seed in (1, 2):
        out = grow(ex, region=Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed)
        d = _seen_kin(out, "medium")
        assert len(d) >= 100
        shares.append(float(np.mean(d > upper)))
    # medium stones beyond the exemplar's upper decile of nearest-medium distances (0.1 of
    # its own), seeds 1-2: a2b29a1 0.372, 0.269 (mean 0.320); now 0.296, 0.241 (mean 0.269)
    assert float(np.mean(shares)) <= 0.295

"""Issue 14 point 1 on untuned exemplars (helper gvar14f): grit, a smaller kind that the
hollows of a larger kind's outline hold across (twice its radius).

- Grit between stones (the audit's two_sizes p2s8: ``ratio=0.15``): pebbles grew nearer
  the stones than the exemplar ever has them (nn[stone>pebble] 0.072-0.075 against
  0.060 at e1d86dd); they now keep ``GAP_GRIT`` of the exemplar's least gap between the
  two kinds' bounding discs.
- Small stones among boulders (the audit's three_sizes p3s8: ratios 1:3:7): small stones
  grew nearer each other than the exemplar has any (nn[small>small] 0.060 against 0.052
  at e1d86dd); the smallest kind, where it is grit, keeps ``GAP_SMALLEST`` of the
  exemplar's least gap between its bounding discs.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.grow._growth import GAP_GRIT, GAP_SMALLEST
from strew.metrics import fidelity, overlaps


def _region(ex, side):
    x0, y0, x1, y1 = ex.region.bounds
    return Region.rectangle(side * (x1 - x0), side * (y1 - y0))


def _disc_gaps(arr, k1, k2):
    """Per element of kind ``k1``: the least gap between its scaled bounding disc and
    that of an element of kind ``k2`` (another one where ``k1 == k2``)."""
    R = np.array([arr.shapes[k].radius for k in arr.kinds])[arr.kind] * np.abs(arr.scale)
    a = np.flatnonzero(arr.kind == arr.kinds.index(k1))
    b = np.flatnonzero(arr.kind == arr.kinds.index(k2))
    d, j = cKDTree(arr.xy[b]).query(arr.xy[a], k=min(8, len(b)))
    g = d - R[a][:, None] - R[b[j]]
    g[b[j] == a[:, None]] = np.inf
    return g.min(axis=1)


def _fails(rep):
    return [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]


def _check(ex, out, region):
    assert len(out) >= 10 * len(ex)
    assert len(overlaps(out)[0]) == 0
    assert bool(np.all(region.contains(out.xy)))
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, _fails(rep)


@pytest.mark.slow
def test_grit_keeps_its_gap_from_the_stones():
    ex = fidelity_suite().make_exemplar("two_sizes", rng=8, ratio=0.15, n_large=50, n_small=500)
    lo = float(_disc_gaps(ex, "stone", "pebble").min())
    assert lo > 1.0  # drawn 1.2 apart
    region = _region(ex, 3.5)
    out = grow(ex, region=region, rng=1)
    # the stones whose nearest pebble comes nearer than GAP_GRIT of the exemplar's least
    # gap (a stone placed beside a pebble is not refused: the rule holds one way round):
    # 24 % at e1d86dd, 2.7 % now
    assert float(np.mean(_disc_gaps(out, "stone", "pebble") < GAP_GRIT * lo)) <= 0.05
    _check(ex, out, region)  # e1d86dd: nn[stone>pebble]=0.0724/0.0595


@pytest.mark.slow
def test_small_stones_among_boulders_keep_their_gap():
    ex = fidelity_suite().make_exemplar("three_sizes", rng=8, small=2.0, ratios=(1.0, 3.0, 7.0), counts=(300, 30, 8))
    lo = float(_disc_gaps(ex, "small", "small").min())
    assert lo > 1.0
    region = _region(ex, 3.5)
    out = grow(ex, region=region, rng=1)
    # small stones nearer another than GAP_SMALLEST of the exemplar's least gap:
    # 10.5 % at e1d86dd, none now
    assert float(np.mean(_disc_gaps(out, "small", "small") < GAP_SMALLEST * lo)) <= 0.01
    _check(ex, out, region)  # e1d86dd: nn[small>small]=0.0598/0.0522
    again = grow(ex, region=region, rng=1)
    assert np.array_equal(again.xy, out.xy) and np.array_equal(again.kind, out.kind)

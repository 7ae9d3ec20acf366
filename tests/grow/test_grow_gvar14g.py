"""Issue 14 point 1 on untuned exemplars (helper gvar14g): stones with no pebble near
them where the sizes are close (the audit's two_sizes p3s8: ``ratio=0.6``).

The growth put stones where the exemplar has pebbles: patches of stones grew with no
pebble as near as the exemplar always has one (the stones' nearest-pebble distances
long in the upper deciles; nn[stone>pebble] 0.057-0.060 against 0.054 on seeds 1-2 at
a12a5fb). :mod:`strew.grow._lone_larger` takes the excess of such stones out for
pebbles after the growth.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity, overlaps


def _region(ex, side):
    x0, y0, x1, y1 = ex.region.bounds
    return Region.rectangle(side * (x1 - x0), side * (y1 - y0))


def _stone_to_pebble(arr, region):
    """Each stone's distance to its nearest pebble, for the stones that see it inside
    ``region`` (as the fidelity judge counts them)."""
    st = arr.xy[arr.kind == arr.kinds.index("stone")]
    pb = arr.xy[arr.kind == arr.kinds.index("pebble")]
    d = cKDTree(pb).query(st)[0]
    return d[d <= region.distance_to_boundary(st)]


def _fails(rep):
    return [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2])
def test_close_sizes_keep_a_pebble_near_every_stone(seed):
    ex = fidelity_suite().make_exemplar("two_sizes", rng=8, ratio=0.6, n_large=40, n_small=120)
    d_ex = _stone_to_pebble(ex, ex.region)
    far = float(d_ex.max())
    region = _region(ex, 3.5)
    out = grow(ex, region=region, rng=seed)
    d_out = _stone_to_pebble(out, region)
    # the stones whose nearest pebble is farther than the exemplar ever has one (by
    # definition none of its own): 7-8 % at a12a5fb, none now
    assert float(np.mean(d_out > far)) <= 0.02
    assert len(out) >= 10 * len(ex)
    assert len(overlaps(out)[0]) == 0
    assert bool(np.all(region.contains(out.xy)))
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, _fails(rep)  # a12a5fb: nn[stone>pebble]=0.0574/0.0537, 0.0601/0.0537
    again = grow(ex, region=region, rng=seed)
    assert np.array_equal(again.xy, out.xy) and np.array_equal(again.kind, out.kind)

"""Issue 14 point 1 on untuned exemplars (helper gvar14i): the harder audit's
(``python benchmarks/grow_variants.py --harder``) two sizes at ratio 0.8 (variant 7, 9
pebbles among 38 stones). Both kinds are of one size level, so the lone-stone pass
(:mod:`strew.grow._lone_larger`) did not look, and patches of stones grew with no pebble
near (nn[stone>pebble] 0.264-0.290 against 0.263 at 31cff62; 19-21 % of the stones
farther from a pebble than the exemplar's farthest, 2-4 % now). The pass now also orders kinds of
one level by size (``LONE_ONE_LEVEL``).
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


def _fails(rep):
    return [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]


def _check(ex, out, region, seed):
    assert len(out) >= 10 * len(ex)
    assert len(overlaps(out)[0]) == 0
    assert bool(np.all(region.contains(out.xy)))
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, _fails(rep)
    again = grow(ex, region=region, rng=seed)
    assert np.array_equal(again.xy, out.xy) and np.array_equal(again.kind, out.kind)


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2])
def test_one_level_sizes_keep_a_pebble_near_every_stone(seed):
    ex = fidelity_suite().make_exemplar("two_sizes", rng=7, ratio=0.8, n_large=50, n_small=80)
    st, pb = ex.kind == ex.kinds.index("stone"), ex.kind == ex.kinds.index("pebble")
    d_ex = cKDTree(ex.xy[pb]).query(ex.xy[st])[0]
    far = float(d_ex[d_ex <= ex.region.distance_to_boundary(ex.xy[st])].max())
    region = _region(ex, 3.5)
    out = grow(ex, region=region, rng=seed)
    st, pb = out.kind == out.kinds.index("stone"), out.kind == out.kinds.index("pebble")
    d = cKDTree(out.xy[pb]).query(out.xy[st])[0]
    d = d[d <= region.distance_to_boundary(out.xy[st])]
    # the stones farther from any pebble than the exemplar's farthest: 19 % and 21 % at
    # 31cff62, 4 % and 2 % now
    assert float(np.mean(d > far)) <= 0.08
    _check(ex, out, region, seed)  # 31cff62: nn[stone>pebble]=0.264/0.263, 0.29/0.263

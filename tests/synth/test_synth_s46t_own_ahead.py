"""Issue 13 point 1 (helpers s44t, s46t): three sizes 60:60:26 (``benchmarks/_variants.py`` EDGE
set, --varied p4, variant seed 27). Its largest class covers 0.256 of the exemplar's inner
frame, above ``_grow.OWN_COVER``, so the ownership rule (``_grow._not_owned``) was off and
the union of overlapping copies placed 1.24 of the large stones' inner density right after
growth (seed 1); ``_farmix.trade_far_top`` then put a medium stone at the closest approach
beside each large one lacking one. Main failed fraction[large], density[large] and
nn[large>medium] (0.12 / 0.111) at seed 1. Now the largest class is owned while the output
runs ahead of its density in the area growth has closed, measured on a grid
(``_grow._top_ahead``, ``_grow._closed_counts``), and in such an output the trade's sites
are tried nearest a drawn exemplar distance first (``_farmix.TOP_DRAW``)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew._fidelity import fidelity
from strew.metrics import overlaps
from strew.synth import synthesize
from strew.synth._api import new_state
from strew.synth._displace import _inner_density

P4 = {"counts": (60, 60, 26)}


@pytest.mark.slow
def test_large_stones_not_over_placed_nor_medium_at_closest_approach():
    ex = fidelity_suite().make_exemplar("three_sizes", rng=27, **P4)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1, measure=False)
    assert len(overlaps(out)[0]) == 0
    prep = new_state(ex).prep
    margin = 2.0 * float(prep.rc.max())
    dens = _inner_density(prep, margin)
    inner = out.region.geometry.buffer(-margin)
    large, medium = ex.kinds.index("large"), ex.kinds.index("medium")
    pl, pm = out.xy[out.kind == large], out.xy[out.kind == medium]
    inl = pl[shapely.contains_xy(inner, pl[:, 0], pl[:, 1])]
    sk_large = int(np.unique(prep.skind[prep.kind == large])[0])
    ratio = len(inl) / float(inner.area) / float(dens[sk_large])
    # main (76c5b94): 1.237; now 1.086
    assert ratio < 1.15, ratio
    # large stones whose nearest medium stands nearer than the exemplar's closest
    # large-medium pair: main 0.23 (the exemplar: none)
    el, em = ex.xy[ex.kind == large], ex.xy[ex.kind == medium]
    closest = float(cKDTree(em).query(el)[0].min())
    near = float(np.mean(cKDTree(pm).query(inl)[0] < closest))
    assert near < 0.19, near
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, [k for k, m in rep.metrics.items() if m.applicable and not m.passed]


@pytest.mark.slow
def test_p4s29_medium_stones_keep_their_small_neighbours():
    # the same set at variant seed 29 (cover 0.281): main failed seed 5 with
    # nn[medium>small] 0.343 / 0.277 (large stones 1.18 of their density after growth)
    ex = fidelity_suite().make_exemplar("three_sizes", rng=29, **P4)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=5, measure=False)
    assert len(overlaps(out)[0]) == 0
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, [(k, m.value, m.tolerance) for k, m in rep.metrics.items() if m.applicable and not m.passed]

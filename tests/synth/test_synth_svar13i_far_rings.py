"""Issue 13 point 1 on hidden exemplars (helper svar13i): rings far apart, whose
neighbourhoods hold no foreign hub (``benchmarks/synth_variants.py --harder`` rings h3:
rings of ten, radius 15, hubs 60 apart). Synthesis stopped after the first ring (11
elements); with ``_prepare.anchor_reach`` growth crosses to the next hub and every
ring is whole. See ``_prepare.anchor_reach``."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import overlaps
from strew.synth import synthesize
from strew.synth._palette import Palette

from strew_testing import fidelity_suite

suite = fidelity_suite()

FAR_RINGS = dict(tiles=10, radius=15.0, hub=5.0, spacing=60.0)


def _far(ex):
    from strew.synth._prepare import anchor_reach, area_radii, size_classes

    arr = Palette({"e": ex})["e"]
    r, rbar = np.asarray(arr["radius"], float), np.asarray(arr["neighborhood_radius"], float)
    kind = arr.kind.astype(np.int64)
    return anchor_reach(arr.xy, rbar + 2.0 * r.max(), kind, np.zeros(len(arr), np.int64), np.zeros(len(arr), bool), size_classes(r, area_radii(arr), kind))


def test_far_rings_grow_past_the_first_ring_with_whole_rings():
    ex = suite.make_exemplar("rings", rng=7, **FAR_RINGS)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1)
    assert len(out) >= 3 * len(ex)  # about 4x the exemplar's area: 4x its count (was 11 elements)
    hub = out.xy[out.kind == out.kinds.index("hub")]
    tile = out.xy[out.kind == out.kinds.index("tile")]
    # every tile away from the region's edge (where a ring's hub may lie beyond it)
    # sits on its hub's ring (radius 15), none off every ring
    x1o, y1o = out.region.bounds[2:]
    away = (tile[:, 0] > 25) & (tile[:, 0] < x1o - 25) & (tile[:, 1] > 25) & (tile[:, 1] < y1o - 25)
    d, _ = cKDTree(hub).query(tile[away])
    assert np.all(np.abs(d - FAR_RINGS["radius"]) < 1.0)
    # hubs away from the region's edge hold whole rings of ten
    inner = (hub[:, 0] > 40) & (hub[:, 0] < x1o - 40) & (hub[:, 1] > 40) & (hub[:, 1] < y1o - 40)
    assert inner.sum() >= 10
    ring = cKDTree(tile).query_ball_point(hub[inner], FAR_RINGS["radius"] + 1.0, return_length=True)
    assert np.all(ring == FAR_RINGS["tiles"])
    assert len(overlaps(out)[0]) == 0


def test_reach_extends_only_where_no_neighbourhood_holds_a_foreign_hub():
    far_ex = suite.make_exemplar("rings", rng=7, **FAR_RINGS)
    reach, far = _far(far_ex)
    hubs = far_ex.kind == far_ex.kinds.index("hub")
    assert far is not None and np.array_equal(far, hubs)  # the foreign anchors are the hubs
    h = far_ex.xy[hubs]
    nn = cKDTree(h).query(h, k=2)[0][:, 1]
    assert np.all(reach[hubs] >= nn)  # each hub's n(e) holds its nearest other hub
    for ex in (suite.make_exemplar("rings"), suite.make_exemplar("rings", rng=7, tiles=14, radius=20.0, hub=8.0, spacing=52.0), suite.make_exemplar("clusters")):
        _, far0 = _far(ex)
        assert far0 is None  # tiles already see the next hub (or no anchors): unchanged

"""Issue 13 point 1 on hidden exemplars (helper rings13j): large rings whose hub is of a
larger size class than its tiles (``benchmarks/synth_variants.py --harder`` rings h2:
rings of sixteen, radius 22, hub 10, hubs 56 apart). The horizon optimisation pulled
tiles off their ring's radius (nn[hub>tile] failing on 4 of 4 runs); with
``_optimize._keep_ring_radius`` a tile moves along its ring only. See
``_optimize.ring_children``."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import overlaps
from strew.synth import synthesize
from strew.synth._palette import Palette
from strew.synth._prepare import prepare

from strew_testing import fidelity_suite

suite = fidelity_suite()

LARGE_RINGS = dict(tiles=16, radius=22.0, hub=10.0, spacing=56.0)


def test_ring_children_are_tiles_on_a_larger_hub_only():
    from strew.synth._optimize import ring_children

    ex = suite.make_exemplar("rings", rng=7, **LARGE_RINGS)
    prep = prepare(Palette.from_arrangement(ex).select())
    kids = ring_children(prep)
    tile = prep.kind == list(ex.kinds).index("tile")
    assert kids[tile & (prep.parent >= 0)].all() and not kids[~tile].any()
    # a cluster's dots ring their disc at distances 2 % apart: not a ring
    clusters = prepare(Palette.from_arrangement(suite.make_exemplar("clusters", rng=7)).select())
    assert not ring_children(clusters).any()


@pytest.mark.slow
def test_large_rings_keep_their_tiles_on_the_ring_radius():
    ex = suite.make_exemplar("rings", rng=7, **LARGE_RINGS)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1)
    assert len(out) >= 3 * len(ex)
    assert len(overlaps(out)[0]) == 0
    hub = out.xy[out.kind == out.kinds.index("hub")]
    tile = out.xy[out.kind == out.kinds.index("tile")]
    # tiles away from the region's edge (where a ring's hub may lie beyond it)
    bx = out.region.bounds
    inner = (tile[:, 0] > bx[0] + 30) & (tile[:, 0] < bx[2] - 30) & (tile[:, 1] > bx[1] + 30) & (tile[:, 1] < bx[3] - 30)
    d, _ = cKDTree(hub).query(tile[inner])
    off = np.abs(d - LARGE_RINGS["radius"])
    assert (off < 1.0).mean() > 0.95  # on some ring
    # on the ring's radius (exemplar: all at 22.0 exactly): 0.92-0.95 of them at seeds
    # 1-2 (variant 7) and 1 (variant 8), against 0.20-0.39 on f963535
    assert (off < 0.05).mean() > 0.85

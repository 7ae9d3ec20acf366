"""Issue 14 point 1 on clustered exemplars whose frame cuts clusters (helper growvar14).

Large discs ringed by grit, spaced so that the exemplar's frame cuts many clusters: the
dots whose disc lies beyond the frame are far from every disc of the exemplar. They used
to make the exemplar read as unclustered; it then grew through the 1-ring alone, which
extended rings into chains of dots (63% of the dots far from any disc).
"""

from __future__ import annotations

import numpy as np
import pytest

from strew import Region
from strew.grow import grow
from strew.grow._clusters import satellite_structure
from strew.metrics import fidelity, summary

from strew_testing import fidelity_suite

make_exemplar = fidelity_suite().make_exemplar

# the audit's edge set "big discs, tight rings of grit" (benchmarks/_variants.py EDGE)
GRIT = dict(large=12.0, small=2.0, ring_gap=0.5, ring_min=7, ring_max=9, cluster_spacing=70.0)


@pytest.mark.parametrize("variant, kw", [(7, GRIT), (20, GRIT), (12, dict(cluster_spacing=90.0, ring_gap=3.0, ring_min=6, ring_max=7)), (20, {})])
def test_frame_cut_clusters_read_as_clustered(variant, kw):
    ex = make_exemplar("clusters", rng=variant, **kw)
    sat = satellite_structure(ex)
    assert sat is not None and ex.kinds[sat.hub] == "disc"
    m = np.concatenate(sat.members)
    assert len(np.unique(m)) == len(m) and np.all(ex.kind[m] != sat.hub)
    # each member is within its ring's distance of its hub
    ring = GRIT["large"] + GRIT["small"] + GRIT["ring_gap"] if kw is GRIT else None
    if ring is not None:
        for h, mem in zip(sat.hubs, sat.members):
            d = np.hypot(*(ex.xy[mem] - ex.xy[h]).T)
            assert np.all(np.abs(d / ring - 1) < 0.2)


@pytest.mark.slow
def test_frame_cut_grit_clusters_grow_faithful():
    ex = make_exemplar("clusters", rng=7, **GRIT)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = grow(ex, region=region, rng=1)
    assert len(out) >= 8 * len(ex)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    assert summary(out)["overlap_pairs"] == 0
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.metrics["nn[dot>disc]"].passed, rep.failures
    assert rep.faithful, rep.failures


def test_clusters_with_too_few_hubs_to_match_grow_as_one_pattern():
    # seven hubs, all on the boundary of their own connectivity: the hubs alone have no
    # interior element to match (§4); the exemplar grows through its whole 1-ring instead
    ex = make_exemplar("clusters", rng=18, cluster_spacing=90.0, ring_gap=3.0, ring_min=6, ring_max=7)
    assert satellite_structure(ex) is not None
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(1.5 * (x1 - x0), 1.5 * (y1 - y0))
    out = grow(ex, region=region, rng=1)
    assert len(out) >= len(ex)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    assert summary(out)["overlap_pairs"] == 0

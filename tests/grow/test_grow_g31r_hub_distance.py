"""Issue 14 point 1: cluster hubs keep the exemplar's least hub distance (helper g31r).

Hubs dart-thrown at one distance (the ``clusters`` class with ``cluster_spacing=48``,
variant seed 22: least hub distance 48.2, the nearest tenth within 48.3) were placed up
to 4 % nearer than that and then squeezed by the relaxation windows: a quarter of the
grown hubs had a hub nearer than the exemplar ever has one, down to 0.93 of the least
distance, and g[disc,disc] failed on seeds 1-3 of the fresh audit row.
``GrowParams.keep_close`` (set by the hubs' growth) keeps a hard-core hub kind's least
distance at placement and through every relaxation window.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import grow
from strew.grow._clusters import satellite_structure
from strew.metrics import summary

from strew_testing import fidelity_suite

make_exemplar = fidelity_suite().make_exemplar


def _least_hub_distance(arr, hub):
    xy = arr.xy[arr.kind == hub]
    return cKDTree(xy).query(xy, k=2)[0][:, 1]


@pytest.mark.parametrize("seed", [1, 2])
def test_grown_hubs_keep_the_exemplars_least_hub_distance(seed):
    ex = make_exemplar("clusters", rng=22, cluster_spacing=48.0, ring_min=3, ring_max=5)
    sat = satellite_structure(ex)
    assert sat is not None
    lo = float(_least_hub_distance(ex, sat.hub).min())
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0))
    out = grow(ex, region=region, rng=seed)
    assert summary(out)["overlap_pairs"] == 0
    d = _least_hub_distance(out, sat.hub)
    # hubs still fill the region at the exemplar's spacing (not thinned to keep apart)
    n_ex = int(np.sum(ex.kind == sat.hub))
    assert len(d) >= 0.8 * 4.0 * n_ex
    assert float(d.min()) >= lo * (1 - 1e-9), (d.min(), lo, float(np.mean(d < lo)))

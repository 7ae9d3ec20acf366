"""Issue 13 point 1 (helper s61c): far-apart clusters (``_prepare._far_hubs``) whose
output leaves a room for a whole cluster, at least the exemplar's closest disc spacing
from every output disc, take a disc with its ring there (``_grow.fill_far_hub_rooms``)
while ``_far_hub_room`` allows. Such a room's empty circle among all elements is the
room less the ring, narrower than the exemplar's largest empty circle, so
``fill_holes`` passed it by: ``--varied`` clusters p2s36 seed 1 stopped at 84 discs in
1050 x 1050 (the exemplar's count over that area: 98) with four rooms up to 110 wide,
and density[disc] failed (0.375 / 0.324)."""

from __future__ import annotations

import numpy as np
import shapely
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize
from strew.synth._grow import circumcircles

suite = fidelity_suite()

# benchmarks/_variants.py EDGE["clusters"][0] (far apart, full rings)
FAR = {"cluster_spacing": 90.0, "ring_gap": 3.0, "ring_min": 6, "ring_max": 7}


def _discs(arr):
    return arr.xy[np.asarray(arr.kind_names) == "disc"]


def test_far_clusters_leave_no_room_for_a_cluster():
    ex = suite.make_exemplar("clusters", rng=36, **FAR)
    d = _discs(ex)
    spacing = float(cKDTree(d).query(d, 2)[0][:, 1].min())
    # the reach of a cluster: its farthest dot from its disc, plus the dot
    xy, names = ex.xy, np.asarray(ex.kind_names)
    dots = xy[names == "dot"]
    reach = float(cKDTree(d).query(dots)[0].max()) + 3.0
    region = Region.rectangle(1050, 1050)
    out = synthesize(ex, region, rng=1, measure=False)
    od = _discs(out)
    cen, rad, _ = circumcircles(od)
    # rooms whose whole cluster lies in the region, with no disc nearer than the spacing
    inner = shapely.box(reach, reach, 1050 - reach, 1050 - reach)
    room = (rad >= spacing) & shapely.contains_xy(inner, cen[:, 0], cen[:, 1])
    assert np.count_nonzero(room) == 0, (np.sort(rad[room])[::-1], spacing)




"""Clustered exemplars whose interior hub rings all open to one side are mirrored, so the
hubs grow on both sides of the start (issue 14 point 1, fresh ``--varied`` row clusters
p2s37: EDGE set p2 "far apart, full rings" at variant seed 37, 0 of 6 seeds on grow,
g[disc,dot] 10.4 against 7.65).

Seven discs; §4's skew rule keeps no interior one, and :func:`hub_reference`'s fallback
(every Delaunay triangle) keeps one whose ring of 4 has bearings -151, -90, -45 and 133
degrees: a gap of 177 degrees that every grown hub copied, so the clusters filled only
the half of the region below the anti-diagonal through the start (helper g64c,
``benchmarks/results/g64c_notes.md``).
"""

from __future__ import annotations

import math

import numpy as np
from strew_testing import fidelity_suite

from strew import Arrangement, Region, Shape
from strew.grow import grow
from strew.grow._analysis import analyze, delaunay_edges
from strew.grow._clusters import (
    HUB_MIRROR_GAP,
    hub_reference,
    mirror_hub_rings,
    ring_union_gap,
    satellite_structure,
)
from strew.grow._exemplars import hex_exemplar
from strew.metrics import fidelity

make_exemplar = fidelity_suite().make_exemplar

# the audit's edge set "far apart, full rings" (benchmarks/_variants.py EDGE clusters[0])
FAR = {"cluster_spacing": 90.0, "ring_gap": 3.0, "ring_min": 6, "ring_max": 7}

# the seven hubs of that exemplar (rounded), in its 300 x 300 frame
HUBS = np.array([[211.2, 198.5], [20.7, 210.8], [95.7, 135.0], [294.2, 19.3], [212.4, 57.8], [119.7, 297.9], [297.8, 112.5]])


def _hubs(xy: np.ndarray) -> Arrangement:
    return Arrangement({"disc": Shape.circle(10.0)}, np.zeros(len(xy), dtype=int), xy[:, 0], xy[:, 1], region=Region.rectangle(300.0, 300.0))


def _fallback(hx: Arrangement):
    return analyze(hx, edges=delaunay_edges(hx.xy, skew_angle=math.pi))


def test_hub_reference_mirrors_only_one_sided_rings():
    hx = _hubs(HUBS)
    own = _fallback(hx)
    assert math.degrees(ring_union_gap(own)) > 170.0  # the ring of hub 0 opens to one side
    ref = hub_reference(hx)
    n = len(hx)
    assert len(ref.exemplar) > n
    # the real hubs are kept where they are, as is the reference set
    assert np.allclose(ref.exemplar.xy[:n], hx.xy)
    assert np.array_equal(ref.interior[:n], own.interior)
    assert not ref.interior[n:].any()  # virtual hubs are never references
    assert math.degrees(ring_union_gap(ref)) < math.degrees(HUB_MIRROR_GAP)
    (i,) = np.flatnonzero(own.interior)
    ring = ref.rings[i].tolist()
    assert set(own.rings[i].tolist()) <= set(ring)
    # each virtual hub is the point reflection of a ring member through hub i, a
    # neighbour of i only, and no nearer any ring member than the hubs' shortest edge
    for k in range(n, len(ref.exemplar)):
        assert k in ring
        assert ref.rings[k].tolist() == [i]
        p = ref.exemplar.xy[k]
        mirror = 2.0 * hx.xy[i] - hx.xy[own.rings[i]]
        assert np.min(np.hypot(*(mirror - p).T)) < 1e-9
        others = [q for q in ring if q != k]
        assert np.min(np.hypot(*(ref.exemplar.xy[others] - p).T)) >= own.shortest_edge
    # the ring stays counter-clockwise
    d = ref.exemplar.xy[ring] - hx.xy[i]
    assert np.all(np.diff(np.arctan2(d[:, 1], d[:, 0])) > 0)
    # rings within the limit are left alone
    assert mirror_hub_rings(own, limit=math.radians(178.0)) is own
    lattice = hex_exemplar(5, 5)
    ref = analyze(lattice)
    assert math.degrees(ring_union_gap(ref)) < 150.0
    assert mirror_hub_rings(ref) is ref
    # the suite's exemplar p2 at variant seed 18: one interior hub, union gap 121 degrees
    ex = make_exemplar("clusters", rng=18, **FAR)
    h18 = ex.select(ex.kind == satellite_structure(ex).hub)
    got = hub_reference(h18)
    assert 115.0 < math.degrees(ring_union_gap(got)) < 150.0
    assert len(got.exemplar) == len(h18)
    assert np.array_equal(got.edges, _fallback(h18).edges)


def test_far_clusters_at_37_grow_hubs_on_both_sides_of_the_start():
    # the row's first try: region 3.5x the frame (1050 wide), seed 1, start at the
    # centre (x + y = 1050). At main ef8ca0b 44 discs, x + y 202-1086, none in the upper
    # quarter (x + y > 1312), g[disc,dot] 10.2 against 7.81; with the mirrored ring 78
    # discs, x + y 233-1987, 25 in that quarter, g[disc,dot] 2.51
    ex = make_exemplar("clusters", rng=37, **FAR)
    x0, y0, x1, y1 = ex.region.bounds
    w = 3.5 * (x1 - x0)
    out = grow(ex, region=Region.rectangle(w, 3.5 * (y1 - y0)), mode="fixed", rng=1)
    kn = np.asarray(out.kind_names)
    s = out.xy[kn == "disc"].sum(axis=1)
    start = w  # the region's centre, x + y
    assert np.sum(s > start + 0.25 * w) >= 5, (s.min(), s.max())
    assert np.sum(s < start - 0.25 * w) >= 5, (s.min(), s.max())
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["g[disc,dot]"]
    assert m.passed, (m.value, m.tolerance)

"""The compiled Step 2 engine (strew.pack._fit): exact tests agree with shapely, and the
fill-gap extensions (fits, suppress) keep every guarantee."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import InputError, Region, Shape
from strew.metrics import outside, overlaps
from strew.pack import pack
from strew.pack._predicates import _in_region, _polys_hit, ring_layout

HOOK = Shape.polygon([(-15, -15), (15, -15), (15, -7), (-5, -7), (-5, 7), (15, 7), (15, 15), (-15, 15)])


def _star(cx, cy, radii, rot, hole=0.0):
    n = len(radii) * 2
    t = np.linspace(0, 2 * np.pi, n, endpoint=False) + rot
    r = np.repeat(radii, 2) * np.tile([1.0, 0.4], len(radii))
    g = shapely.Polygon(np.c_[cx + r * np.cos(t), cy + r * np.sin(t)])
    if hole > 0:
        g = g.difference(shapely.Point(cx, cy).buffer(hole * min(radii) * 0.35, 6))
    return g


def _hit(a, b):
    av, ar, _ = ring_layout([a])
    bv, br, _ = ring_layout([b])
    buf = np.zeros(len(bv) + 1, dtype=np.int64)
    return _polys_hit(av, ar, 0, len(ar) - 1, np.array(a.bounds), bv, br, 0, len(br) - 1, np.array(b.bounds), buf)


@settings(max_examples=200, deadline=None)
@given(
    ra=st.lists(st.floats(0.5, 3.0), min_size=3, max_size=7),
    rb=st.lists(st.floats(0.5, 3.0), min_size=3, max_size=7),
    dx=st.floats(-6, 6),
    dy=st.floats(-6, 6),
    rot=st.floats(0, 6.3),
    hole_a=st.sampled_from([0.0, 1.0]),
    hole_b=st.sampled_from([0.0, 1.0]),
)
def test_polygon_test_agrees_with_shapely(ra, rb, dx, dy, rot, hole_a, hole_b):
    a = _star(0, 0, ra, 0.0, hole_a)
    b = _star(dx, dy, rb, rot, hole_b)
    exact = bool(shapely.intersects(a, b))
    if shapely.distance(shapely.boundary(a), shapely.boundary(b)) < 1e-9 and not exact:
        return  # touching within rounding: either answer is acceptable
    assert _hit(a, b) == exact


def test_polygon_test_sees_containment_and_holes():
    ring = shapely.Point(0, 0).buffer(10, 8).difference(shapely.Point(0, 0).buffer(6, 8))
    small = shapely.Point(0, 0).buffer(2, 8)  # inside the hole: disjoint
    inner = shapely.Point(8, 0).buffer(0.5, 8)  # inside the ring's body: contained
    big = shapely.Point(0, 0).buffer(20, 8)  # contains the ring
    assert not _hit(ring, small) and not _hit(small, ring)
    assert _hit(ring, inner) and _hit(inner, ring)
    assert _hit(ring, big) and _hit(big, ring)


@settings(max_examples=100, deadline=None)
@given(x=st.floats(-5, 65), y=st.floats(-5, 65), rot=st.floats(0, 6.3), s=st.floats(0.2, 1.5))
def test_region_test_agrees_with_shapely(x, y, rot, s):
    from strew.pack._fit import FitEngine
    from strew.pack._exclusive import build_exclusive_regions

    outer = shapely.Point(30, 30).buffer(28, 12)
    dom = outer.difference(shapely.box(25, 25, 35, 35))
    eng = FitEngine(build_exclusive_regions({"hook": HOOK}), dom, None, 0)
    c, sn = np.cos(rot) * s, np.sin(rot) * s
    hv = eng.kv @ np.array([[c, sn], [-sn, c]]) + (x, y)
    hbb = np.r_[hv.min(axis=0), hv.max(axis=0)]
    got = _in_region(hv, eng.kr, 0, len(eng.kr) - 1, hbb, eng.rv, eng.rr, eng.rsegs, eng.g, eng.rhead, eng.rent,
                     eng.rext, eng.rstamp, 1)
    posed = shapely.Polygon(hv[: eng.kr[1]])
    exact = bool(shapely.contains_properly(dom, posed))
    if shapely.distance(shapely.boundary(dom), posed.exterior) < 1e-9:
        return  # touching the boundary within rounding: either answer is acceptable
    assert got == exact


@pytest.mark.parametrize("kw", [{"fits": 1, "suppress": 1.0}, {"fits": 4, "suppress": 0.5}, {}])
def test_fits_and_suppression_keep_the_guarantees(kw):
    region = Region(shapely.Point(60, 60).buffer(58, 16).difference(shapely.box(45, 45, 75, 75)))
    arr = pack({"hook": HOOK}, region, scale=(0.3, 0.5), rng=2, **kw)
    assert len(arr) > 10
    assert len(overlaps(arr)[0]) == 0 and len(outside(arr, region, tolerance=1e-9)) == 0
    info = arr.meta["pack"]
    assert info["stopped"] == "200 consecutive cancellations"
    assert info["poses"] >= info["trials"] - info["sparse"]


def test_more_poses_per_candidate_pack_denser():
    region = Region.rectangle(200, 170)
    one = [len(pack(HOOK, region, scale=(0.5, 0.5), fits=1, suppress=1.0, rng=s)) for s in (1, 2)]
    many = [len(pack(HOOK, region, scale=(0.5, 0.5), rng=s)) for s in (1, 2)]
    assert sum(many) > 1.05 * sum(one)


@pytest.mark.parametrize("kw, match", [({"fits": 0}, "fits"), ({"suppress": 0}, "suppress"), ({"suppress": 1.5}, "suppress"),
                                       ({"suppress": "x"}, "suppress")])
def test_bad_fit_parameters_name_the_problem(kw, match):
    with pytest.raises(InputError, match=match):
        pack(HOOK, Region.rectangle(50, 50), **kw)


# -- robustness: cases too close to call count as touching, and touching is a collision
def _rot(g, angle, origin=(0.0, 0.0)):
    c, s = np.cos(angle), np.sin(angle)
    return shapely.affinity.affine_transform(g, [c, -s, s, c, origin[0] - c * origin[0] + s * origin[1],
                                                 origin[1] - s * origin[0] - c * origin[1]])


@settings(max_examples=200, deadline=None)
@given(angle=st.floats(0, 6.3), t=st.floats(0.05, 0.95), gap=st.sampled_from([0.0, 1e-15, -1e-15, 1e-13]),
       turn=st.floats(0.1, 3.0), inner=st.booleans())
def test_touching_within_rounding_is_a_collision(angle, t, gap, turn, inner):
    import shapely.affinity  # noqa: F401

    a = _rot(shapely.Polygon(HOOK.geometry.exterior), angle)
    xy = shapely.get_coordinates(a.exterior)
    # a vertex of b on (within rounding of) a point of a's first edge
    p = xy[0] + t * (xy[1] - xy[0])
    normal = np.array([xy[1, 1] - xy[0, 1], xy[0, 0] - xy[1, 0]])
    normal /= np.hypot(*normal)
    tri = np.array([[0.0, 0.0], [3.0, -1.0], [3.0, 1.0]]) * 0.5
    if inner:  # b inside a, touching its edge from within
        tri = -tri
    c, s = np.cos(turn), np.sin(turn)
    b = shapely.Polygon(tri @ np.array([[c, s], [-s, c]]) + p + gap * normal)
    if shapely.intersects(a, b):  # GEOS decides exactly; we must never call it disjoint
        assert _hit(a, b) and _hit(b, a)


def test_a_hair_apart_is_disjoint_and_a_hair_over_is_not():
    a = shapely.box(0, 0, 10, 10)
    assert not _hit(a, shapely.box(10 + 1e-9, 0, 20, 10))
    assert _hit(a, shapely.box(10, 0, 20, 10))  # shared edge
    assert _hit(a, shapely.box(10 - 1e-9, 3, 20, 7))
    assert _hit(a, _rot(shapely.box(10, 0, 20, 10), 1e-17, (10, 5)))  # shared edge, rounded


def test_results_are_disjoint_under_shapely_without_tolerance():
    """No shapely re-check runs after Step 2: check strict pairwise disjointness here."""
    region = Region(shapely.Point(60, 60).buffer(58, 16).difference(shapely.box(45, 45, 75, 75)))
    for seed in (0, 1):
        arr = pack({"hook": HOOK, "sq": Shape.rectangle(8, 8)}, region, scale=(0.3, 0.6), rng=seed)
        geoms = arr.geometry
        left, right = shapely.STRtree(geoms).query(geoms, predicate="intersects")
        assert np.all(left == right)
        assert np.all(shapely.contains_properly(region.geometry, geoms))


def test_sparse_placement_keeps_elements_inside_and_reports_its_rings():
    """Step 1 in the compiled engine: exact containment only, cyclic kinds, and the
    stored rings (for the distance field) are the placed elements' outlines."""
    from strew.pack._exclusive import build_exclusive_regions, transform_many
    from strew.pack._fit import FitEngine

    region = Region(shapely.Point(60, 60).buffer(58, 16).difference(shapely.box(45, 45, 75, 75)))
    kinds = build_exclusive_regions({"hook": HOOK, "sq": Shape.rectangle(8, 8)}, scale=(0.3, 0.6))
    eng = FitEngine(kinds, region.geometry, None, 0)
    rng = np.random.default_rng(4)
    xy = rng.uniform(0, 120, size=(300, 2))  # many points near or outside the domain
    n = eng.place_sparse(xy, rng.random(300), rng.random(300), None)
    assert 0 < n < 300 and len(eng) == n
    kind, pose = eng.pkind[:n], eng.pose[:n]
    assert np.array_equal(kind, np.arange(n) % 2)  # cyclic, advanced on each placement
    bodies = np.empty(n, dtype=object)
    for k, ex in enumerate(kinds):
        idx = np.flatnonzero(kind == k)
        bodies[idx] = transform_many(ex.body, pose[idx, :2], pose[idx, 2], pose[idx, 3])
    assert np.all(shapely.contains_properly(region.geometry, bodies))
    segs, off = eng.segments()
    assert len(off) == n + 1 and off[-1] == len(segs)
    for i in (0, n // 2, n - 1):
        ring = shapely.get_coordinates(bodies[i].exterior)
        assert np.allclose(segs[off[i]:off[i + 1], :2], ring[:-1]) or np.allclose(segs[off[i]:off[i + 1], :2], ring[::-1][:-1])

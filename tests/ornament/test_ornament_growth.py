"""Growth framework and built-in patterns (Wong et al. 1998, §4.1 and Appendix A)."""

from __future__ import annotations

import math
import signal

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import InputError, Region
from strew.ornament import (
    FAILURE,
    SUCCESS,
    Circle,
    Goal,
    Pattern,
    Point,
    grow_elements,
    grow_ornament,
    load_pattern,
)
from strew.ornament._engine import RuleContext, _Grower
from strew._progress import Reporter


def dots_of(orn):
    d = orn.of_type("dot")
    c = np.array([e.proxy.center for e in d])
    r = np.array([e.proxy.radius for e in d])
    return d, c, r


def exact_largest_empty_circle(region, c, r, h=0.25):
    """Largest empty circle among dots, by a fine raster then an exact local ascent."""
    from scipy import ndimage

    x0, y0, x1, y1 = region.bounds
    nx, ny = int(np.ceil((x1 - x0) / h)), int(np.ceil((y1 - y0) / h))
    xs, ys = x0 + (np.arange(nx) + 0.5) * h, y0 + (np.arange(ny) + 0.5) * h
    gx, gy = np.meshgrid(xs, ys)
    free = shapely.contains_xy(region.prepared, gx.ravel(), gy.ravel()).reshape(ny, nx)
    for (x, y), rr in zip(c, r):
        free &= (gx - x) ** 2 + (gy - y) ** 2 > rr * rr
    d = ndimage.distance_transform_edt(np.pad(free, 1))[1:-1, 1:-1] * h

    def clearance(p):
        if not region.contains(p[None])[0]:
            return -1.0
        db = float(shapely.distance(region.boundary, shapely.Point(p)))
        return min(db, float((np.hypot(*(c - p).T) - r).min()))

    best = 0.0
    for f in np.argsort(d.ravel())[::-1][:150]:
        i, j = divmod(int(f), nx)
        p, v, step = np.array([xs[j], ys[i]]), clearance(np.array([xs[j], ys[i]])), h
        while step > 1e-4:
            moves = [(p + step * np.array(m), clearance(p + step * np.array(m))) for m in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1))]
            q, w = max(moves, key=lambda t: t[1])
            if w > v:
                p, v = q, w
            else:
                step /= 2
        best = max(best, v)
    return best


# -- dots (Appendix A, Fig. 14) -------------------------------------------------------------
@pytest.fixture(scope="module")
def dots_run():
    region = Region.rectangle(80, 60)
    return region, grow_elements("dots", region, seeds=[(10, 50)], rng=0)


def test_dots_do_not_overlap_and_stay_inside(dots_run):
    region, orn = dots_run
    _, c, r = dots_of(orn)
    assert len(c) > 150
    assert r.max() <= 3.0 + 1e-12
    dd = np.hypot(*(c[:, None] - c[None]).transpose(2, 0, 1)) - r[:, None] - r[None]
    np.fill_diagonal(dd, np.inf)
    assert dd.min() >= -1e-9
    assert np.all(region.distance_to_boundary(c) >= r - 1e-9)
    assert region.contains(c).all()


def test_first_dot_on_seed_and_each_dot_adjacent_to_its_parent(dots_run):
    _, orn = dots_run
    dots, _, _ = dots_of(orn)
    assert np.allclose(dots[0].proxy.center, [10, 50])
    assert dots[0].parent.type == "seed" and dots[0].parent.sterile
    for d in dots[1:]:
        p = d.parent
        assert p.type == "dot"
        gap = math.dist(d.proxy.center, p.proxy.center) - (d.proxy.radius + p.proxy.radius)
        assert abs(gap) < 1e-9
    # the `order` user field numbers dots in placement order
    assert [d.order for d in dots] == list(range(len(dots)))


def test_dots_fill_until_no_empty_circle_of_radius_one(dots_run):
    region, orn = dots_run
    _, c, r = dots_of(orn)
    # the run stopped because no eligible circle of radius >= min_radius (1) remained;
    # measured independently, no empty circle of radius 1 is left (to 1e-6)
    assert exact_largest_empty_circle(region, c, r) < 1.0 + 1e-6


@settings(max_examples=6, deadline=None)
@given(
    w=st.floats(20, 60),
    h=st.floats(20, 60),
    fx=st.floats(0.1, 0.9),
    fy=st.floats(0.1, 0.9),
)
def test_dots_property_any_rectangle_and_seed(w, h, fx, fy):
    region = Region.rectangle(w, h)
    orn = grow_elements("dots", region, seeds=[(fx * w, fy * h)], rng=1)
    _, c, r = dots_of(orn)
    assert len(c) >= 1
    dd = np.hypot(*(c[:, None] - c[None]).transpose(2, 0, 1)) - r[:, None] - r[None]
    np.fill_diagonal(dd, np.inf)
    assert dd.min() >= -1e-9
    assert np.all(region.distance_to_boundary(c) >= r - 1e-9) and region.contains(c).all()


# -- flowers (Appendix A, Figs. 15-16) -----------------------------------------------------
def _grower_with_flower(center=(50.0, 50.0)):
    pat = load_pattern("flowers")
    g = _Grower(pat, Region.rectangle(100, 100), np.array([center]), np.random.default_rng(0), 256, 3.0, None, None, None, Reporter())
    seed = g.elements[0]
    ctx = RuleContext(g, Goal(np.array([80.0, 50.0]), 20.0), seed)
    flower = __import__("strew.ornament", fromlist=["Element"]).Element(pat.types["flower"])
    assert pat.rules[0].body(ctx, seed, flower) is SUCCESS
    g._commit(seed, [flower])
    rule = next(r for r in pat.rules if r.parent == "flower")
    return g, pat, flower, rule


@pytest.mark.parametrize("goal_distance, expect_leaf", [(14.0, True), (9.0, True), (7.5, False), (6.5, False)])
def test_leaf_only_when_goal_farther_than_8(goal_distance, expect_leaf):
    from strew.ornament import Element

    g, pat, parent, rule = _grower_with_flower()
    centre = parent.proxy.center + np.array([0.0, goal_distance])
    ctx = RuleContext(g, Goal(centre, goal_distance - 3.0), parent)
    stem, child = Element(pat.types["stem"]), Element(pat.types["flower"])
    assert rule.body(ctx, parent, stem, child) is SUCCESS
    leaves = [e for e in ctx.dynamic if e.type == "leaf"]
    assert bool(leaves) == expect_leaf
    assert math.dist(child.proxy.center, parent.proxy.center) == pytest.approx(min(goal_distance, 10.0))
    assert np.allclose(stem.proxy.start, parent.proxy.center) and np.allclose(stem.proxy.end, child.proxy.center)
    if leaves:
        base = leaves[0].proxies[0].start
        assert np.allclose(base, (stem.proxy.start + stem.proxy.end) / 2)  # at the stem midpoint
        tip = leaves[0].proxies[0].end
        assert math.dist(base, tip) == pytest.approx(3.0)
        assert abs(np.dot(tip - base, stem.proxy.end - stem.proxy.start)) < 1e-9  # at a right angle


def test_flower_rule_fails_when_new_flower_would_intersect():
    from strew.ornament import Element

    g, pat, parent, rule = _grower_with_flower()
    # a goal 4 units away puts the child flower (radius 3) over its parent
    ctx = RuleContext(g, Goal(parent.proxy.center + np.array([4.0, 0.0]), 1.0), parent)
    assert rule.body(ctx, parent, Element(pat.types["stem"]), Element(pat.types["flower"])) is FAILURE


def test_flowers_run_leaves_only_on_long_stems_and_flowers_disjoint():
    orn = grow_elements("flowers", Region.rectangle(90, 60), rng=0)
    flowers = orn.of_type("flower")
    assert len(flowers) > 20
    c = np.array([f.proxy.center for f in flowers])
    dd = np.hypot(*(c[:, None] - c[None]).transpose(2, 0, 1))
    np.fill_diagonal(dd, np.inf)
    assert dd.min() >= 6.0 - 1e-9
    leaves = orn.of_type("leaf")
    assert leaves
    for leaf in leaves:
        stem = next(s for s in leaf.parent.children if s.type == "stem")
        assert stem.proxy.length > 8.0


# -- the framework ---------------------------------------------------------------------------
def _alarm(seconds):
    def handler(signum, frame):
        raise TimeoutError("growth did not terminate")

    signal.signal(signal.SIGALRM, handler)
    signal.alarm(seconds)


def test_rule_that_always_fails_ends_through_the_exclude_list():
    pat = Pattern("stubborn", min_radius=1.0)
    pat.element("seed", Point)
    pat.element("dot", Circle)
    calls = []

    @pat.rule("seed", children=["dot"])
    def never(ctx, seed, dot):
        calls.append(ctx.goal.radius)
        return FAILURE

    _alarm(60)
    try:
        orn = grow_elements(pat, Region.rectangle(40, 30), rng=0)
    finally:
        signal.alarm(0)
    assert [e.type for e in orn.elements] == ["seed"]
    assert orn.stats["successes"] == 0
    assert orn.stats["failures"] == len(calls) >= 1
    # every failure put the circle's centre on the exclude list, which was never cleared
    assert orn.stats["exclude_list"] == orn.stats["failures"]
    # no circle was tried twice at the same centre
    assert len(calls) < 200


def test_region_change_regenerates_and_respects_holes():
    outer = shapely.Polygon([(0, 0), (70, 0), (70, 50), (0, 50)], holes=[[(25, 15), (45, 15), (45, 35), (25, 35)]])
    holed = Region(outer)
    disc = Region.circle(30, 30, 28)
    a = grow_elements("dots", holed, seeds=[(5, 5)], rng=0)
    b = grow_elements("dots", disc, seeds=[(30, 30)], rng=0)
    for region, orn in ((holed, a), (disc, b)):
        _, c, r = dots_of(orn)
        assert np.all(region.distance_to_boundary(c) >= r - 1e-9) and region.contains(c).all()
    _, ca, _ = dots_of(a)
    hole = shapely.box(25, 15, 45, 35)
    assert not shapely.contains_xy(hole, ca[:, 0], ca[:, 1]).any()
    # dots grew around the hole, on every side of it
    assert (ca[:, 0] < 25).any() and (ca[:, 0] > 45).any() and (ca[:, 1] < 15).any() and (ca[:, 1] > 35).any()
    assert len(a.elements) != len(b.elements)


@pytest.mark.parametrize("name", ["dots", "flowers", "spirals", "hierarchy"])
def test_same_seed_same_output_every_pattern(name):
    region = Region.rectangle(50, 40)
    a = grow_ornament(name, region, rng=3)
    b = grow_ornament(name, region, rng=3)
    assert len(a) > 0
    assert a.equals(b.with_meta(**a.meta))
    assert np.array_equal(a.x, b.x) and np.array_equal(a.y, b.y)
    assert region.contains_geometry(a.geometry, tolerance=1e-6).all()


def test_hierarchy_grows_in_phases():
    orn = grow_elements("hierarchy", Region.rectangle(90, 60), rng=0)
    order = ["vines", "flowers", "leaves", "fillers"]
    phases = [order.index(e.phase) for e in orn.elements]
    assert phases == sorted(phases)  # placed phase by phase
    # (a vine that joins two fronts of the structure may come in the flowers phase, see
    # the pattern's vine_joins_vine)
    by_type = {e.type: e.phase for e in orn.elements if e.type != "seed" and not (e.type == "vine" and e.target >= 0)}
    assert by_type["vine"] == "vines" and by_type["flower"] == "flowers" and by_type["quote"] == "fillers"
    assert {e.phase for e in orn.elements if e.type == "vine" and e.target >= 0} <= {"vines", "flowers"}
    assert {e.phase for e in orn.elements if e.type == "leaf"} == {"leaves"}
    for f in orn.of_type("flower"):
        assert f.parent.type in ("vine", "twig")  # flowers hang on (subsidiary) vines


def test_spirals_alternate_orientation_and_use_several_segments():
    orn = grow_elements("spirals", Region.rectangle(70, 50), rng=0)
    arms = orn.of_type("arm")
    assert len(arms) > 30
    by_spiral = {}
    for a in arms:
        by_spiral.setdefault(a.spiral, []).append(a)
    assert all(len(v) >= 3 and len(v) == v[0].segments for v in by_spiral.values())
    for a in arms:
        if a.parent.type == "arm":
            assert a.orientation == -a.parent.orientation
    # spirals scale to the empty circle: several distinct sizes
    assert len({round(a.scale, 3) for a in arms}) > 5


def test_seed_points_outside_region_are_rejected():
    with pytest.raises(InputError, match="outside the region"):
        grow_elements("dots", Region.rectangle(10, 10), seeds=[(20, 5)])


def test_default_seed_is_inside_and_central():
    region = Region.rectangle(40, 20)
    orn = grow_elements("dots", region, rng=0, max_elements=2)
    s = orn.seeds[0]
    assert region.contains(orn.seeds).all()
    assert abs(s[1] - 10) < 0.5


def test_resolution_sets_the_raster_buffer():
    region = Region.rectangle(60, 30)
    coarse = grow_elements("dots", region, rng=0, resolution=64)
    fine = grow_elements("dots", region, rng=0, resolution=256)
    assert coarse.stats["resolution"] == 64 and coarse.stats["cell"] == pytest.approx(60 / 64)
    assert fine.stats["cell"] == pytest.approx(60 / 256)
    for orn in (coarse, fine):  # exact tests keep dots apart whatever the raster
        _, c, r = dots_of(orn)
        dd = np.hypot(*(c[:, None] - c[None]).transpose(2, 0, 1)) - r[:, None] - r[None]
        np.fill_diagonal(dd, np.inf)
        assert dd.min() >= -1e-9

"""The framework's contract with rules (Wong et al. 1998, §4.1-4.2): goals, order, proxies."""

from __future__ import annotations

import math

import numpy as np
import shapely

from strew import Region
from strew.ornament import (
    FAILURE,
    SUCCESS,
    Arc,
    Bezier,
    Circle,
    Pattern,
    Point,
    Polygon,
    Segment,
    grow_elements,
    offset,
)


def _dots_pattern(record=None):
    pat = Pattern("rec", min_radius=1.5)
    pat.element("seed", Point)
    pat.element("dot", Circle)

    @pat.rule("seed dot", children=["dot"])
    def grow(ctx, parent, dot):
        if record is not None:
            record.append((ctx.goal.center.copy(), ctx.goal.radius, [e.index for e in ctx.elements]))
        if parent.type == "seed":
            dot.proxy.set(parent.proxy.center, 2.0)
            parent.sterile = True
        else:
            r = min(2.0, ctx.goal.radius)
            dot.proxy.set(offset(parent.proxy.center, ctx.goal.center - parent.proxy.center, parent.proxy.radius + r), r)
            if ctx.intersects(dot):
                return FAILURE
        return SUCCESS

    return pat


def test_goal_circles_are_empty_inside_and_touch_the_ornament():
    region = Region.rectangle(50, 40)
    record = []
    orn = grow_elements(_dots_pattern(record), region, seeds=[(25, 20)], rng=0)
    h = orn.stats["cell"]
    assert len(record) > 30
    for centre, rho, placed in record[1:]:
        d_b = float(shapely.distance(region.boundary, shapely.Point(centre)))
        assert region.contains(centre[None])[0] and rho <= d_b + 1e-9  # inside R
        dists = []
        for i in placed:
            e = orn.elements[i]
            c = e.proxy.center
            r = e.proxy.radius if e.type == "dot" else 0.0
            dists.append(math.dist(centre, c) - r)
        nearest = min(dists)
        assert nearest >= rho - 1e-9  # empty: no placed element inside C
        # stopped by an element, not by the boundary (§4.1): an element touches C
        assert nearest <= rho + h + 1e-9
    # circles are taken largest first while space is open: early goals are big
    radii = [r for _, r, _ in record]
    assert max(radii[:5]) > 3 * min(radii[-20:])


def test_rules_are_tried_in_declaration_order_and_sterile_parents_skipped():
    pat = Pattern("order", min_radius=2.0)
    pat.element("seed", Point)
    pat.element("dot", Circle)
    calls = []

    @pat.rule("seed", children=["dot"])
    def first(ctx, seed, dot):
        calls.append("first")
        dot.proxy.set(seed.proxy.center, 2.0)
        seed.sterile = True
        return SUCCESS

    @pat.rule("seed", children=["dot"])
    def second(ctx, seed, dot):
        calls.append("second")
        return FAILURE

    @pat.rule("dot", children=["dot"])
    def dot_rule(ctx, parent, dot):
        calls.append("dot")
        return FAILURE

    orn = grow_elements(pat, Region.rectangle(30, 30), rng=0)
    assert calls[0] == "first" and "second" not in calls  # the seed went sterile after succeeding
    assert [e.type for e in orn.elements] == ["seed", "dot"]
    # afterwards the dot is the only fertile element: every failed circle called its rule once
    assert orn.stats["failures"] == calls.count("dot") > 0


def test_every_proxy_kind_grows_renders_and_blocks_space():
    pat = Pattern("kinds", min_radius=3.0)
    pat.element("seed", Point)
    pat.element("thing", [Circle, Arc, Segment, Bezier, Polygon], size=0.0)

    @pat.rule("seed thing", children=["thing"])
    def place(ctx, parent, thing):
        g, rho = ctx.goal.center, 0.8 * ctx.goal.radius
        s = rho / math.sqrt(2)
        circle, arc, seg, bez, poly = thing.proxies
        circle.set(g, 0.3 * rho)
        arc.set(g, 0.6 * rho, 0.0, math.pi)
        seg.set(g + (-s, s), g + (s, s))
        bez.set(g + (-s, -s), 0.5, 0.4, g + (s, -s), -0.5, 0.4)
        poly.set([g + (0.7 * rho, 0), g + (0.8 * rho, 0.1 * rho), g + (0.75 * rho, -0.1 * rho)])
        thing.size = rho
        if ctx.intersects(thing) or not ctx.inside(thing):
            return FAILURE
        return SUCCESS

    region = Region.circle(40, 40, 38)
    orn = grow_elements(pat, region, rng=0)
    things = orn.of_type("thing")
    assert len(things) > 5
    geoms = [shapely.union_all([p.geometry for p in t.proxies]) for t in things]
    for i in range(len(geoms)):
        for j in range(i):
            assert not geoms[i].intersects(geoms[j])
    arr = orn.render("outline")
    assert len(arr) == len(things)  # one row per element, one mark per proxy in its parts
    assert [len(parts) for parts in arr.element_parts] == [5] * len(things)
    assert region.contains_geometry(arr.geometry, tolerance=1e-6).all()
    filled = orn.render("tapered")
    assert any(p.style["fill"] != "none" for parts in filled.element_parts for p in parts)


def test_exclude_list_cleared_near_a_success_and_by_rules():
    from strew._progress import Reporter
    from strew.ornament import load_pattern
    from strew.ornament._engine import _Grower

    g = _Grower(load_pattern("dots"), Region.rectangle(60, 60), [[30.0, 30.0]], None, None, 1.0, None, None, None, Reporter())
    for p in ([10.0, 10.0], [12.0, 10.0], [50.0, 50.0]):
        g.add_exclude(np.array(p))
    assert g.n_ex == 3
    g.clear_exclude_near(np.array([11.0, 10.0]), 1.5)  # §4.1: points within epsilon of C go
    assert g.n_ex == 1 and np.allclose(g.ex[0], [50.0, 50.0])
    g.clear_exclude_all()  # what a rule's ctx.clear_exclude() does
    assert g.n_ex == 0


def test_rule_can_clear_the_exclude_list_and_unblock_growth():
    pat = Pattern("gate", state={"tries": 0}, min_radius=2.0)
    pat.element("seed", Point)
    pat.element("dot", Circle)
    goals = []

    @pat.rule("seed", children=["dot"])
    def gated(ctx, seed, dot):
        # fail the first three circles (they go on the exclude list); the third failure
        # clears the list first, so the earlier circles become eligible again
        ctx.state.tries += 1
        goals.append(tuple(ctx.goal.center))
        if ctx.state.tries <= 3:
            if ctx.state.tries == 3:
                ctx.clear_exclude()
            return FAILURE
        dot.proxy.set(seed.proxy.center, 2.0)
        seed.sterile = True
        return SUCCESS

    orn = grow_elements(pat, Region.rectangle(40, 40), rng=0)
    assert [e.type for e in orn.elements] == ["seed", "dot"]
    assert orn.stats["successes"] == 1 and len(goals) == 4  # the dot has no rule: later circles fail
    assert len(set(goals[:3])) == 3
    assert goals[3] in goals[:2]  # an excluded circle came back after the list was cleared

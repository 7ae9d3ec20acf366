"""Issue 23: drawn ornaments stay inside their panel (marks are cut at its edge)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import Region, metrics
from strew.ornament import grow_elements
from strew.ornament._render import _clip_to_panel

RING = Region(shapely.Point(35, 35).buffer(35, quad_segs=32).difference(shapely.Point(35, 35).buffer(12, quad_segs=16)))


# seed 1960127676: the gallery's willow ring, whose stems stood out of the panel before
@pytest.mark.parametrize(("pattern", "style", "seed"), [("willow", "morris", 1960127676), ("hierarchy", "color", 7), ("flowers", "ink", 7)])
def test_every_mark_lies_inside_a_ring_panel(pattern, style, seed):
    orn = grow_elements(pattern, RING, seeds=[(35, 4)], rng=seed)
    arr = orn.render(style)
    assert len(arr) > 20
    assert len(metrics.outside(arr)) == 0


def test_clip_cuts_a_filled_mark_and_a_stroke_at_the_panel_edge():
    panel = shapely.box(0, 0, 10, 10)
    cover = shapely.buffer(panel, 1e-9)
    square = [np.array([[8.0, 8], [12, 8], [12, 12], [8, 12]])]
    (ring,) = _clip_to_panel(square, True, panel, cover)
    assert shapely.Polygon(ring).area == pytest.approx(4.0)
    line = [np.array([[-5.0, 5], [5, 5]])]
    (cut,) = _clip_to_panel(line, False, panel, cover)
    assert shapely.LineString(cut).length == pytest.approx(5.0)
    inside = [np.array([[1.0, 1], [2, 1], [2, 2]])]
    assert _clip_to_panel(inside, True, panel, cover) is inside
    assert _clip_to_panel([np.array([[20.0, 20], [30, 30]])], False, panel, cover) == []


# -- issue 23 point 7: the gallery's ornament flaws -----------------------------------------
def _world_parts(arr, i):
    """Element i's parts as world-space (n, 2) rings, part by part."""
    from strew.arrangement import transform_points

    return [[transform_points(p.points, arr.x[i], arr.y[i], arr.rotation[i], arr.scale[i]) for p in part.paths] for part in arr.element_parts[i]]


@pytest.mark.parametrize("seed", [1, 2])
def test_hierarchy_ring_main_vine_closes(seed):
    orn = grow_elements("hierarchy", RING, seeds=[(35, 4)], rng=seed)
    arr = orn.render("color")
    vines = shapely.union_all(arr.geometry[arr.kind_names == "vine"])
    # one piece, annulus-like: one hole, and the panel's hole inside it
    assert isinstance(vines, shapely.Polygon)
    assert len(vines.interiors) == 1
    assert shapely.Polygon(vines.interiors[0]).contains(shapely.Point(35, 35))


def test_vine_width_runs_on_at_every_joint():
    from strew.ornament.patterns.hierarchy import nearest_on

    orn = grow_elements("hierarchy", RING, seeds=[(35, 4)], rng=1)
    arr = orn.render("color")
    rows = {int(e): i for i, e in enumerate(arr["element"]) if arr.kind_names[i] == "vine"}
    by_index = {e.index: e for e in orn.elements}

    def widths(i):
        (body,) = _world_parts(arr, i)[0]
        assert len(body) == 50  # not cut at the panel's edge
        return np.hypot(*(body[:25] - body[::-1][:25]).T)  # (25,) across the curve at u = k / 24

    joints = 0
    for el, i in rows.items():
        vine = by_index[el]
        ends = [(vine.parent, 0)]
        if vine.target >= 0:  # a vine that joins two fronts: at its end too
            ends.append((by_index[vine.target], -1))
        for other, k in ends:
            if other.type != "vine":
                continue
            u = nearest_on(other.proxy, vine.proxy.points[k])
            assert np.hypot(*(other.proxy.point_at(u) - vine.proxy.points[k])) < 1e-9  # on a sample
            w_other = widths(rows[other.index])[int(round(u * 24))]
            assert abs(widths(i)[k] - w_other) <= 1e-6 * w_other
            joints += 1
    assert joints >= 10
    assert any(e.type == "vine" and e.target >= 0 for e in orn.elements)  # the ring was joined


@pytest.mark.parametrize("style", ["vine", "filigree"])
def test_each_spiral_is_one_outline(style):
    orn = grow_elements("spirals", Region.rectangle(60, 40), rng=2)
    arr = orn.render(style)
    arms = [e for e in orn.elements if e.type == "arm"]
    spirals = {a.spiral for a in arms}
    assert set(arr.kinds) == {"spiral"} and len(arr) == len(spirals) > 5
    for i in range(len(arr)):
        # one closed outline: no joins between segments' outlines to show a seam
        assert [len(part) for part in _world_parts(arr, i)] == [1]
        (ring,) = _world_parts(arr, i)[0]
        poly = shapely.Polygon(ring).buffer(0)
        first = next(a for a in arms if a.index == int(arr["element"][i]))
        mine = [a for a in arms if a.spiral == first.spiral]
        assert len(mine) >= 3
        centre = np.vstack([a.proxy.polyline(24)[1:-1] for a in mine])
        assert shapely.contains_xy(poly.buffer(1e-9), centre[:, 0], centre[:, 1]).mean() > 0.9


@pytest.mark.parametrize("panel", ["rect", "arch"])
def test_flowers_do_not_overlap_and_each_sits_on_a_stem(panel, tmp_path):
    from strew import load, save

    from strew.ornament._demo import _panels

    region = {k: r for k, _, r in _panels()}[panel]
    orn = grow_elements("flowers", region, rng=1)
    arr = orn.render("ink")
    pairs, areas = metrics.overlaps(arr)
    assert len(pairs) == 0  # all filled: no pair overlaps, none touches by more than an edge
    assert metrics.summary(arr)["filled_overlap_pairs"] == 0
    # and so once written and read back as SVG (coordinates rounded to 10 digits)
    save(arr, tmp_path / "f.svg")
    assert len(metrics.overlaps(load(tmp_path / "f.svg"))[0]) == 0
    kinds = arr.kind_names
    g = arr.geometry
    stems = shapely.union_all(g[kinds == "stem"])
    blooms = np.flatnonzero(np.isin(kinds, ["flower", "bud"]))
    assert len(blooms) > 40
    # every flower and bud touches a stem (none floats), within 1e-5 (a 1e-6 gap is kept)
    assert shapely.distance(g[blooms], stems).max() < 1e-5
    # and a stem shows between the flowers it joins: each one's drawn stem reaches both
    by_index = {e.index: e for e in orn.elements}
    at = {tuple(np.round(by_index[int(arr["element"][b])].proxy.center, 9)): b for b in blooms}
    for i in np.flatnonzero(kinds == "stem"):
        st = by_index[int(arr["element"][i])].proxy
        ends = [at.get(tuple(np.round(p, 9))) for p in (st.start, st.end)]
        assert None not in ends and all(shapely.distance(g[i], g[b]) < 1e-5 for b in ends)
    # stems don't cross stems: the proxies meet only at a shared flower's centre
    segs = [by_index[int(e)].proxy for e, k in zip(arr["element"], kinds) if k == "stem"]
    lines = [shapely.LineString([s.start, s.end]) for s in segs]
    tree = shapely.STRtree(lines)
    for a, b in zip(*tree.query(lines, predicate="intersects")):
        if a < b:
            meet = lines[a].intersection(lines[b])
            shared = {tuple(np.round(p, 9)) for p in (segs[a].start, segs[a].end)} & {tuple(np.round(p, 9)) for p in (segs[b].start, segs[b].end)}
            assert isinstance(meet, shapely.Point) and shared and np.allclose(meet.coords[0], list(shared)[0])

"""Local growth (Ijiri et al. §5): regularity, overlaps, rotation modes, tools, determinism."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from scipy.spatial import cKDTree

from strew import Arrangement, InputError, Region, Shape, metrics
from strew._feedback import ResultWarning
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar
from strew.grow._growth import ELEMENT, GrowParams, _Grower, _segments_cross

SPACING = 10.0


def six_neighbour_fraction(out, spacing=SPACING, margin=2.0):
    """Fraction of interior elements with exactly six neighbours at spacing ±15%."""
    xy = out.xy
    tree = cKDTree(xy)
    hull = shapely.MultiPoint(xy).convex_hull
    inner = shapely.distance(hull.boundary, shapely.points(xy)) > margin * spacing
    hi = np.array([len(tree.query_ball_point(p, 1.15 * spacing)) - 1 for p in xy])
    lo = np.array([len(tree.query_ball_point(p, 0.85 * spacing)) - 1 for p in xy])
    return int(inner.sum()), float(((hi == 6) & (lo == 0))[inner].mean())


def bond_angles(out, spacing=SPACING):
    tree = cKDTree(out.xy)
    pairs = np.array(sorted(tree.query_pairs(1.15 * spacing)))
    d = out.xy[pairs[:, 1]] - out.xy[pairs[:, 0]]
    return np.degrees(np.arctan2(d[:, 1], d[:, 0]))


def crossing_edges(xy, edges):
    mids = 0.5 * (xy[edges[:, 0]] + xy[edges[:, 1]])
    tree = cKDTree(mids)
    reach = np.linalg.norm(xy[edges[:, 0]] - xy[edges[:, 1]], axis=1).max()
    n = 0
    for a, (i, j) in enumerate(edges.tolist()):
        for b in tree.query_ball_point(mids[a], reach):
            k, m = edges[b]
            if len({i, j, k, m}) == 4 and _segments_cross(tuple(xy[i]), tuple(xy[j]), tuple(xy[k]), tuple(xy[m])):
                n += 1
    return n


@pytest.mark.parametrize("relax", [True, False])
def test_hex_lattice_grows_into_a_hex_lattice(relax):
    out = grow(hex_exemplar(), region=Region.rectangle(260, 200), rng=1, relax=relax)
    inner, frac = six_neighbour_fraction(out)
    assert inner > 200
    assert frac >= 0.90
    assert len(metrics.overlaps(out)[0]) == 0
    # filled: close to the lattice density (one element per 86.6 area units)
    assert len(out) >= 0.85 * 260 * 200 / (SPACING**2 * np.sqrt(3) / 2)


@pytest.mark.parametrize("make", [stone_exemplar, tile_exemplar])
def test_no_overlaps_and_inside_region(make):
    ex = make()
    assert len(metrics.overlaps(ex)[0]) == 0
    region = Region.circle(100, 100, 80)
    out = grow(ex, region=region, rng=3)
    assert len(out) > 100
    assert len(metrics.overlaps(out)[0]) == 0
    assert region.contains(out.xy).all()
    # every element copies an exemplar element: kind, and scale, and sub_id agree
    sub = out["sub_id"]
    assert np.array_equal(out.kind, ex.kind[sub])
    assert np.allclose(out.scale, ex.scale[sub])


def test_count_and_determinism():
    ex = stone_exemplar()
    a = grow(ex, count=150, rng=5)
    b = grow(ex, count=150, rng=5)
    assert len(a) == 150
    assert a.equals(b)
    c = grow(ex, count=150, rng=5, start=(40.0, -20.0))
    assert c.xy[0].tolist() == [40.0, -20.0]


def test_rotate_mode_reproduces_a_rotated_lattice():
    th = np.radians(20)
    ex = hex_exemplar()
    R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    xy = ex.xy @ R.T
    rotated = ex.replace(x=xy[:, 0], y=xy[:, 1])
    out = grow(rotated, count=300, mode="rotate", rng=2)
    ang = bond_angles(out)
    off = np.abs((ang - 20 + 30) % 60 - 30)  # distance to the lattice directions 20° + k 60°
    assert np.mean(off < 3) > 0.95
    _, frac = six_neighbour_fraction(out, margin=1.5)
    assert frac >= 0.9
    # the best-fit rotations are lattice symmetries: multiples of 60°
    r = np.degrees(out.rotation) % 60
    assert np.all(np.minimum(r, 60 - r) < 1e-6)


def test_flow_mode_aligns_elements_with_a_straight_field():
    th = np.radians(35)
    direction = np.array([np.cos(th), np.sin(th)])
    out = grow(hex_exemplar(), count=250, mode="flow", flow=lambda p: np.tile(direction, (len(p), 1)), rng=4)
    assert np.allclose(out.rotation, th)
    off = np.abs((bond_angles(out) - 35 + 30) % 60 - 30)
    assert np.mean(off < 3) > 0.95


def test_flow_mode_follows_strokes():
    from strew.fields import flow_field

    stroke = np.array([[0.0, 0.0], [200.0, 200.0]])  # 45° everywhere
    out = grow(hex_exemplar(), count=120, mode="flow", flow=flow_field([stroke]), rng=4)
    assert np.allclose(out.rotation, np.pi / 4, atol=1e-6)


def test_grown_connectivity_has_no_crossings_or_near_duplicates():
    # heuristics (b) merge at l_short and (d) edge collision, Fig. 6
    for ex in (stone_exemplar(), tile_exemplar()):
        ref = analyze(ex)
        out = grow(ref, region=Region.rectangle(150, 120), rng=2, relax=False, connectivity=True)
        edges = np.array(out.extra["connectivity"]["edges"])
        assert out.extra["connectivity"]["count"] == len(out)
        assert crossing_edges(out.xy, edges) == 0
        d, _ = cKDTree(out.xy).query(out.xy, k=2)
        assert d[:, 1].min() >= 0.5 * ref.shortest_edge


def _grower(**kw):
    ref = analyze(hex_exemplar())
    g = _Grower(ref, GrowParams(count=100, **kw), np.random.default_rng(0))
    return ref, g


def test_merge_heuristic_connects_to_existing_objects():
    ref, g = _grower()
    # a seed at the origin and an existing element where one of its ring slots will land
    s = g.new_object(0.0, 0.0, -1)
    a = int(np.flatnonzero(ref.ring_arrays()["ids"] >= 0)[0])
    rel = ref.ring_arrays()["rel"][a, 0]
    o = g.new_object(rel[0] + 0.3 * g.l_short, rel[1], -1)
    g._last_nb = np.zeros(0, dtype=np.int64)
    assert g.place(s, a, 0, 0.0)
    # no new seed within l_short of o; instead an edge s - o
    assert o in g.adj[s]
    near = [i for i in g.near(*g.pos[o], g.l_short) if i != o]
    assert near == []
    assert len(g.adj[s]) == 6


def test_angle_heuristic_drops_seeds_too_close_in_angle():
    ref, g = _grower()
    s = g.new_object(0.0, 0.0, -1)
    # an existing neighbour 25° away from ring slot 0's direction (< half of 60°)
    rings = ref.ring_arrays()
    rel0 = rings["rel"][0, 0]
    ang = np.arctan2(rel0[1], rel0[0]) + np.radians(25)
    o = g.new_object(25 * np.cos(ang), 25 * np.sin(ang), -1)
    g.add_edge(s, o)
    g._last_nb = np.zeros(0, dtype=np.int64)
    assert g.place(s, 0, 0, 0.0)
    seeds = [i for i in g.adj[s] if i != o and g.kind[i] >= 0]  # ring seeds carry a symbol id
    dirs = [np.degrees(np.arctan2(*(g.pos[i] - g.pos[s])[::-1])) for i in seeds]
    # slot 0 was dropped, the five others became seeds
    assert len(seeds) == 5
    assert all(abs((d - np.degrees(ang) + 180) % 360 - 180) >= 30 - 1e-9 for d in dirs)


def test_edge_collision_heuristic():
    ref, g = _grower()
    s = g.new_object(0.0, 0.0, -1)
    rel0 = ref.ring_arrays()["rel"][0, 0]
    # an existing edge crossing the segment from s to ring slot 0, far from the slot itself
    mid = 0.5 * rel0
    perp = np.array([-rel0[1], rel0[0]]) / np.linalg.norm(rel0)
    p = g.new_object(*(mid + 20 * perp), -1)
    q = g.new_object(*(mid - 20 * perp), -1)
    g.add_edge(p, q)
    g._last_nb = np.zeros(0, dtype=np.int64)
    assert g.place(s, 0, 0, 0.0)
    for i in g.adj[s]:
        assert not _segments_cross(tuple(g.pos[s]), tuple(g.pos[i]), tuple(g.pos[p]), tuple(g.pos[q]))
    assert len([i for i in g.adj[s] if g.kind[i] >= 0]) == 5


def test_long_edge_heuristic_adds_a_seed_on_the_bisector():
    ref, g = _grower()
    s = g.new_object(0.0, 0.0, -1)
    g.state[s] = ELEMENT
    # two neighbours 120° apart at distance 10: their edge would be 17.3 > 1.5 * 10
    a = g.new_object(10.0, 0.0, 0)
    b = g.new_object(10 * np.cos(2 * np.pi / 3), 10 * np.sin(2 * np.pi / 3), 0)
    g.add_edge(s, a)
    g.add_edge(s, b)
    before = g.n
    g._ring_edges(s, 0, {}, ref.ring_arrays()["rel"][0, :6], 1.0, 0.0)
    assert g.n == before + 1
    x = g.n - 1
    assert g.kind[x] == -1  # no symbol id
    assert np.allclose(g.pos[x], 10 * np.array([np.cos(np.pi / 3), np.sin(np.pi / 3)]))
    assert {s, a, b} <= g.adj[x]
    assert b not in g.adj[a]


def test_spray_limits_growth_to_the_path():
    path = np.array([[0.0, 0.0], [150.0, 0.0], [150.0, 80.0]])
    radius = 18.0
    out = grow(stone_exemplar(), spray=path, spray_radius=radius, rng=1)
    line = shapely.LineString(path)
    d = shapely.distance(line, shapely.points(out.xy))
    assert np.all(d <= radius + 1e-9)
    # the whole path is covered: its far end has elements near it
    assert np.linalg.norm(out.xy - path[-1], axis=1).min() < radius
    assert len(out) > 40


def test_boundary_strokes_stop_growth():
    region = Region.rectangle(200, 100)
    wall = np.array([[120.0, -10.0], [120.0, 110.0]])
    out = grow(hex_exemplar(), region=region, start=(50.0, 50.0), boundary=[wall], rng=1, connectivity=True)
    assert len(out) > 60
    assert np.all(out.x < 120)
    # and growth reaches the wall
    assert out.x.max() > 100
    # a wall with a gap lets growth around it
    short = np.array([[120.0, -10.0], [120.0, 60.0]])
    out2 = grow(hex_exemplar(), region=region, start=(50.0, 50.0), boundary=[short], rng=1)
    assert np.any(out2.x > 130)


def test_priority_grows_high_priority_kinds_first():
    ex = stone_exemplar()
    kinds = ex.kinds
    base = grow(ex, count=200, rng=3)
    out = grow(ex, count=200, rng=3, priority={"gray_stone": 5.0})
    g = kinds.index("gray_stone")
    assert (out.kind == g).mean() > (base.kind == g).mean()


def test_variation_jitter():
    ex = tile_exemplar()
    out = grow(ex, count=150, rng=8, jitter_scale=0.1, jitter_rotation=np.radians(10), jitter_color=0.2)
    sub = out["sub_id"]
    ratio = out.scale / ex.scale[sub]
    assert ratio.min() >= 0.9 - 1e-12 and ratio.max() <= 1.1 + 1e-12
    assert ratio.std() > 0.02
    assert len(set(out["color"].tolist())) > 20
    assert len(metrics.overlaps(out)[0]) == 0


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({}, "give count"),
        ({"count": 0}, "count:"),
        ({"count": 5, "mode": "spin"}, "mode: unknown choice 'spin'"),
        ({"count": 5, "mode": "flow"}, "needs a flow field"),
        ({"count": 5, "spray": [[0, 0], [1, 1]]}, "spray_radius:"),
        ({"count": 5, "priority": {"nope": 1}}, "unknown kind 'nope'"),
        ({"count": 5, "jitter_scale": 1.5}, "jitter_scale:"),
        ({"region": Region.rectangle(10, 10), "start": (50, 50)}, "outside the region"),
    ],
)
def test_bad_parameters(kwargs, message):
    with pytest.raises(InputError, match=message):
        grow(hex_exemplar(), **kwargs)


def test_grown_connectivity_round_trips_as_an_exemplar(tmp_path):
    from strew import load, save

    out = grow(hex_exemplar(), count=120, rng=1, connectivity=True)
    p = tmp_path / "g.json"
    save(out, p)
    back = load(p)
    ref = analyze(back)
    assert {tuple(e) for e in ref.edges.tolist()} == {tuple(e) for e in out.extra["connectivity"]["edges"]}
    with pytest.raises(InputError, match="made for 120 elements"):
        analyze(back.select(np.arange(100)))


def test_progress_and_cancellation():
    from strew import Cancelled

    seen = []
    grow(hex_exemplar(), count=300, rng=1, progress=lambda d, t, m: seen.append((d, t)))
    assert seen and seen[-1] == (300, 300)
    assert all(a[0] <= b[0] for a, b in zip(seen, seen[1:]))
    with pytest.raises(Cancelled):
        grow(hex_exemplar(), count=300, rng=1, should_cancel=lambda: True)


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=8)
@given(st.floats(-np.pi, np.pi), st.floats(0.5, 3.0), st.floats(-1e3, 1e3), st.floats(-1e3, 1e3))
def test_similarity_transformed_lattice_grows_regularly(angle, s, tx, ty):
    # rotate, scale and move the exemplar lattice: the grown pattern follows
    ex = hex_exemplar()
    R = s * np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    xy = ex.xy @ R.T + (tx, ty)
    shapes = {k: sh.transformed(np.c_[s * np.eye(2), np.zeros(2)]) for k, sh in ex.shapes.items()}
    moved = ex.replace(shapes=shapes, x=xy[:, 0], y=xy[:, 1], rotation=np.full(len(ex), angle))
    out = grow(moved, count=200, mode="rotate", rng=0)
    _, frac = six_neighbour_fraction(out, spacing=SPACING * s, margin=1.5)
    assert frac >= 0.9
    assert len(metrics.overlaps(out)[0]) == 0


def test_initial_seed_with_a_symbol_id():
    ex = stone_exemplar()
    for name in ex.kinds:
        out = grow(ex, count=5, rng=0, start_kind=name)
        assert out.kind_names[0] == name
    with pytest.raises(InputError, match="start_kind:"):
        grow(ex, count=5, start_kind="nope")


def test_region_with_a_hole_keeps_centres_inside():
    outer = shapely.box(0, 0, 200, 160)
    region = Region(outer.difference(shapely.Point(100, 80).buffer(40)))
    out = grow(stone_exemplar(), region=region, start=(20.0, 20.0), rng=6)
    assert len(out) > 100
    assert region.contains(out.xy).all()
    assert np.all(np.hypot(out.x - 100, out.y - 80) > 39.9)  # the hole is a 64-gon of radius 40
    assert len(metrics.overlaps(out)[0]) == 0


def test_growth_order_is_nearest_seed_first():
    # §5.1: the seed nearest the initial seed grows first, so the lattice grows in rings
    out = grow(hex_exemplar(), count=61, rng=0, relax=False, start=(0.0, 0.0))
    d = np.hypot(out.x, out.y)
    assert d[0] == 0.0
    assert np.allclose(d[1:7], SPACING)
    assert np.all(np.diff(d) >= -1e-9)  # on an exact lattice: never closer than before


@pytest.mark.parametrize("avoid", [True, False])
def test_elements_large_against_their_spacing_do_not_hang(avoid):
    """Issue 17.5: octagons of radius 89 within 0.07 units made each grid lookup walk
    about 10^8 empty cells (over 60 s before should_cancel was first polled)."""
    import time

    t = np.linspace(0, 2 * np.pi, 8, endpoint=False)
    octagon = Shape.polygon(np.c_[89 * np.cos(t), 89 * np.sin(t)])
    xy = np.random.default_rng(0).uniform(0, 0.07, (10, 2))
    ex = Arrangement({"oct": octagon}, np.zeros(10, int), xy[:, 0], xy[:, 1])
    t0 = time.perf_counter()
    if avoid:  # every copy of these octagons collides: growth stops at once, and says why (issue 22.3)
        with pytest.warns(ResultWarning, match="made 1 of the 100 elements.*avoid_overlaps=False"):
            out = grow(ex, count=100, rng=1, avoid_overlaps=avoid, should_cancel=lambda: False)
    else:
        out = grow(ex, count=100, rng=1, avoid_overlaps=avoid, should_cancel=lambda: False)
    # a hang regression, not a speed measurement: before the fix this took minutes
    assert time.perf_counter() - t0 < 20
    assert 1 <= len(out) <= 100
    if avoid:
        assert len(metrics.overlaps(out)[0]) == 0
    else:
        assert len(out) == 100

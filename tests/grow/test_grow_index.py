"""The growth's spatial index (strew.grow._index.GrowIndex) against brute force."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from strew.grow._index import GrowIndex
from strew_testing import crosses_strictly


def _index(n: int, cell: float):
    cap = max(n, 1)
    pos = np.zeros((cap, 2))
    state = np.zeros(cap, dtype=np.int8)
    xy: list[tuple[float, float]] = []
    return GrowIndex(cell, pos, state, xy), pos, state, xy


coords = st.floats(-50, 50, allow_nan=False, width=32)


@settings(max_examples=30, deadline=None)
@given(
    pts=st.lists(st.tuples(coords, coords, st.integers(0, 3)), min_size=1, max_size=60),
    moves=st.lists(st.tuples(st.integers(0, 59), coords, coords), max_size=40),
    dead=st.lists(st.integers(0, 59), max_size=10),
    q=st.tuples(coords, coords, st.floats(0, 80)),
    states=st.integers(1, 15),
    cell=st.sampled_from([0.7, 3.0, 25.0]),
)
def test_near_matches_a_scan_after_moves_and_removals(pts, moves, dead, q, states, cell):
    idx, pos, state, xy = _index(len(pts), cell)
    for i, (x, y, s) in enumerate(pts):
        pos[i] = (x, y)
        state[i] = s
        xy.append((float(x), float(y)))
        idx.adj.append(set())
        idx.insert(i, x, y)
    live = np.ones(len(pts), dtype=bool)
    for i, x, y in moves:
        i %= len(pts)
        ox, oy = xy[i]
        pos[i] = (x, y)
        xy[i] = (float(x), float(y))
        idx.move(i, ox, oy, x, y)
    for i in dead:
        i %= len(pts)
        idx.remove(i)
        live[i] = False
    x, y, r = q
    got = idx.near(x, y, r, states)
    want = [i for i in range(len(pts)) if live[i] and (states >> int(state[i])) & 1
            and (pos[i, 0] - x) ** 2 + (pos[i, 1] - y) ** 2 <= r * r]
    assert sorted(got) == want
    assert len(set(got)) == len(got)
    # several queries at once: the same objects in the same order, query by query
    qs = [(x, y, r), (y, x, 0.5 * r), (x + 1.0, y - 2.0, 2.0 * r)]
    qi, js = idx.near_many(np.array([a for a, _, _ in qs]), np.array([b for _, b, _ in qs]), np.array([c for _, _, c in qs]), states)
    assert list(zip(qi.tolist(), js.tolist())) == [(k, j) for k, (a, b, c) in enumerate(qs) for j in idx.near(a, b, c, states)]
    if got:
        assert idx.near(x, y, r, states, limit=1) == got[:1]
        # grid order: by cell column, then row (the order the growth's ties depend on)
        cells = [(math.floor(xy[i][0] / cell), math.floor(xy[i][1] / cell)) for i in got]
        assert cells == sorted(cells)


@settings(max_examples=30, deadline=None)
@given(
    pts=st.lists(st.tuples(coords, coords), min_size=2, max_size=40),
    pairs=st.lists(st.tuples(st.integers(0, 39), st.integers(0, 39)), max_size=60),
    drop=st.lists(st.integers(0, 59), max_size=15),
    moves=st.lists(st.tuples(st.integers(0, 39), coords, coords), max_size=20),
    seg=st.tuples(coords, coords, coords, coords),
    cell=st.sampled_from([1.0, 6.0, 40.0]),
)
def test_crosses_matches_a_scan_of_the_live_edges(pts, pairs, drop, moves, seg, cell):
    n = len(pts)
    idx, pos, state, xy = _index(n, cell)
    for i, (x, y) in enumerate(pts):
        pos[i] = (x, y)
        state[i] = 1
        xy.append((float(x), float(y)))
        idx.adj.append(set())
        idx.insert(i, x, y)
    made = []
    for a, b in pairs:
        a, b = a % n, b % n
        idx.add_edge(a, b, a, b)
        if a != b:
            made.append((a, b))
    for k in drop:
        if made:
            a, b = made[k % len(made)]
            idx.remove_edge(a, b)
    for i, x, y in moves:
        i %= n
        ox, oy = xy[i]
        pos[i] = (x, y)
        xy[i] = (float(x), float(y))
        idx.move(i, ox, oy, x, y)
    assert idx.edges == {(min(a, b), max(a, b)) for a in range(n) for b in idx.adj[a]}
    p, q = (seg[0], seg[1]), (seg[2], seg[3])
    for ia, ib in ((-2, -2), (0, -2), (0, 1)):
        want = any(crosses_strictly(p, q, xy[u], xy[v]) for u, v in idx.edges if u not in (ia, ib) and v not in (ia, ib))
        assert idx.crosses(ia, p, ib, q) == want
        assert idx.crosses_plane(ia, p, ib, q) == want  # the plane's short path


def test_crosses_on_a_torus_sees_an_edge_across_the_tile_edge():
    idx, pos, state, xy = _index(4, 2.0)
    tile = (0.0, 0.0, 10.0, 10.0)
    # an edge just right of the tile's left edge; a segment near the right edge whose
    # image one tile to the left crosses it
    for i, (x, y) in enumerate([(0.5, 4.0), (0.5, 6.0), (9.0, 5.0), (11.0, 5.0)]):
        pos[i] = (x, y)
        state[i] = 1
        xy.append((x, y))
        idx.adj.append(set())
        idx.insert(i, x, y)
    idx.add_edge(0, 1, 0, 1)
    assert not idx.crosses(-2, (9.0, 5.0), -2, (9.8, 5.0), tile, 3.0)
    assert idx.crosses(-2, (9.0, 5.0), -2, (11.0, 5.0), tile, 3.0)
    # an edge at an image of one of the segment's ends does not count
    assert not idx.crosses(0, (9.0, 5.0), -2, (11.0, 5.0), tile, 3.0)

"""grow's edge grid: ``GrowIndex._index_edge`` lists an edge through the compiled
``_index_kernels.edge_insert`` and leaves the grid as ``HashGrid.insert`` leaves it
(issue 14 point 5, speed; byte-identical output)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import strew.grow._index as gi
from strew.grow._index import GrowIndex

coords = st.floats(-40, 40, allow_nan=False, width=32)


def _grid_state(idx: GrowIndex):
    ec = idx.edge_cells
    n = ec.n
    return (n, ec.head.tolist(), ec.tail.tolist(), ec.ent[:n].tolist(), ec.ext.tolist(), None if ec._ext is None else list(ec._ext), ec.cur.tolist(), ec.live)


def _run(pts, edges, moves, cell, compiled: bool):
    cap = len(pts)
    pos = np.zeros((cap, 2))
    state = np.ones(cap, dtype=np.int8)
    xy: list[tuple[float, float]] = []
    idx = GrowIndex(cell, pos, state, xy)
    for i, (x, y) in enumerate(pts):
        pos[i] = (x, y)
        xy.append((float(x), float(y)))
        idx.adj.append(set())
        idx.insert(i, x, y)
    calls = {"n": 0}
    real = gi.edge_insert

    def edge_insert(*a):
        calls["n"] += 1
        return real(*a) if compiled else (-1, False, False)

    gi.edge_insert = edge_insert
    try:
        for a, b in edges:
            idx.add_edge(a % cap, b % cap, a % cap, b % cap)
        for i, x, y in moves:
            i %= cap
            ox, oy = xy[i]
            pos[i] = (x, y)
            xy[i] = (float(x), float(y))
            idx.move(i, ox, oy, x, y)
        for a, b in edges[::3]:
            idx.remove_edge(a % cap, b % cap)
    finally:
        gi.edge_insert = real
    return _grid_state(idx), calls["n"]


@settings(max_examples=20, deadline=None)
@given(
    pts=st.lists(st.tuples(coords, coords), min_size=2, max_size=40),
    edges=st.lists(st.tuples(st.integers(0, 39), st.integers(0, 39)), min_size=1, max_size=400),
    moves=st.lists(st.tuples(st.integers(0, 39), coords, coords), max_size=60),
    cell=st.sampled_from([0.9, 4.0, 30.0]),
)
def test_edge_insert_leaves_the_grid_as_insert_does(pts, edges, moves, cell):
    # many edges over few points: the entry array grows and the table is rebuilt
    # (stale entries of moved ends), boxes of one cell and of many
    want, _ = _run(pts, edges, moves, cell, compiled=False)
    got, calls = _run(pts, edges, moves, cell, compiled=True)
    assert got == want
    if len({(min(a, b), max(a, b)) for a, b in ((a % len(pts), b % len(pts)) for a, b in edges) if a != b}) > 1:
        assert calls > 0  # the first listing sets the extent in Python; the next ones are compiled

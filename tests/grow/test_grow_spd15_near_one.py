"""grow's single point query (``strew.grow._index_kernels.near_one``, issue 14 point 5,
speed; byte-identical output) against the shared grid's batched query
(:func:`strew._kernels.grid.hash_near`): the same objects in the same order, with and
without a limit, after moves and removals (h/spd14w's test, ported with the kernel)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from strew._kernels.grid import HashGrid, hash_near

coords = st.floats(-50, 50, allow_nan=False, width=32)


@settings(max_examples=40, deadline=None)
@given(
    pts=st.lists(st.tuples(coords, coords, st.integers(0, 3)), min_size=1, max_size=60),
    moves=st.lists(st.tuples(st.integers(0, 59), coords, coords), max_size=30),
    dead=st.lists(st.integers(0, 59), max_size=10),
    q=st.tuples(coords, coords, st.floats(0, 80)),
    classes=st.integers(1, 15),
    limit=st.sampled_from([1, 2, 5, 1000]),
    cell=st.sampled_from([0.7, 3.0, 25.0]),
)
def test_near_one_is_hash_near_of_one_query(pts, moves, dead, q, classes, limit, cell):
    from strew.grow._index_kernels import near_one

    n = len(pts)
    grid = HashGrid(cell, n)
    pos = np.zeros((n, 2))
    cls = np.zeros(n, dtype=np.int8)
    for i, (x, y, c) in enumerate(pts):
        pos[i] = (x, y)
        cls[i] = c
        grid.insert_point(i, float(x), float(y))
    for i, x, y in moves:
        pos[i % n] = (x, y)
        grid.insert_point(i % n, float(x), float(y))
    for i in dead:
        grid.remove(i % n)
    x, y, r = (float(v) for v in q)
    oq, want = np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.int64)
    k = hash_near(np.array([x]), np.array([y]), np.array([r]), classes, limit, grid.cell, grid.head, grid.ent, grid.cur,
                  grid.ext, pos, cls, oq, want)
    got = np.full(n, -1, dtype=np.int64)
    m = near_one(x, y, r, classes, limit, grid.cell, grid.head, grid.ent, grid.cur, grid.ext, pos, cls, got)
    assert m == k
    assert got[:m].tolist() == want[:k].tolist()
    # and against a scan: every live object of the classes within r, at most limit
    live = [i for i in range(n) if i in grid]
    scan = {i for i in live if (classes >> int(cls[i])) & 1 and (pos[i, 0] - x) ** 2 + (pos[i, 1] - y) ** 2 <= r * r}
    assert set(got[:m].tolist()) <= scan and m == min(limit, len(scan))

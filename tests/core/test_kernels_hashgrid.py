"""The hashed incremental grid (strew._kernels.grid.HashGrid and its compiled queries)
against brute force: after insertions, moves (a new listing), removals and rebuilds, a
query gives exactly the current items, in cell order and creation order within a cell."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from strew._kernels.grid import GONE, HashGrid, hash_cross, hash_insert_box, hash_near, hash_query_box, hash_segments
from strew_testing import crosses_strictly

ITEMS = 24
# quarter units: sums, differences and the crossing test's products are exact in floats;
# a small field, so that items share cells and moves stay near (order and staleness show)
coords = st.integers(-60, 60).map(lambda v: v / 4)
sizes = st.integers(0, 40).map(lambda v: v / 4)
cells = st.sampled_from([0.75, 3.0, 11.0, 40.0])
tables = st.sampled_from([1, 4, 1024])  # tiny tables: many cells per chain, frequent rebuilds

# an operation: ("box", item, x, y, w, h), ("point", item, x, y), ("remove", item), ("rebuild",)
ops = st.lists(
    st.one_of(
        st.tuples(st.just("box"), st.integers(0, ITEMS - 1), coords, coords, sizes, sizes),
        st.tuples(st.just("point"), st.integers(0, ITEMS - 1), coords, coords),
        st.tuples(st.just("remove"), st.integers(0, ITEMS - 1)),
        st.tuples(st.just("rebuild")),
    ),
    max_size=80,
)


class Model:
    """What the grid should hold: each item's current box and when it was listed."""

    def __init__(self, cell: float) -> None:
        self.cell = cell
        self.box: dict[int, tuple[float, float, float, float]] = {}
        self.when: dict[int, int] = {}
        self.clock = 0

    def insert(self, item: int, box: tuple[float, float, float, float]) -> None:
        self.box[item] = box
        self.when[item] = self.clock
        self.clock += 1

    def remove(self, item: int) -> None:
        self.box.pop(item, None)
        self.when.pop(item, None)

    def span(self, box) -> tuple[int, int, int, int]:
        h = self.cell
        return math.floor(box[0] / h), math.floor(box[1] / h), math.floor(box[2] / h), math.floor(box[3] / h)

    def query(self, box) -> list[int]:
        """Items listed in the cells the box touches: cell by cell (x-major), oldest
        listing first within a cell, each item once."""
        qx0, qy0, qx1, qy1 = self.span(box)
        listed = []  # (cell x, cell y, when, item) of every listing in the box's cells
        for i, b in self.box.items():
            x0, y0, x1, y1 = self.span(b)
            for cx in range(max(x0, qx0), min(x1, qx1) + 1):
                for cy in range(max(y0, qy0), min(y1, qy1) + 1):
                    listed.append((cx, cy, self.when[i], i))
        seen: list[int] = []
        for *_, i in sorted(listed):
            if i not in seen:
                seen.append(i)
        return seen


def _apply(grid: HashGrid, model: Model, pos: np.ndarray, op) -> None:
    if op[0] == "box":
        _, i, x, y, w, h = op
        grid.insert(i, x, y, x + w, y + h)
        model.insert(i, (x, y, x + w, y + h))
        pos[i] = (x, y)
    elif op[0] == "point":
        _, i, x, y = op
        grid.insert_point(i, x, y)
        model.insert(i, (x, y, x, y))
        pos[i] = (x, y)
    elif op[0] == "remove":
        grid.remove(op[1])
        model.remove(op[1])
    else:
        grid.rebuild()


@settings(max_examples=60, deadline=None)
@given(ops=ops, cell=cells, table=tables, q=st.tuples(coords, coords, sizes, sizes))
def test_box_query_is_the_current_items_in_cell_and_creation_order(ops, cell, table, q):
    grid, model = HashGrid(cell, 4, table=table), Model(cell)
    pos = np.zeros((ITEMS, 2))
    for op in ops:
        _apply(grid, model, pos, op)
        assert grid.live == len(model.box)
    # the given box, every box ever listed (where stale entries lie) and one around everything
    boxes = [(q[0], q[1], q[0] + q[2], q[1] + q[3]), (-1e3, -1e3, 1e3, 1e3)]
    boxes += [(op[2], op[3], op[2] + op[4], op[3] + op[5]) if op[0] == "box" else (op[2], op[3], op[2], op[3])
              for op in ops if op[0] in ("box", "point")]
    for box in boxes:
        assert grid.query(*box).tolist() == model.query(box)
    assert sorted(grid.query(-1e3, -1e3, 1e3, 1e3).tolist()) == sorted(model.box)
    assert [i for i in range(ITEMS) if i in grid] == sorted(model.box)
    # a rebuild drops only stale entries: the same answers after it
    before = grid.n
    grid.rebuild()
    assert grid.n <= before
    for box in boxes:
        assert grid.query(*box).tolist() == model.query(box)
    assert all(grid.cur[i] == GONE for i in range(len(grid.cur)) if i not in model.box)
    assert [i for i in range(ITEMS) if i in grid] == sorted(model.box)


boxes_of = st.lists(st.tuples(coords, coords, sizes, sizes), max_size=40)


def _same_structure(grid: HashGrid, head, tail, ent, ext, n) -> None:
    assert n == grid.n
    assert np.array_equal(head, grid.head) and np.array_equal(ext, grid.ext)
    assert np.array_equal(ent[:n], grid.ent[:n])
    if tail is not None:
        assert np.array_equal(tail, grid.tail)


@settings(max_examples=60, deadline=None)
@given(items=boxes_of, cell=st.sampled_from([3.0, 11.0, 40.0]), q=st.tuples(coords, coords, sizes, sizes))
def test_compiled_box_listing_is_the_python_one(items, cell, q):
    """hash_insert_box (pack's placed regions, listed from compiled code) builds the very
    arrays HashGrid.insert builds (no rebuild runs: few entries), and the grid it builds
    answers box queries as the model does."""
    b = [(x, y, x + w, y + h) for x, y, w, h in items]
    grid, model = HashGrid(cell, len(b) + 1, table=1024), Model(cell)
    head = np.full(len(grid.head), -1, np.int64)
    tail = head.copy()
    ent = np.full((9 * 1024, 4), -1, np.int64)
    ext = np.array([0, 0, -1, -1], np.int64)
    n = 0
    for i, box in enumerate(b):
        grid.insert(i, *box)
        model.insert(i, box)
        n = hash_insert_box(cell, head, tail, ent, ext, n, i, *box)
    _same_structure(grid, head, tail, ent, ext, n)
    cur = np.zeros(len(b) + 1, np.int64)  # every entry current
    for box in [(q[0], q[1], q[0] + q[2], q[1] + q[3]), (-1e3, -1e3, 1e3, 1e3), *b]:
        out = np.empty(len(b) + 1, np.int64)
        m = hash_query_box(cell, head, ent, cur, ext, *box, np.zeros(len(b) + 1, np.int64), 1, out)
        assert out[:m].tolist() == model.query(box)


@settings(max_examples=60, deadline=None)
@given(segs=st.lists(st.tuples(coords, coords, coords, coords), max_size=40), cell=cells, table=st.sampled_from([1, 4, 64]))
def test_segment_grid_built_at_once_is_the_incremental_one(segs, cell, table):
    """hash_segments (pack's domain edges) lists each segment by its box, as listing them
    one by one in a HashGrid of the same table would (no rebuild: a table it never outgrows)."""
    s = np.array(segs, dtype=float).reshape(-1, 4)
    head, ent, ext = hash_segments(s, cell, table)
    grid = HashGrid(cell, len(s) + 1, table=table)
    grid.rebuild = lambda: None  # the compiled build keeps its table whatever the entries
    for i, (ax, ay, bx, by) in enumerate(s):
        grid.insert(i, min(ax, bx), min(ay, by), max(ax, bx), max(ay, by))
    _same_structure(grid, head, None, ent, ext, grid.n)
    assert len(ent) == max(grid.n, 1)


@settings(max_examples=60, deadline=None)
@given(
    pts=st.lists(st.tuples(st.integers(0, ITEMS - 1), coords, coords), max_size=60),
    steps=st.lists(st.tuples(st.integers(0, ITEMS - 1), sizes, sizes), max_size=20),
    dead=st.lists(st.integers(0, ITEMS - 1), max_size=8),
    cls=st.lists(st.integers(0, 3), min_size=ITEMS, max_size=ITEMS),
    queries=st.lists(st.tuples(coords, coords, sizes), min_size=1, max_size=4),
    reach=st.integers(0, 120).map(lambda v: v / 4),
    classes=st.integers(1, 15),
    cell=cells,
    table=tables,
)
def test_near_is_the_points_within_reach_in_cell_and_creation_order(pts, steps, dead, cls, queries, reach, classes, cell, table):
    grid, model = HashGrid(cell, ITEMS, table=table), Model(cell)
    pos = np.zeros((ITEMS, 2))
    for i, x, y in pts:  # a listed item listed again is a move: a new listing, the old one stale
        _apply(grid, model, pos, ("point", i, x, y))
    was = [(x, y) for _, x, y in pts]
    for i, dx, dy in steps:  # short moves: the old entry near the new one
        if i in model.box:
            was.append(tuple(pos[i]))
            _apply(grid, model, pos, ("point", i, pos[i, 0] + dx, pos[i, 1] + dy))
    for i in dead:
        _apply(grid, model, pos, ("remove", i))
    # also around every place a point was listed at (where stale entries lie)
    queries = queries + [(x, y, reach) for x, y in was]
    cls = np.array(cls, dtype=np.int8)
    xs, ys, rs = (np.array([q[k] for q in queries]) for k in range(3))
    oq, oi = np.empty(ITEMS * len(queries), np.int64), np.empty(ITEMS * len(queries), np.int64)
    k = hash_near(xs, ys, rs, classes, ITEMS, cell, grid.head, grid.ent, grid.cur, grid.ext, pos, cls, oq, oi)
    want = []
    for n, (x, y, r) in enumerate(queries):
        # within reach and of a wanted class, in the order of the box query around the disc
        hits = [i for i in model.query((x - r, y - r, x + r, y + r))
                if (pos[i, 0] - x) ** 2 + (pos[i, 1] - y) ** 2 <= r * r and (classes >> int(cls[i])) & 1]
        want += [(n, i) for i in hits]
    assert list(zip(oq[:k].tolist(), oi[:k].tolist())) == want
    # at most `limit` per query: the first ones; output too short: -1
    k1 = hash_near(xs, ys, rs, classes, 1, cell, grid.head, grid.ent, grid.cur, grid.ext, pos, cls, oq, oi)
    firsts = [next(((n, i) for m, i in want if m == n), None) for n in range(len(queries))]
    assert list(zip(oq[:k1].tolist(), oi[:k1].tolist())) == [p for p in firsts if p is not None]
    if want:
        short = np.empty(len(want) - 1, np.int64)
        assert hash_near(xs, ys, rs, classes, ITEMS, cell, grid.head, grid.ent, grid.cur, grid.ext, pos, cls, short, short.copy()) == -1


@settings(max_examples=60, deadline=None)
@given(
    pts=st.lists(st.tuples(coords, coords), min_size=2, max_size=16),
    segs=st.lists(st.tuples(st.integers(0, 15), st.integers(0, 15)), min_size=1, max_size=ITEMS),
    moves=st.lists(st.tuples(st.integers(0, 15), coords, coords), max_size=12),
    dead=st.lists(st.integers(0, ITEMS - 1), max_size=6),
    q=st.tuples(coords, coords, coords, coords),
    tags=st.tuples(st.integers(-2, 15), st.integers(-2, 15)),
    cell=cells,
    table=tables,
)
def test_cross_sees_exactly_the_current_segments(pts, segs, moves, dead, q, tags, cell, table):
    n = len(pts)
    pos = np.array(pts, dtype=float)
    ends = np.array([(a % n, b % n, a % n, b % n) for a, b in segs], dtype=np.int64)
    grid = HashGrid(cell, 2, table=table)

    def listing(d):
        (ax, ay), (bx, by) = pos[ends[d, 0]], pos[ends[d, 1]]
        grid.insert(d, min(ax, bx), min(ay, by), max(ax, bx), max(ay, by))

    for d in range(len(ends)):
        listing(d)
    gone = set()
    for i, x, y in moves:  # a moved end: its segments listed anew (the old entries stale)
        pos[i % n] = (x, y)
        for d in range(len(ends)):
            if i % n in ends[d, :2] and d not in gone:
                listing(d)
    for d in dead:
        if d < len(ends):
            grid.remove(d)
            gone.add(d)
    # the given segment, and one across the middle of each segment listed, removed or not
    probes = [((q[0], q[1]), (q[2], q[3]), tags)]
    for d in range(len(ends)):
        (ax, ay), (bx, by) = pos[ends[d, 0]], pos[ends[d, 1]]
        mx, my, nx, ny = (ax + bx) / 2, (ay + by) / 2, (ay - by) / 2, (bx - ax) / 2
        probes += [((mx - nx, my - ny), (mx + nx, my + ny), (-2, -2)), ((mx - nx, my - ny), (mx + nx, my + ny), tags)]
    for p, r, (ta, tb) in probes:
        want = any(crosses_strictly(p, r, pos[ends[d, 0]], pos[ends[d, 1]]) for d in range(len(ends))
                   if d not in gone and not {int(ends[d, 2]), int(ends[d, 3])} & {ta, tb})
        assert hash_cross(p[0], p[1], r[0], r[1], ta, tb, cell, grid.head, grid.ent, grid.cur, grid.ext, ends, pos) == want


def test_table_must_be_a_power_of_two():
    with pytest.raises(ValueError, match="power of two"):
        HashGrid(1.0, table=3)

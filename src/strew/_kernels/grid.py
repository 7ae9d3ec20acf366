"""The shared spatial grids (issue 15 point 5): a bucket grid over points, built once,
and one incremental grid, filled as elements are placed: a hashed one of unbounded
cells, whose items may move and leave (grow) or stay where they were listed (pack,
ornament).

Both are uniform grids of square cells held as linked lists in flat int64 arrays, so
compiled loops walk them with no allocation:

* **bucket grid** over points (:func:`bucket_grid`): ``head`` (nx * ny,) holds the first
  point of each cell (-1: empty), ``nxt`` (n,) the next point of the same cell. Cell of
  a point: ``int((x - x0) / cell) * ny + int((y - y0) / cell)``. Points near ``(x, y)``
  within ``reach`` are those of the cells ``int((x - reach - x0) / cell)`` ..
  ``int((x + reach - x0) / cell)`` (clamped to ``0 .. nx - 1``), likewise in y.
* **hashed incremental grid** (:class:`HashGrid`): unbounded cells ``(floor(x / cell),
  floor(y / cell))`` hashed into a power-of-two table of chains; ``ent`` (m, 4) int64
  holds each entry's item, cell x, cell y and the next entry of its chain, appended at
  the chain's tail, so the entries of a cell are met in creation order (callers whose
  output depends on that order, grow's, stay byte-identical). Items are listed by point
  or by box (an item is listed in every cell its box touches); listing an item again (a
  move) makes its old entries stale, removing it marks it gone (``cur``: an entry ``e``
  of item ``i`` is current when ``e >= cur[i]``), and a rebuild drops stale entries.
  ``ext`` holds the cells any entry was made in; queries walk no cell outside it.
  Compiled queries: :func:`hash_near` (points within a radius, filtered by class bits),
  :func:`hash_cross` (segments crossed) and :func:`hash_query_box` (items in a box's
  cells), all through :func:`hash_span` (the cells of a box). Compiled listing, for
  callers whose items never move: :func:`hash_insert_box` (pack lists each placed region
  from its compiled loop, in a table it sizes to its domain's cells, never grown) and
  :func:`hash_segments` (a domain's edges, at once).

One incremental grid, not a bounded one beside it: an unbounded grid needs no extent in
advance (grow's is unknown until it stops; a bounded grid would pile far items into its
border cells) and a pose or wrapped image beyond the domain costs nothing more; for
pack and ornament, which know their extent, a table of about one chain per cell of it
keeps the cost of the hash and the cell test per entry small (pack's fill-gap CPU 1.02x
of the bounded grid's, ``python benchmarks/pack_field_scanline.py --base WT --repeat 5``).

Usage from a compiled loop (the pattern of ``strew.pack._predicates._collides``; items
that never move are all current, so no ``cur`` test)::

    cx0, cy0, cx1, cy1 = hash_span(xmin, ymin, xmax, ymax, cell, ext)
    mask = head.shape[0] - 1
    for cx in range(cx0, cx1 + 1):
        for cy in range(cy0, cy1 + 1):
            e = head[((cx * HASH_X) ^ (cy * HASH_Y)) & mask]
            while e >= 0:
                item = ent[e, 0]
                hit = ent[e, 1] == cx and ent[e, 2] == cy and stamp[item] != qid
                e = ent[e, 3]
                if not hit:
                    continue  # another cell of the chain, or an item already seen
                stamp[item] = qid
                ...  # exact test against item
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .geometry import seg_cross

__all__ = ["bucket_grid", "HASH_X", "HASH_Y", "GONE", "hash_span", "hash_near", "hash_cross", "hash_query_box",
           "hash_insert_box", "hash_segments", "HashGrid"]


@numba.njit(cache=True, nogil=True)
def _col_range(pts, c):  # pragma: no cover - numba
    """``pts[:, c].min(), pts[:, c].max()`` of a non-empty (n, k) array, as one loop (NaN
    if the column holds one, as numpy; array reductions compile slowly, issue 16)."""
    lo = pts[0, c]
    hi = lo
    for i in range(pts.shape[0]):
        v = pts[i, c]
        if np.isnan(v):
            return v, v
        if v < lo:
            lo = v
        if v > hi:
            hi = v
    return lo, hi


@numba.njit(cache=True, nogil=True)
def bucket_grid(pts, cell, queries, reverse):  # pragma: no cover - numba
    """Uniform grid over ``pts`` with linked buckets: ``(x0, y0, cell, nx, ny, head, nxt)``.

    Parameters
    ----------
    pts : (n, 2) float, n >= 1
    cell : float
        The wished cell side; it grows when the grid would hold far more cells than
        points and ``queries`` (computed in floats, so a tiny cell over a wide spread
        cannot overflow).
    queries : int64
        How many queries will follow (sizes the grid with the points).
    reverse : bool
        Each bucket lists its points in decreasing index order, or increasing with
        ``reverse``.

    Returns
    -------
    x0, y0, cell : float
    nx, ny : int
    head : (nx * ny,) int64
        First point of cell ``i * ny + j`` (-1: empty).
    nxt : (n,) int64
        Next point of the same cell (-1: end).

    Compiled callers pass ``np.int64(0)`` and ``np.bool_(...)``, never literal constants:
    numba compiles one specialisation per literal value (issue 16).
    """
    n = pts.shape[0]
    x0, x1 = _col_range(pts, 0)
    y0, y1 = _col_range(pts, 1)
    w = x1 - x0
    h = y1 - y0
    cell = max(cell, 1e-12)
    if (w / cell + 1.0) * (h / cell + 1.0) > 4.0 * (n + queries) + 1024.0:
        cell = max(w, h) / np.sqrt(4.0 * (n + queries)) + cell
    nx = int(w / cell) + 1
    ny = int(h / cell) + 1
    head = np.full(nx * ny, -1, np.int64)
    nxt = np.full(n, -1, np.int64)
    for t in range(n):
        j = n - 1 - t if reverse else t
        g = int((pts[j, 0] - x0) / cell) * ny + int((pts[j, 1] - y0) / cell)
        nxt[j] = head[g]
        head[g] = j
    return x0, y0, cell, nx, ny, head, nxt


# -- the hashed grid ----------------------------------------------------------------------

HASH_X = 73856093
HASH_Y = 19349663
GONE = np.iinfo(np.int64).max  # ``cur`` of an item not in a hashed grid


@numba.njit(cache=True, nogil=True)
def hash_span(xmin, ymin, xmax, ymax, h, ext):  # pragma: no cover - numba
    """Cells ``(cx0, cy0, cx1, cy1)`` of a hashed grid of side ``h`` that the box
    touches, clipped to ``ext`` (the cells any entry was made in)."""
    # (comparisons, not min/max: each builtin is one more function to compile)
    cx0 = math.floor(xmin / h)
    cy0 = math.floor(ymin / h)
    cx1 = math.floor(xmax / h)
    cy1 = math.floor(ymax / h)
    if cx0 < ext[0]:
        cx0 = ext[0]
    if cy0 < ext[1]:
        cy0 = ext[1]
    if cx1 > ext[2]:
        cx1 = ext[2]
    if cy1 > ext[3]:
        cy1 = ext[3]
    return cx0, cy0, cx1, cy1


@numba.njit(cache=True, nogil=True)
def hash_near(xs, ys, rs, classes, limit, h, head, ent, cur, ext, pos, cls, out_q, out_i):  # pragma: no cover - numba
    """Point items of a hashed grid within ``rs[q]`` of ``(xs[q], ys[q])`` whose class bit
    is set in ``classes`` (``(classes >> cls[i]) & 1``), for each query q in turn, at most
    ``limit`` each, in cell order (x-major) and creation order within a cell: the pairs
    (q, item) in ``out_q, out_i``; their count, or -1 when those are too short (the
    caller grows them and asks again). ``pos`` (items, 2) holds the items' positions.
    The cells walked are clipped to ``ext``, the cells any entry was made in."""
    mask = head.shape[0] - 1
    k = 0
    cap = out_q.shape[0]
    for q in range(xs.shape[0]):
        x = xs[q]
        y = ys[q]
        r = rs[q]
        r2 = r * r
        found = 0
        cx0, cy0, cx1, cy1 = hash_span(x - r, y - r, x + r, y + r, h, ext)
        for cx in range(cx0, cx1 + 1):
            for cy in range(cy0, cy1 + 1):
                e = head[((cx * HASH_X) ^ (cy * HASH_Y)) & mask]
                while e >= 0 and found < limit:
                    if ent[e, 1] == cx and ent[e, 2] == cy:
                        i = ent[e, 0]
                        if e >= cur[i]:
                            dx = pos[i, 0] - x
                            dy = pos[i, 1] - y
                            if dx * dx + dy * dy <= r2 and ((classes >> cls[i]) & 1) != 0:
                                if k >= cap:
                                    return -1
                                out_q[k] = q
                                out_i[k] = i
                                k += 1
                                found += 1
                    e = ent[e, 3]
    return k


@numba.njit(cache=True, nogil=True)
def hash_cross(px, py, qx, qy, ta, tb, h, head, ent, cur, ext, ends, pos):  # pragma: no cover - numba
    """Does segment pq cross, at a point interior to both (:func:`~strew._kernels.geometry.seg_cross`),
    a segment item of a hashed grid? Item ``d`` is the segment ``pos[ends[d, 0]]`` -
    ``pos[ends[d, 1]]`` tagged ``ends[d, 2]``, ``ends[d, 3]``; items with a tag equal to
    ``ta`` or ``tb`` are skipped. Walks the cells of pq's box (clipped to ``ext``)."""
    mask = head.shape[0] - 1
    lx, hx = (px, qx) if px <= qx else (qx, px)
    ly, hy = (py, qy) if py <= qy else (qy, py)
    cx0, cy0, cx1, cy1 = hash_span(lx, ly, hx, hy, h, ext)
    for cx in range(cx0, cx1 + 1):
        for cy in range(cy0, cy1 + 1):
            e = head[((cx * HASH_X) ^ (cy * HASH_Y)) & mask]
            while e >= 0:
                if ent[e, 1] == cx and ent[e, 2] == cy:
                    d = ent[e, 0]
                    ou = ends[d, 2]
                    ov = ends[d, 3]
                    if e >= cur[d] and ou != ta and ou != tb and ov != ta and ov != tb:
                        u = ends[d, 0]
                        v = ends[d, 1]
                        if seg_cross(px, py, qx, qy, pos[u, 0], pos[u, 1], pos[v, 0], pos[v, 1]):
                            return True
                e = ent[e, 3]
    return False


@numba.njit(cache=True, nogil=True)
def hash_query_box(h, head, ent, cur, ext, xmin, ymin, xmax, ymax, stamp, qid, out):  # pragma: no cover - numba
    """Items of a hashed grid currently listed in the cells that a box touches, each
    once (``stamp[item]`` is set to ``qid``, which must be new), in cell order (x-major)
    and creation order within a cell, written to ``out``; returns their number (a
    superset of the items whose boxes meet the box). ``out`` must have room for every
    item."""
    mask = head.shape[0] - 1
    cx0, cy0, cx1, cy1 = hash_span(xmin, ymin, xmax, ymax, h, ext)
    m = 0
    for cx in range(cx0, cx1 + 1):
        for cy in range(cy0, cy1 + 1):
            e = head[((cx * HASH_X) ^ (cy * HASH_Y)) & mask]
            while e >= 0:
                if ent[e, 1] == cx and ent[e, 2] == cy:
                    it = ent[e, 0]
                    if e >= cur[it] and stamp[it] != qid:
                        stamp[it] = qid
                        out[m] = it
                        m += 1
                e = ent[e, 3]
    return m


@numba.njit(cache=True, nogil=True)
def hash_insert_box(h, head, tail, ent, ext, ne, item, xmin, ymin, xmax, ymax):  # pragma: no cover - numba
    """:meth:`HashGrid.insert` from compiled code, for a grid whose items never move
    (pack's placed regions): list ``item`` in every cell of side ``h`` that its box
    touches, at its chain's tail, writing entries from ``ne`` on, and widen ``ext``;
    returns the new entry count. ``ent`` must have room for the box's cells (at most
    9 for a box no wider than two cells); the table is not grown."""
    cx0 = math.floor(xmin / h)
    cy0 = math.floor(ymin / h)
    cx1 = math.floor(xmax / h)
    cy1 = math.floor(ymax / h)
    if ext[0] > ext[2]:
        ext[0] = cx0
        ext[1] = cy0
        ext[2] = cx1
        ext[3] = cy1
    else:
        if cx0 < ext[0]:
            ext[0] = cx0
        if cy0 < ext[1]:
            ext[1] = cy0
        if cx1 > ext[2]:
            ext[2] = cx1
        if cy1 > ext[3]:
            ext[3] = cy1
    mask = head.shape[0] - 1
    for cx in range(cx0, cx1 + 1):
        for cy in range(cy0, cy1 + 1):
            hh = ((cx * HASH_X) ^ (cy * HASH_Y)) & mask
            ent[ne, 0] = item
            ent[ne, 1] = cx
            ent[ne, 2] = cy
            ent[ne, 3] = -1
            t = tail[hh]
            if t >= 0:
                ent[t, 3] = ne
            else:
                head[hh] = ne
            tail[hh] = ne
            ne += 1
    return ne


@numba.njit(cache=True, nogil=True)
def hash_segments(segs, h, table):  # pragma: no cover - numba
    """A hashed grid of cell side ``h`` and ``table`` chains (a power of two) built at
    once for fixed segments (s, 4) ``ax, ay, bx, by``, each listed by its box
    (:func:`hash_insert_box`, item = segment index): ``head`` (table,), ``ent`` (m, 4)
    and ``ext`` (4,) int64, as :class:`HashGrid` holds them (no segment ever moves)."""
    n = 0
    for s in range(len(segs)):
        n += ((math.floor(max(segs[s, 0], segs[s, 2]) / h) - math.floor(min(segs[s, 0], segs[s, 2]) / h) + 1)
              * (math.floor(max(segs[s, 1], segs[s, 3]) / h) - math.floor(min(segs[s, 1], segs[s, 3]) / h) + 1))
    head = np.full(table, -1, np.int64)
    tail = np.full(table, -1, np.int64)
    ent = np.full((max(n, 1), 4), -1, np.int64)
    ext = np.zeros(4, np.int64)
    ext[2] = -1
    ext[3] = -1
    e = 0
    for s in range(len(segs)):
        e = hash_insert_box(h, head, tail, ent, ext, e, s, min(segs[s, 0], segs[s, 2]), min(segs[s, 1], segs[s, 3]),
                            max(segs[s, 0], segs[s, 2]), max(segs[s, 1], segs[s, 3]))
    return head, ent, ext


class HashGrid:
    """The hashed incremental grid: unbounded square cells of side ``cell``, hashed into
    a table of chains, holding items (ints >= 0) listed by point or by box.

    Parameters
    ----------
    cell : float
        Side of the cells (cell ``(cx, cy)`` covers ``[cx * cell, (cx + 1) * cell)`` in x).
    items : int
        Room for items ``0 .. items - 1`` to begin with (more is made as needed).
    table : int
        The least number of chains (a power of two); the table grows with the entries.

    Attributes
    ----------
    head, tail : (table,) int64
        First and last entry of each chain (-1: empty); ``table`` is a power of two and
        cell ``(cx, cy)`` is in chain ``((cx * HASH_X) ^ (cy * HASH_Y)) & (table - 1)``
        (int64 arithmetic, wrapping).
    ent : (capacity, 4) int64
        The entries (the first ``n`` in use): item, cell x, cell y, next entry of the
        same chain (-1: last). A chain links its entries in the order they were made,
        so the entries of one cell are met in creation order.
    cur : (items,) int64
        First entry of each item's current listing, :data:`GONE` when it is not in the
        grid. An item's listing is made in one go and a later one has larger entries, so
        entry ``e`` of item ``i`` is current exactly when ``e >= cur[i]``: moving an item
        lists it anew and leaves the old entries stale, removing it sets ``GONE``;
        :meth:`rebuild` drops stale entries (keeping the order), and runs by itself when
        the entries outnumber the chains twice.
    ext : (4,) int64
        ``(cx0, cy0, cx1, cy1)``, the cells any entry was made in (empty: ``0, 0, -1,
        -1``); queries walk no cell outside, so a query far wider than the contents costs
        no more than the contents.
    live : int
        How many items are in the grid.

    Compiled queries: :func:`hash_near` (point items within a radius), :func:`hash_cross`
    (segment items crossed), :func:`hash_query_box` (items listed in a box's cells; from
    Python :meth:`query`). Listing from Python stays in Python (a box covers one to four
    cells, and a kernel call costs about as much); compiled code whose items never move
    lists with :func:`hash_insert_box`, which makes the same entries (with no ``cur``
    and no automatic rebuild).
    """

    def __init__(self, cell: float, items: int = 1024, table: int = 1024) -> None:
        if table < 1 or table & (table - 1):
            raise ValueError(f"table must be a power of two, not {table}")
        self.cell = float(cell)
        self.table = table
        self.head = np.full(table, -1, dtype=np.int64)
        self.tail = np.full(table, -1, dtype=np.int64)
        self.ent = np.full((1024, 4), -1, dtype=np.int64)
        self.n = 0
        self.cur = np.full(max(int(items), 1), GONE, dtype=np.int64)
        self.ext = np.array([0, 0, -1, -1], dtype=np.int64)
        self._ext: list[int] | None = None
        self.live = 0
        self._stamp = np.zeros(0, dtype=np.int64)
        self._qid = 0

    def reserve(self, items: int) -> None:
        """Room for items ``0 .. items - 1``."""
        if items > len(self.cur):
            cur = np.full(max(items, 2 * len(self.cur)), GONE, dtype=np.int64)
            cur[: len(self.cur)] = self.cur
            self.cur = cur

    def __contains__(self, item: int) -> bool:
        return 0 <= item < len(self.cur) and self.cur[item] != GONE

    def insert(self, item: int, xmin: float, ymin: float, xmax: float, ymax: float) -> None:
        """List ``item`` in every cell its box (xmin <= xmax, ymin <= ymax) touches, as
        its current listing (an earlier one becomes stale)."""
        if self.n >= 2 * len(self.head):
            self.rebuild()
        h = self.cell
        cx0, cx1 = math.floor(xmin / h), math.floor(xmax / h)
        cy0, cy1 = math.floor(ymin / h), math.floor(ymax / h)
        ext = self._ext
        if ext is None:
            self._ext = ext = [cx0, cy0, cx1, cy1]
            self.ext[:] = ext
        elif cx0 < ext[0] or cy0 < ext[1] or cx1 > ext[2] or cy1 > ext[3]:
            ext[:] = [min(cx0, ext[0]), min(cy0, ext[1]), max(cx1, ext[2]), max(cy1, ext[3])]
            self.ext[:] = ext
        first = e = self.n
        need = e + (cx1 - cx0 + 1) * (cy1 - cy0 + 1)
        ent = self.ent
        if need > len(ent):
            ent = np.full((2 * need, 4), -1, dtype=np.int64)
            ent[:e] = self.ent[:e]
            self.ent = ent
        if need - e > 1:
            # (the cells' entries in one compiled call, as the loop below writes them;
            # ``ext`` already holds the box, so the kernel's widening is a no-op: issue
            # 14 point 5, the grower lists every new and moved edge here)
            e = hash_insert_box(h, self.head, self.tail, ent, self.ext, e, item, float(xmin), float(ymin), float(xmax), float(ymax))
        else:
            head, tail = self.head, self.tail
            hh = ((cx0 * HASH_X) ^ (cy0 * HASH_Y)) & (len(head) - 1)
            ent[e] = (item, cx0, cy0, -1)
            t = tail[hh]
            if t >= 0:
                ent[t, 3] = e
            else:
                head[hh] = e
            tail[hh] = e
            e += 1
        self.n = e
        if item >= len(self.cur):
            self.reserve(item + 1)
        if self.cur[item] == GONE:
            self.live += 1
        self.cur[item] = first

    def insert_point(self, item: int, x: float, y: float) -> None:
        """:meth:`insert` of the point (x, y): one cell (the growth's hot path, so written out)."""
        if self.n >= 2 * len(self.head):
            self.rebuild()
        h = self.cell
        cx, cy = math.floor(x / h), math.floor(y / h)
        ext = self._ext
        if ext is None:
            self._ext = ext = [cx, cy, cx, cy]
            self.ext[:] = ext
        elif cx < ext[0] or cy < ext[1] or cx > ext[2] or cy > ext[3]:
            ext[:] = [min(cx, ext[0]), min(cy, ext[1]), max(cx, ext[2]), max(cy, ext[3])]
            self.ext[:] = ext
        e = self.n
        ent = self.ent
        if e >= len(ent):
            ent = np.full((2 * len(ent), 4), -1, dtype=np.int64)
            ent[:e] = self.ent[:e]
            self.ent = ent
        hh = ((cx * HASH_X) ^ (cy * HASH_Y)) & (len(self.head) - 1)
        ent[e] = (item, cx, cy, -1)
        t = self.tail[hh]
        if t >= 0:
            ent[t, 3] = e
        else:
            self.head[hh] = e
        self.tail[hh] = e
        self.n = e + 1
        cur = self.cur
        if item >= len(cur):
            self.reserve(item + 1)
            cur = self.cur
        if cur[item] == GONE:
            self.live += 1
        cur[item] = e

    def remove(self, item: int) -> None:
        """``item`` leaves the grid (its entries turn stale); no-op when not in it."""
        if item < len(self.cur) and self.cur[item] != GONE:
            self.cur[item] = GONE
            self.live -= 1

    def rebuild(self) -> None:
        """Drop the stale entries, keeping the others in order, in a table of more chains
        than entries kept (a power of two, ``table`` at least)."""
        n = self.n
        items = self.ent[:n, 0]
        keep = np.arange(n) >= self.cur[items]
        old = np.flatnonzero(keep)
        m = len(old)
        table = max(self.table, 1 << int(max(m, 1)).bit_length())
        cap = max(1024, 1 << int(2 * m - 1).bit_length()) if m else 1024
        ent = np.full((cap, 4), -1, dtype=np.int64)
        ent[:m, :3] = self.ent[old, :3]
        self.n = m
        hh = ((ent[:m, 1] * HASH_X) ^ (ent[:m, 2] * HASH_Y)) & (table - 1)
        order = np.argsort(hh, kind="stable")
        hs = hh[order]
        same = hs[1:] == hs[:-1]
        ent[order[:-1][same], 3] = order[1:][same]
        self.ent = ent
        self.head = np.full(table, -1, dtype=np.int64)
        self.tail = np.full(table, -1, dtype=np.int64)
        if m:
            first = np.r_[True, ~same]
            last = np.r_[~same, True]
            self.head[hs[first]] = order[first]
            self.tail[hs[last]] = order[last]
            # each item's current listing starts at its first kept entry
            items, at = np.unique(ent[:m, 0], return_index=True)
            self.cur[items] = at

    def query(self, xmin: float, ymin: float, xmax: float, ymax: float) -> np.ndarray:
        """Items listed in the cells a box touches, each once, in cell order (x-major)
        and creation order within a cell (:func:`hash_query_box`): a superset of the
        items whose boxes meet it."""
        if len(self._stamp) < len(self.cur):
            self._stamp = np.zeros(len(self.cur), dtype=np.int64)
        self._qid += 1
        out = np.empty(len(self.cur), dtype=np.int64)
        m = hash_query_box(self.cell, self.head, self.ent, self.cur, self.ext, float(xmin), float(ymin), float(xmax), float(ymax), self._stamp, self._qid, out)
        return out[:m]

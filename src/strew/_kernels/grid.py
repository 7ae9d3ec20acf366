"""The shared spatial grids (issue 15 point 5): a bucket grid over points, built once,
and an incremental grid of boxes, filled as elements are placed.

Both are uniform grids of square cells held as linked lists in flat int64 arrays, so
compiled loops walk them with no allocation:

* **bucket grid** over points (:func:`bucket_grid`): ``head`` (nx * ny,) holds the first
  point of each cell (-1: empty), ``nxt`` (n,) the next point of the same cell. Cell of
  a point: ``int((x - x0) / cell) * ny + int((y - y0) / cell)``. Points near ``(x, y)``
  within ``reach`` are those of the cells ``int((x - reach - x0) / cell)`` ..
  ``int((x + reach - x0) / cell)`` (clamped to ``0 .. nx - 1``), likewise in y.
* **incremental grid** of boxes, described by ``g = (x0, y0, cell, cols, rows)`` (5,)
  float: ``head`` (cols * rows,) int64, the first entry of each cell (-1: empty);
  entries ``enext`` (m,) int64 (the next entry of the same cell, -1: end) and
  ``eitem`` (m,) int64 (the item the entry lists). :func:`insert_box` adds an item to
  every cell its box touches (:func:`cell_span`, clamped to the grid, so boxes beyond
  the grid's extent land in its border cells and are still found); a query walks the
  cells of its own box and skips items already seen by a stamp array (``stamp[item] ==
  qid``), since an item that spans several cells is listed in each. Cell ``(c, q)`` is
  ``head[q * cols + c]``. :func:`grid_segments` builds the same structure at once for
  the boxes of fixed segments (a domain's edges).

Usage from a compiled loop (the pattern of ``strew.pack._predicates.collides``)::

    c0, c1, q0, q1 = cell_span(g[0], g[1], g[2], int(g[3]), int(g[4]), xmin, ymin, xmax, ymax)
    for q in range(q0, q1 + 1):
        for c in range(c0, c1 + 1):
            e = head[q * int(g[3]) + c]
            while e >= 0:
                item = eitem[e]
                e = enext[e]
                if stamp[item] == qid:
                    continue
                stamp[item] = qid
                ...  # exact test against item
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["cell_span", "insert_box", "grid_segments", "query_box", "bucket_grid", "BoxGrid"]


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def cell_span(gx0, gy0, gc, cols, rows, xmin, ymin, xmax, ymax):  # pragma: no cover - numba
    """Grid cells ``(c0, c1, q0, q1)`` (inclusive) that a box touches, each end clamped
    to the grid: a box beyond the grid's extent maps to its border cells, so a box and
    a query that meet always share a cell."""
    c0 = min(max(int((xmin - gx0) / gc), 0), cols - 1)
    c1 = max(min(int((xmax - gx0) / gc), cols - 1), 0)
    q0 = min(max(int((ymin - gy0) / gc), 0), rows - 1)
    q1 = max(min(int((ymax - gy0) / gc), rows - 1), 0)
    return c0, c1, q0, q1


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def insert_box(g, head, enext, eitem, ne, item, xmin, ymin, xmax, ymax):  # pragma: no cover - numba
    """List ``item`` in every cell of the incremental grid ``g`` that its box touches,
    writing entries from ``ne`` on; returns the new entry count. ``enext`` and ``eitem``
    must have room for the box's cells (at most 9 for a box no wider than a cell)."""
    cols = int(g[3])
    c0, c1, q0, q1 = cell_span(g[0], g[1], g[2], cols, int(g[4]), xmin, ymin, xmax, ymax)
    for q in range(q0, q1 + 1):
        for c in range(c0, c1 + 1):
            cell = q * cols + c
            enext[ne] = head[cell]
            eitem[ne] = item
            head[cell] = ne
            ne += 1
    return ne


@numba.njit(cache=True)
def query_box(g, head, enext, eitem, stamp, qid, xmin, ymin, xmax, ymax, out):  # pragma: no cover - numba
    """Items of the incremental grid ``g`` listed in the cells that a box touches, each
    once (``stamp`` (items,) int64 is set to ``qid``, which must be new), written to
    ``out``; returns their number (a superset of the items whose boxes meet the box:
    the caller tests them exactly). ``out`` must have room for every item."""
    cols = int(g[3])
    c0, c1, q0, q1 = cell_span(g[0], g[1], g[2], cols, int(g[4]), xmin, ymin, xmax, ymax)
    m = 0
    for q in range(q0, q1 + 1):
        for c in range(c0, c1 + 1):
            e = head[q * cols + c]
            while e >= 0:
                it = eitem[e]
                e = enext[e]
                if stamp[it] == qid:
                    continue
                stamp[it] = qid
                out[m] = it
                m += 1
    return m


@numba.njit(cache=True)
def grid_segments(segs, gx0, gy0, gc, cols, rows):  # pragma: no cover - numba
    """The incremental grid's lists, built at once for fixed segments (s, 4) ``ax, ay,
    bx, by`` (each listed in the cells its box touches): ``head`` (rows * cols,),
    ``enext`` and ``eitem`` (entries,) int64, ``eitem`` holding segment indices."""
    n = 0
    for s in range(len(segs)):
        c0, c1, q0, q1 = cell_span(gx0, gy0, gc, cols, rows, min(segs[s, 0], segs[s, 2]), min(segs[s, 1], segs[s, 3]), max(segs[s, 0], segs[s, 2]), max(segs[s, 1], segs[s, 3]))
        n += max(c1 - c0 + 1, 0) * max(q1 - q0 + 1, 0)
    head = np.empty(rows * cols, dtype=np.int64)
    for i in range(rows * cols):
        head[i] = -1
    nxt = np.empty(n, dtype=np.int64)
    sid = np.empty(n, dtype=np.int64)
    e = 0
    for s in range(len(segs)):
        c0, c1, q0, q1 = cell_span(gx0, gy0, gc, cols, rows, min(segs[s, 0], segs[s, 2]), min(segs[s, 1], segs[s, 3]), max(segs[s, 0], segs[s, 2]), max(segs[s, 1], segs[s, 3]))
        for q in range(q0, q1 + 1):
            for c in range(c0, c1 + 1):
                nxt[e] = head[q * cols + c]
                sid[e] = s
                head[q * cols + c] = e
                e += 1
    return head, nxt, sid


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


class BoxGrid:
    """The incremental grid for Python callers: boxes inserted one at a time, queries
    answered by the compiled :func:`query_box`.

    Parameters
    ----------
    bounds : (x0, y0, x1, y1)
        The extent the grid covers; boxes beyond it land in its border cells (still
        found, at the cost of a longer walk there).
    cell : float
        The wished cell side; it grows until the grid holds at most ``max_cells`` cells.

    Attributes
    ----------
    g : (5,) float
        ``(x0, y0, cell, cols, rows)``, as the compiled kernels take it.
    head : (cols * rows,) int64
    enext, eitem : (capacity,) int64
        The entries (the first ``ne`` are in use).
    """

    def __init__(self, bounds: tuple[float, float, float, float], cell: float, max_cells: int = 1 << 20) -> None:
        x0, y0, x1, y1 = (float(v) for v in bounds)
        cell = float(cell)
        w, h = max(x1 - x0, cell), max(y1 - y0, cell)
        if (w / cell + 1) * (h / cell + 1) > max_cells:
            cell = max(cell, float(np.sqrt(w * h / max_cells)) * 1.01)
        self.cols = int(w / cell) + 1
        self.rows = int(h / cell) + 1
        self.x0, self.y0, self.cell = x0, y0, cell
        self.g = np.array([x0, y0, cell, self.cols, self.rows], dtype=float)
        self.head = np.full(self.cols * self.rows, -1, dtype=np.int64)
        self.enext = np.empty(1024, dtype=np.int64)
        self.eitem = np.empty(1024, dtype=np.int64)
        self.ne = 0
        self.stamp = np.full(256, -1, dtype=np.int64)
        self.out = np.empty(256, dtype=np.int64)
        self.qid = 0

    def span(self, xmin: float, ymin: float, xmax: float, ymax: float) -> tuple[int, int, int, int]:
        """:func:`cell_span` in Python: cells ``(c0, c1, q0, q1)``, inclusive, clamped."""
        x0, y0, c, cols, rows = self.x0, self.y0, self.cell, self.cols, self.rows
        return (min(max(int((xmin - x0) / c), 0), cols - 1), max(min(int((xmax - x0) / c), cols - 1), 0),
                min(max(int((ymin - y0) / c), 0), rows - 1), max(min(int((ymax - y0) / c), rows - 1), 0))

    def insert(self, item: int, xmin: float, ymin: float, xmax: float, ymax: float) -> None:
        """List ``item`` (an int >= 0) in the cells its box touches (:func:`insert_box`)."""
        c0, c1, q0, q1 = self.span(xmin, ymin, xmax, ymax)
        need = self.ne + (c1 - c0 + 1) * (q1 - q0 + 1)
        if need > len(self.enext):
            size = max(2 * len(self.enext), need)
            for name in ("enext", "eitem"):
                a = getattr(self, name)
                b = np.empty(size, dtype=np.int64)
                b[: self.ne] = a[: self.ne]
                setattr(self, name, b)
        if item >= len(self.stamp):
            size = max(2 * len(self.stamp), item + 1)
            self.stamp = np.concatenate([self.stamp, np.full(size - len(self.stamp), -1, dtype=np.int64)])
            self.out = np.empty(size, dtype=np.int64)
        head, enext, eitem, ne, cols = self.head, self.enext, self.eitem, self.ne, self.cols
        for q in range(q0, q1 + 1):
            for c in range(c0, c1 + 1):
                cell = q * cols + c
                enext[ne] = head[cell]
                eitem[ne] = item
                head[cell] = ne
                ne += 1
        self.ne = ne

    def query(self, xmin: float, ymin: float, xmax: float, ymax: float) -> np.ndarray:
        """Items listed in the cells a box touches, each once, in no particular order
        (a view, valid until the next call): a superset of the items whose boxes meet it."""
        self.qid += 1
        m = query_box(self.g, self.head, self.enext, self.eitem, self.stamp, self.qid, xmin, ymin, xmax, ymax, self.out)
        return self.out[:m]

"""Compiled listing of a growth's edge in its edge grid (issue 14 point 5).

``GrowIndex._index_edge`` lists every new edge, and every edge of a point that moves to
another cell, in the cells its bounding box covers: some 11,600 listings in a growth of
2,000 stones, each through :meth:`strew._kernels.grid.HashGrid.insert`'s Python (the
box's cells, the extent, the chains). :func:`edge_insert` does the same in one call, with
:func:`strew._kernels.grid.hash_insert_box` writing the entries as ``insert`` has them
written; the caller keeps the grid's Python fields in step and takes ``insert`` when the
table is due a rebuild or the entries would not fit.

:func:`near_one` is :func:`strew._kernels.grid.hash_near` for one query given as
scalars (``GrowIndex.near``): the grower asks single queries for every element placed
(Fig. 6 (b), the overlap guard, the closeness rules; 3,512 in the flow growth of
``benchmarks/grow.py --against``'s hexflow, some 28,000 in a growth of 2,000 stones),
and numba's call costs about a quarter of a microsecond per array argument; the
batched kernel's query and output arrays (four of its fourteen arguments) and the
three writes that filled them were a third of each call (h/spd14w's cb7c585, ported).
Both kernels are reached by the warm-up's 'grow' case.
"""

from __future__ import annotations

import math

import numba

from .._kernels.grid import GONE, HASH_X, HASH_Y, hash_cross, hash_insert_box, hash_span


@numba.njit(cache=True, nogil=True)
def edge_insert(h, head, tail, ent, ext, ne, cur, item, pos, a, b):  # pragma: no cover - numba
    """List ``item``, the edge from point ``a`` to point ``b`` of ``pos``, in every cell of
    side ``h`` its box touches, as ``HashGrid.insert(item, min x, min y, max x, max y)``
    lists it (entries from ``ne`` on, ``ext`` widened, ``cur[item]``).

    Returns ``(entries, widened, new)``: the new entry count (-1 when ``ent`` has no room
    for the box's cells: nothing is written), whether ``ext`` grew, and whether the item
    was not listed before (``cur`` was GONE)."""
    xa = pos[a, 0]
    ya = pos[a, 1]
    xb = pos[b, 0]
    yb = pos[b, 1]
    # (comparisons, not min/max: each builtin is one more function to compile)
    xmin = xa if xa <= xb else xb  # noqa: FURB136
    xmax = xb if xa <= xb else xa  # noqa: FURB136
    ymin = ya if ya <= yb else yb  # noqa: FURB136
    ymax = yb if ya <= yb else ya  # noqa: FURB136
    cx0 = math.floor(xmin / h)
    cy0 = math.floor(ymin / h)
    cx1 = math.floor(xmax / h)
    cy1 = math.floor(ymax / h)
    if ne + (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > ent.shape[0]:
        return -1, False, False
    widened = ext[0] > ext[2] or cx0 < ext[0] or cy0 < ext[1] or cx1 > ext[2] or cy1 > ext[3]
    n = hash_insert_box(h, head, tail, ent, ext, ne, item, xmin, ymin, xmax, ymax)
    new = cur[item] == GONE
    cur[item] = ne
    return n, widened, new


@numba.njit(cache=True, nogil=True)
def near_one(x, y, r, classes, limit, h, head, ent, cur, ext, pos, cls, out_i):  # pragma: no cover - numba
    """Point items of a hashed grid within ``r`` of ``(x, y)`` whose class bit is set in
    ``classes``, at most ``limit``, in the order :func:`~strew._kernels.grid.hash_near`
    gives them (cells x-major, creation order within a cell), written to ``out_i``
    (room for every item: each live item is listed once); returns their count."""
    mask = head.shape[0] - 1
    r2 = r * r
    found = 0
    # (a live item is listed once, so this never bites; but nothing is written beyond
    # out_i. A comparison, not min(): each builtin is one more function to compile)
    if limit > out_i.shape[0]:  # noqa: PLR1730
        limit = out_i.shape[0]
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
                            out_i[found] = i
                            found += 1
                e = ent[e, 3]
    return found


@numba.njit(cache=True, nogil=True)
def cross_any(px, py, qs, ta, tbs, h, head, ent, cur, ext, ends, pos):  # pragma: no cover - numba
    """Does any segment from (px, py) to ``qs[k]`` (tagged ``ta``, ``tbs[k]``) cross an
    edge of the grid (:func:`strew._kernels.grid.hash_cross` for each, in one call:
    ``GrowIndex.crosses_plane_any``; g70v, issue 14 point 5)?"""
    for k in range(qs.shape[0]):
        if hash_cross(px, py, qs[k, 0], qs[k, 1], ta, tbs[k], h, head, ent, cur, ext, ends, pos):
            return True
    return False

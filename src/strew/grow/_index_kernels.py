"""Compiled listing of a growth's edge in its edge grid (issue 14 point 5).

``GrowIndex._index_edge`` lists every new edge, and every edge of a point that moves to
another cell, in the cells its bounding box covers: some 11,600 listings in a growth of
2,000 stones, each through :meth:`strew._kernels.grid.HashGrid.insert`'s Python (the
box's cells, the extent, the chains). :func:`edge_insert` does the same in one call, with
:func:`strew._kernels.grid.hash_insert_box` writing the entries as ``insert`` has them
written; the caller keeps the grid's Python fields in step and takes ``insert`` when the
table is due a rebuild or the entries would not fit.
"""

from __future__ import annotations

import math

import numba

from .._kernels.grid import GONE, hash_insert_box


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

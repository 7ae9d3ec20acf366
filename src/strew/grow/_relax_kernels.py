"""Compiled loops of the grower's relaxation (Ijiri et al. 2008, §5.5; issue 14 point 5).

The normal equations of Eq. 5 for a small window (:func:`strew.grow._relax.relax_positions`'
dense path), assembled in one compiled loop instead of some twenty numpy calls on
arrays of a few hundred terms. The sums are made in the order numpy made them
(``np.bincount`` over the concatenated terms, then ``np.add.at`` term by term), so the
system, and the solve after it, are the same to the last bit.

Compiled with ``cache=True``; the warm-up (``python -m strew._warmup``, run by
``hatch_build.py``) reaches it through its "grow" cases.
"""

from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True)
def dense_normal_equations(pos, src, dst, off, w, free, reg):  # pragma: no cover - numba
    """The dense normal equations (nf, nf) and right-hand side (nf, 2) of the terms
    ``w[e] * || x_dst[e] - x_src[e] - off[e] ||^2`` over the free points (numbered in
    order), with the fixed points on the right-hand side and a pull of weight ``reg``
    towards each free point's position.

    Each entry is summed in the order of :func:`strew.grow._relax.relax_positions`'
    numpy assembly: the matrix as ``np.bincount`` sums the concatenation of the terms'
    (dst, dst), (src, src), (dst, src), (src, dst) entries and the pull, the right-hand
    side as its four ``np.add.at`` calls, each term in turn."""
    n = pos.shape[0]
    m = src.shape[0]
    col = np.full(n, -1, dtype=np.int64)
    nf = 0
    for i in range(n):
        if free[i]:
            col[i] = nf
            nf += 1
    N = np.zeros((nf, nf))
    b = np.empty((nf, 2))
    for i in range(n):
        if free[i]:
            b[col[i], 0] = reg * pos[i, 0]
            b[col[i], 1] = reg * pos[i, 1]
    # the matrix: the concatenation's blocks in turn (bincount: 0.0 + each in order)
    for e in range(m):
        d = dst[e]
        if free[d]:
            N[col[d], col[d]] += w[e]
    for e in range(m):
        s = src[e]
        if free[s]:
            N[col[s], col[s]] += w[e]
    for e in range(m):
        s = src[e]
        d = dst[e]
        if free[d] and free[s]:
            N[col[d], col[s]] += -w[e]
    for e in range(m):
        s = src[e]
        d = dst[e]
        if free[d] and free[s]:
            N[col[s], col[d]] += -w[e]
    for q in range(nf):
        N[q, q] += reg
    # the right-hand side: np.add.at's four calls in turn
    _rhs(pos, src, dst, off, w, free, col, b)
    return N, b


@numba.njit(cache=True)
def sparse_normal_equations(pos, src, dst, off, w, free, reg):  # pragma: no cover - numba
    """:func:`dense_normal_equations` for a sparse solve: the matrix's entries as the
    coordinate lists (rows, cols, vals) of the numpy assembly, in its order (the
    blocks (dst, dst), (src, src), (dst, src), (src, dst), then the pull), and the
    right-hand side (nf, 2), summed as there."""
    n = pos.shape[0]
    m = src.shape[0]
    col = np.full(n, -1, dtype=np.int64)
    nf = 0
    for i in range(n):
        if free[i]:
            col[i] = nf
            nf += 1
    k = 0
    for e in range(m):
        k += (1 if free[dst[e]] else 0) + (1 if free[src[e]] else 0) + (2 if free[dst[e]] and free[src[e]] else 0)
    rows = np.empty(k + nf, dtype=np.int64)
    cols = np.empty(k + nf, dtype=np.int64)
    vals = np.empty(k + nf)
    q = 0
    for e in range(m):
        d = dst[e]
        if free[d]:
            rows[q] = col[d]
            cols[q] = col[d]
            vals[q] = w[e]
            q += 1
    for e in range(m):
        s = src[e]
        if free[s]:
            rows[q] = col[s]
            cols[q] = col[s]
            vals[q] = w[e]
            q += 1
    for e in range(m):
        s = src[e]
        d = dst[e]
        if free[d] and free[s]:
            rows[q] = col[d]
            cols[q] = col[s]
            vals[q] = -w[e]
            q += 1
    for e in range(m):
        s = src[e]
        d = dst[e]
        if free[d] and free[s]:
            rows[q] = col[s]
            cols[q] = col[d]
            vals[q] = -w[e]
            q += 1
    for i in range(nf):
        rows[q] = i
        cols[q] = i
        vals[q] = reg
        q += 1
    b = np.empty((nf, 2))
    for i in range(n):
        if free[i]:
            b[col[i], 0] = reg * pos[i, 0]
            b[col[i], 1] = reg * pos[i, 1]
    _rhs(pos, src, dst, off, w, free, col, b)
    return rows, cols, vals, b


@numba.njit(cache=True)
def _rhs(pos, src, dst, off, w, free, col, b):  # pragma: no cover - numba
    """The right-hand side's four ``np.add.at`` calls of the numpy assembly, in turn."""
    m = src.shape[0]
    for e in range(m):
        d = dst[e]
        if free[d]:
            b[col[d], 0] += w[e] * off[e, 0]
            b[col[d], 1] += w[e] * off[e, 1]
    for e in range(m):
        s = src[e]
        d = dst[e]
        if free[d] and not free[s]:
            b[col[d], 0] += w[e] * pos[s, 0]
            b[col[d], 1] += w[e] * pos[s, 1]
    for e in range(m):
        s = src[e]
        if free[s]:
            b[col[s], 0] += -(w[e] * off[e, 0])
            b[col[s], 1] += -(w[e] * off[e, 1])
    for e in range(m):
        s = src[e]
        d = dst[e]
        if free[s] and not free[d]:
            b[col[s], 0] += w[e] * pos[d, 0]
            b[col[s], 1] += w[e] * pos[d, 1]

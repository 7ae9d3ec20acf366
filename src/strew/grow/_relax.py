"""Relaxation (Ijiri et al. 2008, §5.5).

Eq. 5 asks every element's ring to match its reference ring shape::

    min_x  sum_i sum_{j in w(x_i)} || x_j - (x_i + r_ji) ||^2

with some elements held at their positions (Eq. 6). The problem is a linear least
squares problem; we solve its normal equations in closed form with a sparse direct
solver. The paper handles Eq. 6 with Lagrange multipliers; eliminating the fixed
unknowns gives the same minimiser with a smaller, symmetric positive definite system.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import spsolve

__all__ = ["relax_positions"]

#: Up to this many free points the normal equations are solved as a dense system (below
#: the size at which OpenBLAS starts threads, which costs more than it saves here).
DENSE_MAX = 96


def relax_positions(
    positions: np.ndarray,
    src: np.ndarray,
    dst: np.ndarray,
    offsets: np.ndarray,
    free: np.ndarray,
    *,
    regularization: float = 1e-9,
    weights: np.ndarray | None = None,
) -> np.ndarray:
    """Least-squares fit of ring shapes (Eq. 5) with fixed elements (Eq. 6).

    Parameters
    ----------
    positions : (n, 2) float
        Current positions; fixed points keep theirs.
    src, dst : (m,) int
        Terms ``|| x_dst - (x_src + offset) ||^2``: ``src`` is the ring's centre ``x_i``,
        ``dst`` its neighbour ``x_j``.
    offsets : (m, 2) float
        The desired relative positions ``r_ji``.
    free : (n,) bool
        Unknowns; the others are constraints ``x_k = x_k^0`` (Eq. 6).
    regularization : float
        Weight of a tiny pull towards the current positions, so that a group of free
        points joined to no fixed one still has a unique minimiser (Eq. 5 alone is
        translation invariant).
    weights : (m,) float, optional
        A weight per term (Eq. 5 weighs all alike; :mod:`strew.grow._flow_holes` holds
        some pairs harder than others). None: all 1.

    Returns
    -------
    (n, 2) float
        The minimiser.

    Examples
    --------
    >>> pos = np.array([[0.0, 0.0], [3.0, 1.0]])
    >>> relax_positions(pos, np.array([0]), np.array([1]), np.array([[1.0, 0.0]]),
    ...                 np.array([False, True])).round(4).tolist()
    [[0.0, 0.0], [1.0, 0.0]]
    """
    pos = np.asarray(positions, dtype=float)
    free = np.asarray(free, dtype=bool)
    src = np.asarray(src, dtype=np.intp)
    dst = np.asarray(dst, dtype=np.intp)
    off = np.asarray(offsets, dtype=float).reshape(-1, 2)
    out = pos.copy()
    nf = int(free.sum())
    if nf == 0 or len(src) == 0:
        return out
    # Normal equations of the terms r = x_d - x_s - off, assembled directly (a graph
    # Laplacian over the free points); fixed points move to the right-hand side. One
    # compiled loop (:mod:`strew.grow._relax_kernels`) sums them in the order the numpy
    # assembly of 8224b5f did (np.bincount and np.add.at term by term): the same system
    # to the last bit, some twenty numpy calls fewer per window (issue 14 point 5).
    from ._relax_kernels import dense_normal_equations, sparse_normal_equations

    args = (np.ascontiguousarray(pos), np.ascontiguousarray(src), np.ascontiguousarray(dst), np.ascontiguousarray(off),
            np.ones(len(src)) if weights is None else np.ascontiguousarray(weights, dtype=float), np.ascontiguousarray(free), float(regularization))
    if nf <= DENSE_MAX:
        # small windows (the growth's windowed relaxation): a dense solve is far cheaper
        # than assembling a sparse matrix; the system is the same
        N, b = dense_normal_equations(*args)
        sol = np.linalg.solve(N, b)
    else:
        rows, cols, vals, b = sparse_normal_equations(*args)
        sol = spsolve(sp.csc_matrix((vals, (rows, cols)), shape=(nf, nf)), b)
    out[free] = np.asarray(sol).reshape(nf, 2)
    return out

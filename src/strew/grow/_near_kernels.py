"""Compiled neighbour counts and far-point tests of flow mode's measures (issue 14 point 5).

The passes after a flow growth (:mod:`strew.grow._flow_net`, ``_flow_shear``,
``_flow_retry``, ``_flow_densify``, ``_flow_regrow``) measure a lattice again and again:
how many elements lie within 0.85 and 1.15 spacings of each element (the six-site
test), and which points of a quarter-edge grid lie farther than some distance from every
element (the gaps). Each measure built a :class:`scipy.spatial.cKDTree` and queried it;
here a uniform grid of cells (built once per call, a counting sort) answers both in one
compiled call.

The answers are cKDTree's, to the last bit: a point ``p`` counts within ``r`` of ``q``
where ``dx * dx + dy * dy <= r * r`` (``dx = p - q`` per axis, summed in that order:
cKDTree's ``sqeuclidean_distance_double`` for two dimensions; ``query_ball_point``'s
leaf test ``d <= tub``), and :func:`far_from` repeats ``query``'s
``distance_upper_bound``: the nearest point counts only where its squared distance is
below ``r * r``, and its distance is then ``sqrt`` of that, compared with ``r``. The cells
only choose the candidates (their side is a little more than ``r``, so the 3 x 3 cells
about a query hold every point within ``r`` whatever the rounding of the cell index); the
test on each candidate is the one above. (cKDTree may skip the test for a whole node
whose farthest corner is nearer than ``r``; a point inside the node is then nearer too,
as its squared distance cannot round above the corner's but by a last-bit drift of the
node bounds, which the grow hashes would show: none did.)

Compiled with ``cache=True``; the warm-up's "grow flow region" case reaches them.
"""

from __future__ import annotations

import math

import numba
import numpy as np

__all__ = ["ball_counts", "far_from"]

# cell side over the radius: above 1, so that a point within r of a query lies in one of
# the nine cells about the query's, with room for the rounding of (x - x0) / h
_SIDE = 1.0 + 1e-6
# more cells than this many per point (a very sparse set): cKDTree instead
_MAX_CELLS_PER_POINT = 64


@numba.njit(cache=True)
def _near(px, py, qx, qy, r_hi, r_lo, h, far):  # pragma: no cover - numba
    """Over a uniform grid of side ``h`` (> r_hi) on the points (px, py): for each query
    (qx, qy), with ``far`` False the counts of points within ``r_hi`` and ``r_lo``
    (``ball_counts``), with ``far`` True (``r_hi``: the distance) 1 where it lies
    farther than ``r_hi`` from every point (``far_from``) and 0 where not (the second
    array then unused). (One kernel, the grid's build inlined: each compiled function
    costs a cold start some half a second.)"""
    n = px.shape[0]
    # the grid: origin, shape, each cell's first entry in ``order`` and the points by
    # cell (a counting sort; each cell's in index order)
    x0 = px[0]
    y0 = py[0]
    for i in range(1, n):
        if px[i] < x0:
            x0 = px[i]
        if py[i] < y0:
            y0 = py[i]
    cell = np.empty(n, dtype=np.int64)
    cy = np.empty(n, dtype=np.int64)
    nx = 1
    ny = 1
    for i in range(n):
        a = int(math.floor((px[i] - x0) / h))
        b = int(math.floor((py[i] - y0) / h))
        cell[i] = a
        cy[i] = b
        if a + 1 > nx:
            nx = a + 1
        if b + 1 > ny:
            ny = b + 1
    start = np.zeros(nx * ny + 1, dtype=np.int64)
    for i in range(n):
        cell[i] = cell[i] * ny + cy[i]
        start[cell[i] + 1] += 1
    for c in range(nx * ny):
        start[c + 1] += start[c]
    fill = start[:-1].copy()
    order = np.empty(n, dtype=np.int64)
    for i in range(n):
        order[fill[cell[i]]] = i
        fill[cell[i]] += 1
    m = qx.shape[0]
    hi = np.zeros(m, dtype=np.int64)
    lo = np.zeros(m, dtype=np.int64)
    t_hi = r_hi * r_hi
    t_lo = r_lo * r_lo
    for q in range(m):
        x = qx[q]
        y = qy[q]
        # the query's cell and the one each side per axis, clipped to the grid (none
        # where the query lies two cells or more outside it, or is NaN)
        tx = (x - x0) / h
        ty = (y - y0) / h
        if not (tx > -2.0 and ty > -2.0 and tx < nx + 1.0 and ty < ny + 1.0):
            if far:
                hi[q] = 1
            continue
        ix = int(math.floor(tx))
        iy = int(math.floor(ty))
        ax = ix - 1 if ix >= 1 else 0
        bx = ix + 1 if ix + 1 <= nx - 1 else nx - 1
        ay = iy - 1 if iy >= 1 else 0
        by = iy + 1 if iy + 1 <= ny - 1 else ny - 1
        k_hi = 0
        k_lo = 0
        best = np.inf
        for a in range(ax, bx + 1):
            for b in range(ay, by + 1):
                c = a * ny + b
                for e in range(start[c], start[c + 1]):
                    i = order[e]
                    dx = px[i] - x
                    dy = py[i] - y
                    d = dx * dx + dy * dy
                    if far:
                        if d < best:
                            best = d
                    else:
                        if d <= t_hi:
                            k_hi += 1
                        if d <= t_lo:
                            k_lo += 1
        if far:
            # query's test: a neighbour only below the squared bound; its distance the root
            hi[q] = 1 if (not (best < t_hi) or math.sqrt(best) > r_hi) else 0
        else:
            hi[q] = k_hi
            lo[q] = k_lo
    return hi, lo


def _columns(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    a = np.asarray(a, dtype=np.float64).reshape(-1, 2)
    return np.ascontiguousarray(a[:, 0]), np.ascontiguousarray(a[:, 1])


def _sparse(px: np.ndarray, py: np.ndarray, h: float) -> bool:
    """True where a grid of side ``h`` over the points would hold far more cells than
    points (or the extent is not finite): cKDTree answers instead."""
    w = (float(px.max()) - float(px.min())) / h + 1.0
    t = (float(py.max()) - float(py.min())) / h + 1.0
    return not (math.isfinite(w) and math.isfinite(t)) or w * t > _MAX_CELLS_PER_POINT * len(px) + 4096


def ball_counts(points: np.ndarray, queries: np.ndarray, r_hi: float, r_lo: float) -> tuple[np.ndarray, np.ndarray]:
    """How many of ``points`` lie within ``r_hi`` and within ``r_lo`` of each query.

    Parameters
    ----------
    points : (n, 2) float
    queries : (m, 2) float
    r_hi, r_lo : float
        The radii, positive; ``r_lo <= r_hi``.

    Returns
    -------
    hi, lo : (m,) int
        ``cKDTree(points).query_ball_point(queries, r, return_length=True)`` for each
        radius (a query at a point counts that point).
    """
    px, py = _columns(points)
    qx, qy = _columns(queries)
    r_hi, r_lo = float(r_hi), float(r_lo)
    if not len(qx):
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    if not len(px):
        z = np.zeros(len(qx), dtype=np.int64)
        return z, z.copy()
    h = _SIDE * max(r_hi, r_lo)
    if not (h > 0 and math.isfinite(h)) or _sparse(px, py, h):
        from scipy.spatial import cKDTree

        tree = cKDTree(np.c_[px, py])
        q = np.c_[qx, qy]
        return (np.asarray(tree.query_ball_point(q, r_hi, return_length=True), dtype=np.int64),
                np.asarray(tree.query_ball_point(q, r_lo, return_length=True), dtype=np.int64))
    return _near(px, py, qx, qy, r_hi, r_lo, h, False)


def far_from(points: np.ndarray, queries: np.ndarray, r: float) -> np.ndarray:
    """Which queries lie farther than ``r`` from every one of ``points``.

    Parameters
    ----------
    points : (n, 2) float
    queries : (m, 2) float
    r : float
        The distance, positive.

    Returns
    -------
    (m,) bool
        ``cKDTree(points).query(queries, distance_upper_bound=r)[0] > r``.
    """
    px, py = _columns(points)
    qx, qy = _columns(queries)
    r = float(r)
    if not len(qx):
        return np.zeros(0, dtype=bool)
    if not len(px):
        return np.ones(len(qx), dtype=bool)
    h = _SIDE * r
    if not (h > 0 and math.isfinite(h)) or _sparse(px, py, h):
        from scipy.spatial import cKDTree

        return cKDTree(np.c_[px, py]).query(np.c_[qx, qy], distance_upper_bound=r)[0] > r
    return _near(px, py, qx, qy, r, r, h, True)[0] == 1

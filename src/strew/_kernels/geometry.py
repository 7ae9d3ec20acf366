"""Segment and polygon predicates shared by the compiled loops (issue 15 point 5).

Coordinates are plain floats; polygons are *flat ring layouts*: vertices ``v`` (n, 2),
each ring closed (its last vertex repeats its first), ring ``r`` spanning
``v[rings[r]:rings[r + 1]]`` (``rings`` (r + 1,) int64).

The predicates are robust in one direction: an orientation or a crossing within the
relative tolerance :data:`TOL` is *too close to call* and reported as touching, so a
caller that treats touching as a collision never accepts a doubtful case (see
``strew.pack._fit``). :func:`seg_cross` is the strict opposite (only crossings interior
to both segments count), for the edge collision of ``strew.grow``.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["TOL", "circumcircles", "point_segment_distance", "seg_dist2", "seg_dist2_min", "orient", "seg_hit", "seg_cross", "inside", "where"]

# Relative tolerance of the exact tests: an orientation whose value is within TOL of the
# magnitude of its two products, or a crossing within TOL of the point it is compared
# with, counts as touching (far above the rounding of these few operations, about
# 3.3e-16, so the sign of every other decision is certain).
TOL = 1e-12

_SMALL = dict(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)


@numba.njit(cache=True, nogil=True, inline="always")
def seg_dist2(px: float, py: float, ax: float, ay: float, bx: float, by: float) -> float:  # pragma: no cover - numba
    """Squared distance from the point ``(px, py)`` to the segment ``(ax, ay)-(bx, by)``."""
    dx = bx - ax
    dy = by - ay
    ll = dx * dx + dy * dy
    t = 0.0
    if ll > 0.0:
        t = ((px - ax) * dx + (py - ay) * dy) / ll
        if t < 0.0:
            t = 0.0
        elif t > 1.0:
            t = 1.0
    qx = ax + t * dx - px
    qy = ay + t * dy - py
    return qx * qx + qy * qy


def circumcircles(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Circumcircles of triangles, row by row (numpy; synth's holes and fidelity's empty circles).

    Parameters
    ----------
    a, b, c : (m, 2) float
        The corners.

    Returns
    -------
    centre : (k, 2) float
    radius : (k,) float
        Of the ``k`` triangles that are not degenerate (twice the signed area beyond 1e-12).
    ok : (m,) bool
        Which triangles those are.

    Examples
    --------
    >>> centre, radius, ok = circumcircles(np.array([[0.0, 0.0]]), np.array([[2.0, 0.0]]), np.array([[0.0, 2.0]]))
    >>> centre, radius, ok
    (array([[1., 1.]]), array([1.41421356]), array([ True]))
    """
    bx, by = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
    cx, cy = c[:, 0] - a[:, 0], c[:, 1] - a[:, 1]
    d = 2.0 * (bx * cy - by * cx)
    ok = np.abs(d) > 1e-12
    d = np.where(ok, d, 1.0)
    ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d
    uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d
    centre = np.c_[a[:, 0] + ux, a[:, 1] + uy]
    return centre[ok], np.hypot(ux, uy)[ok], ok


def point_segment_distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distances from points to segments, row by row: :func:`seg_dist2`'s rule in numpy.

    Parameters
    ----------
    p, a, b : (n, 2) float
        The points and the segments' ends (a degenerate segment is its point ``a``).

    Returns
    -------
    (n,) float

    Examples
    --------
    >>> point_segment_distance(np.array([[0.0, 1.0], [3.0, 0.0]]), np.zeros((2, 2)), np.array([[2.0, 0.0], [2.0, 0.0]]))
    array([1., 1.])
    """
    ab = b - a
    L2 = (ab**2).sum(axis=1)
    t = np.where(L2 > 0, ((p - a) * ab).sum(axis=1) / np.where(L2 > 0, L2, 1.0), 0.0)
    t = np.clip(t, 0.0, 1.0)
    q = a + t[:, None] * ab
    return np.sqrt(((p - q) ** 2).sum(axis=1))


@numba.njit(**_SMALL)
def seg_dist2_min(px, py, ax, ay, ex, ey, il2, best):  # pragma: no cover - numba
    """Smallest squared distance from ``(px, py)`` to the segments ``a + t e``, starting
    from ``best``.

    ``ax, ay, ex, ey, il2`` are (s,) float: start points, direction vectors and
    ``1 / |e|**2`` (0 for a point). Branch-free, so the loop vectorises; the values
    equal :func:`seg_dist2`'s up to rounding.
    """
    for k in range(len(ax)):
        dx = px - ax[k]
        dy = py - ay[k]
        t = min(max((dx * ex[k] + dy * ey[k]) * il2[k], 0.0), 1.0)
        qx = dx - t * ex[k]
        qy = dy - t * ey[k]
        best = min(best, qx * qx + qy * qy)
    return best


@numba.njit(**_SMALL)
def orient(ax, ay, bx, by, cx, cy):  # pragma: no cover - numba
    """Orientation of c about ab: +1, -1, or 0 when too close to call (within TOL)."""
    u = (bx - ax) * (cy - ay)
    v = (by - ay) * (cx - ax)
    det = u - v
    if abs(det) <= TOL * (abs(u) + abs(v)):
        return 0
    return 1 if det > 0 else -1


@numba.njit(**_SMALL)
def seg_hit(ax, ay, bx, by, cx, cy, dx, dy):  # pragma: no cover - numba
    """Closed segments ab and cd meet, or come too close to call (touching counts;
    collinear overlap counts)."""
    if max(ax, bx) < min(cx, dx) or max(cx, dx) < min(ax, bx):
        return False
    if max(ay, by) < min(cy, dy) or max(cy, dy) < min(ay, by):
        return False
    d1 = orient(cx, cy, dx, dy, ax, ay)
    d2 = orient(cx, cy, dx, dy, bx, by)
    if d1 * d2 > 0:
        return False  # ab lies strictly on one side of the line cd
    d3 = orient(ax, ay, bx, by, cx, cy)
    d4 = orient(ax, ay, bx, by, dx, dy)
    # a proper crossing, or a zero orientation with overlapping boxes (touching,
    # collinear, or too close to call): reject (a cancellation only makes it stricter)
    return d3 * d4 <= 0


@numba.njit(**_SMALL)
def seg_cross(px, py, qx, qy, ax, ay, bx, by):  # pragma: no cover - numba
    """Segments pq and ab cross at a point interior to both (strict: touching, an end on
    the other segment and collinear overlap do not count).

    The opposite rule to :func:`seg_hit`: it serves the edge collision of a growth
    (Ijiri et al. 2008, Fig. 6 (d)), where edges that share an end or meet at one must
    both stay. Exact sign tests of four orientations, no tolerance: a case too close to
    call goes to whichever side its rounding gives (``strew.grow`` needs the same bytes
    for the same seed, not robustness here).
    """
    ex = bx - ax
    ey = by - ay
    d1 = ex * (py - ay) - ey * (px - ax)
    d2 = ex * (qy - ay) - ey * (qx - ax)
    if not ((d1 > 0 and d2 < 0) or (d1 < 0 and d2 > 0)):
        return False
    fx = qx - px
    fy = qy - py
    d3 = fx * (ay - py) - fy * (ax - px)
    d4 = fx * (by - py) - fy * (bx - px)
    return (d3 > 0 and d4 < 0) or (d3 < 0 and d4 > 0)


@numba.njit(**_SMALL)
def inside(px, py, v, rings, r0, r1):  # pragma: no cover - numba
    """Even-odd point in the rings ``r0:r1`` of a flat ring layout (half-open in y: an
    edge counts when ``(ay > py) != (by > py)`` and the point lies left of the crossing,
    the rule of :mod:`strew._kernels.raster`)."""
    ins = False
    for r in range(r0, r1):
        for i in range(rings[r], rings[r + 1] - 1):
            ay = v[i, 1]
            by = v[i + 1, 1]
            if (ay > py) != (by > py):
                ax = v[i, 0]
                xc = ax + (py - ay) * (v[i + 1, 0] - ax) / (by - ay)
                if px < xc:
                    ins = not ins
    return ins


@numba.njit(**_SMALL)
def where(px, py, v, rings, r0, r1):  # pragma: no cover - numba
    """Even-odd point in the rings ``r0:r1``: 1 inside, 0 outside, -1 when a crossing
    lies within TOL of the point (too close to call)."""
    ins = False
    for r in range(r0, r1):
        for i in range(rings[r], rings[r + 1] - 1):
            ay = v[i, 1]
            by = v[i + 1, 1]
            if (ay > py) != (by > py):
                ax = v[i, 0]
                bx = v[i + 1, 0]
                xc = ax + (py - ay) * (bx - ax) / (by - ay)
                if abs(px - xc) <= TOL * (abs(px) + abs(ax) + abs(bx)):
                    return -1
                if px < xc:
                    ins = not ins
    return 1 if ins else 0


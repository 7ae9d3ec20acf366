"""A compiled certificate that two simple polygons overlap by more than a sliver.

The grower counts two areal elements as overlapping when the area of their
intersection exceeds ``1e-9`` of the first one's area (``_Collide._hits_any``,
``overlaps_pool_many``, ``overlapping``, ``overlapping_many``: not in the paper, which
does not test overlaps). Each such pair cost a GEOS overlay (``shapely.intersection``)
and an area: some 2,000 pairs in a growth of 2,000 stones, most of them candidates of
``_nudge`` that overlap a neighbour plainly (issue 14 point 5).

:func:`overlap_certain` proves the answer True without the overlay where it can, from a
lower bound on the intersection's area: a vertex ``v`` of one polygon lying inside the
other at a distance ``d`` from its boundary, and farther than ``rho <= d`` from every
edge of its own polygon that does not end at ``v``, has the disc of radius ``rho`` about
it inside the other polygon and, within that disc, the sector of its own polygon's
interior angle ``theta`` at ``v``; so the intersection holds at least ``theta * rho**2 / 2``.
A pair is certified when that bound exceeds four times the threshold (rounding is some
``1e-15`` of these figures); every other pair takes the overlay as before, so the
answers are the overlay's, bit for bit.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .._kernels.geometry import seg_dist2 as _seg_dist2

#: the bound must exceed the threshold (1e-9 of the first polygon's area) this many times
CERTAIN_MARGIN = 4.0


@numba.njit(cache=True, nogil=True)
def _ring_area(c, a, b):  # pragma: no cover - numba
    """Signed shoelace area of the closed ring ``c[a:b]`` (last point equal to the first)."""
    s = 0.0
    for i in range(a, b - 1):
        s += c[i, 0] * c[i + 1, 1] - c[i + 1, 0] * c[i, 1]
    return 0.5 * s

@numba.njit(cache=True, nogil=True)
def _inside_depth2(px, py, c, a, b):  # pragma: no cover - numba
    """Squared distance from p to the boundary of the closed ring ``c[a:b]`` when p is
    inside it (crossing number), else -1."""
    inside = False
    d2 = np.inf
    for i in range(a, b - 1):
        ax, ay = c[i, 0], c[i, 1]
        bx, by = c[i + 1, 0], c[i + 1, 1]
        if (ay > py) != (by > py):
            xc = ax + (py - ay) * (bx - ax) / (by - ay)
            if px < xc:
                inside = not inside
        e = _seg_dist2(px, py, ax, ay, bx, by)
        if e < d2:  # noqa: PLR1730 - a comparison, not min(): one builtin fewer to compile
            d2 = e
    return d2 if inside else -1.0


@numba.njit(cache=True, nogil=True)
def _sector_bound(cp, pa, pb, orient, cq, qa, qb, need):  # pragma: no cover - numba
    """Is there a vertex of ring ``cp[pa:pb]`` (orientation sign ``orient``) whose
    sector inside ring ``cq[qa:qb]`` has an area above ``need``?"""
    m = pb - pa - 1  # vertices (the ring repeats the first)
    if m < 3:
        return False
    for k in range(m):
        i = pa + k
        vx, vy = cp[i, 0], cp[i, 1]
        d2 = _inside_depth2(vx, vy, cq, qa, qb)
        if d2 <= 0.0 or math.pi * d2 <= need:  # outside, or no sector can be large enough
            continue
        u = pa + (k - 1 if k > 0 else m - 1)
        w = pa + k + 1
        e0x, e0y = cp[u, 0] - vx, cp[u, 1] - vy
        e1x, e1y = cp[w, 0] - vx, cp[w, 1] - vy
        # interior angle at v: from the outgoing edge to the incoming one, turning
        # counter-clockwise in a counter-clockwise ring
        th = math.atan2(orient * (e1x * e0y - e1y * e0x), e1x * e0x + e1y * e0y)
        if th < 0.0:
            th += 2.0 * math.pi
        if 0.5 * th * d2 <= need:
            continue
        r2 = d2
        for j in range(m):
            if j == k or j == (k - 1 if k > 0 else m - 1):
                continue  # the two edges that end at v
            e = _seg_dist2(vx, vy, cp[pa + j, 0], cp[pa + j, 1], cp[pa + j + 1, 0], cp[pa + j + 1, 1])
            if e < r2:
                r2 = e
                if 0.5 * th * r2 <= need:
                    break
        if 0.5 * th * r2 > need:
            return True
    return False


@numba.njit(cache=True, nogil=True)
def overlap_certain(ca, oa, cb, ob, out):  # pragma: no cover - numba
    """For pairs of simple polygons (closed exterior rings, no holes), set ``out[p]``
    True where the intersection of ring ``p`` of A and ring ``p`` of B certainly holds
    more than ``1e-9`` of A's area (see the module's docstring); False: not proved.

    Parameters
    ----------
    ca, cb : (N, 2) float64
        The rings' coordinates, one after another (each closed).
    oa, ob : (P + 1,) int64
        Ring ``p`` is ``ca[oa[p]:oa[p + 1]]`` (``cb``, ``ob`` likewise).
    out : (P,) bool
        Written.
    """
    for p in range(out.shape[0]):
        a0, a1, b0, b1 = oa[p], oa[p + 1], ob[p], ob[p + 1]
        sa = _ring_area(ca, a0, a1)
        sb = _ring_area(cb, b0, b1)
        need = CERTAIN_MARGIN * 1e-9 * abs(sa)
        ok = False
        if sa != 0.0 and sb != 0.0:
            ok = _sector_bound(cb, b0, b1, 1.0 if sb > 0 else -1.0, ca, a0, a1, need)
            if not ok:
                ok = _sector_bound(ca, a0, a1, 1.0 if sa > 0 else -1.0, cb, b0, b1, need)
        out[p] = ok


@numba.njit(cache=True, nogil=True)
def _orient(ax, ay, bx, by, px, py):  # pragma: no cover - numba
    """Twice the signed area of (a, b, p): > 0 where p lies left of a -> b."""
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax)


@numba.njit(cache=True, nogil=True)
def _inside(px, py, c, a, b, ox, oy):  # pragma: no cover - numba
    """Is p inside the closed ring ``c[a:b] + (ox, oy)`` (crossing number)?"""
    inside = False
    for i in range(a, b - 1):
        ax, ay = c[i, 0] + ox, c[i, 1] + oy
        bx, by = c[i + 1, 0] + ox, c[i + 1, 1] + oy
        if (ay > py) != (by > py):
            xc = ax + (py - ay) * (bx - ax) / (by - ay)
            if px < xc:
                inside = not inside
    return inside


@numba.njit(cache=True, nogil=True)
def _touch_one(ca, a0, a1, cb, b0, b1, ox, oy, tol, sa, sb):  # pragma: no cover - numba
    """1, 0 or -1 (see :func:`intersect_certain`) for ring ``ca[a0:a1]`` against ring
    ``cb[b0:b1] + (ox, oy)``; ``sa``, ``sb`` are scratch index buffers (ring lengths)."""
    tol2 = tol * tol
    # the two bounding boxes, each widened by ``tol``
    ax0 = ay0 = np.inf
    ax1 = ay1 = -np.inf
    for i in range(a0, a1):
        x, y = ca[i, 0], ca[i, 1]
        ax0, ax1, ay0, ay1 = min(ax0, x), max(ax1, x), min(ay0, y), max(ay1, y)
    bx0 = by0 = np.inf
    bx1 = by1 = -np.inf
    for j in range(b0, b1):
        x, y = cb[j, 0] + ox, cb[j, 1] + oy
        bx0, bx1, by0, by1 = min(bx0, x), max(bx1, x), min(by0, y), max(by1, y)
    if ax1 < bx0 - tol or bx1 < ax0 - tol or ay1 < by0 - tol or by1 < ay0 - tol:
        return 0  # (apart by more than ``tol``)
    # the edges of each that reach into the other's box: only they can come within
    # ``tol`` of the other's edges or cross them (a vertex near the other's boundary
    # starts such an edge)
    na = 0
    for i in range(a0, a1 - 1):
        x0, x1 = min(ca[i, 0], ca[i + 1, 0]), max(ca[i, 0], ca[i + 1, 0])
        y0, y1 = min(ca[i, 1], ca[i + 1, 1]), max(ca[i, 1], ca[i + 1, 1])
        if x1 >= bx0 - tol and x0 <= bx1 + tol and y1 >= by0 - tol and y0 <= by1 + tol:
            sa[na] = i
            na += 1
    nb = 0
    for j in range(b0, b1 - 1):
        x0, x1 = min(cb[j, 0], cb[j + 1, 0]) + ox, max(cb[j, 0], cb[j + 1, 0]) + ox
        y0, y1 = min(cb[j, 1], cb[j + 1, 1]) + oy, max(cb[j, 1], cb[j + 1, 1]) + oy
        if x1 >= ax0 - 2.0 * tol and x0 <= ax1 + 2.0 * tol and y1 >= ay0 - 2.0 * tol and y0 <= ay1 + 2.0 * tol:
            sb[nb] = j
            nb += 1
    # a vertex within ``tol`` of the other's boundary: not decided here
    for p in range(na):
        i = sa[p]
        px, py = ca[i, 0], ca[i, 1]
        for q in range(nb):
            j = sb[q]
            if _seg_dist2(px, py, cb[j, 0] + ox, cb[j, 1] + oy, cb[j + 1, 0] + ox, cb[j + 1, 1] + oy) <= tol2:
                return -1
    for q in range(nb):
        j = sb[q]
        px, py = cb[j, 0] + ox, cb[j, 1] + oy
        for p in range(na):
            i = sa[p]
            if _seg_dist2(px, py, ca[i, 0], ca[i, 1], ca[i + 1, 0], ca[i + 1, 1]) <= tol2:
                return -1
    # every vertex is over ``tol`` from the other's edges: two edges either cross
    # clearly (each end over ``tol`` from the other edge's line) or the pair is unsure
    for p in range(na):
        i = sa[p]
        ax, ay, bx, by = ca[i, 0], ca[i, 1], ca[i + 1, 0], ca[i + 1, 1]
        la = math.sqrt((bx - ax) ** 2 + (by - ay) ** 2)
        for q in range(nb):
            j = sb[q]
            cx, cy = cb[j, 0] + ox, cb[j, 1] + oy
            dx, dy = cb[j + 1, 0] + ox, cb[j + 1, 1] + oy
            if max(ax, bx) < min(cx, dx) - tol or max(cx, dx) < min(ax, bx) - tol:
                continue
            if max(ay, by) < min(cy, dy) - tol or max(cy, dy) < min(ay, by) - tol:
                continue
            lc = math.sqrt((dx - cx) ** 2 + (dy - cy) ** 2)
            o1 = _orient(ax, ay, bx, by, cx, cy)
            o2 = _orient(ax, ay, bx, by, dx, dy)
            o3 = _orient(cx, cy, dx, dy, ax, ay)
            o4 = _orient(cx, cy, dx, dy, bx, by)
            ma = tol * la
            mc = tol * lc
            if abs(o1) <= ma or abs(o2) <= ma or abs(o3) <= mc or abs(o4) <= mc:
                return -1
            if (o1 > 0.0) != (o2 > 0.0) and (o3 > 0.0) != (o4 > 0.0):
                return 1
    # no boundaries meet (with room): they intersect only where one holds the other
    if _inside(ca[a0, 0], ca[a0, 1], cb, b0, b1, ox, oy):
        return 1
    if _inside(cb[b0, 0] + ox, cb[b0, 1] + oy, ca, a0, a1, 0.0, 0.0):
        return 1
    return 0


@numba.njit(cache=True, nogil=True)
def intersect_certain(ca, oa, cb, ob, k, off, tol, out):  # pragma: no cover - numba
    """For the pairs ``k``: does simple polygon ``k[p]`` of A (ring ``ca[oa[q]:oa[q + 1]]``,
    closed) intersect simple polygon ``k[p]`` of B moved by ``off[p]`` (ring
    ``cb[ob[q]:ob[q + 1]] + off[p]``)? ``out[p]``: 1 certainly (as ``shapely.intersects``
    answers), 0 certainly not, -1 not known here (a vertex within ``tol`` of the
    other's boundary, or two edges nearly parallel where they meet).

    The answers given are shapely's on the same polygons: every decision is made with
    ``tol`` of room, far above the rounding of the coordinates (so a coordinate a few
    units in the last place off, as a sum made in another order may be, decides alike);
    the unsure pairs are left to shapely (issue 14 point 5).
    """
    most = 1
    for q in range(oa.shape[0] - 1):
        most = max(most, oa[q + 1] - oa[q])
    for q in range(ob.shape[0] - 1):
        most = max(most, ob[q + 1] - ob[q])
    sa = np.empty(most, dtype=np.int64)
    sb = np.empty(most, dtype=np.int64)
    for p in range(k.shape[0]):
        q = k[p]
        out[p] = _touch_one(ca, oa[q], oa[q + 1], cb, ob[q], ob[q + 1], off[p, 0], off[p, 1], tol, sa, sb)

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

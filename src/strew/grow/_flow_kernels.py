"""Compiled loops of flow mode's passes (issue 14 point 5).

:func:`boundary_distance` is :meth:`strew.Region.distance_to_boundary` (GEOS's
distance from each point to the region's boundary lines, through shapely) without
a shapely point made per query point: the passes after the growth
(:mod:`strew.grow._flow_net`, ``_flow_shear``, ``_flow_retry``, ``_flow_densify``,
...) ask it for every element and for quarter-edge grids of thousands of points, some
eighty times per growth, and making the points cost more than the distances (4.5 % of
a flow growth with relaxation). The kernel repeats GEOS's arithmetic
(``geos::algorithm::Distance::pointToSegment`` and ``Coordinate::distance``: the
same operations in the same order, no fused multiply-add), and the least over the
segments is exact, so the distances are GEOS's to the last bit (1.2 million points
over rectangles and a polygon with a hole: none differed; GEOS 3.14.1). The core
(:mod:`strew.region`) may not import the kernel layer, so the call sites in
:mod:`strew.grow` call this instead.

Compiled with ``cache=True``; the warm-up's "grow flow" case reaches it.
"""

from __future__ import annotations

import math

import numba
import numpy as np
import shapely

__all__ = ["boundary_distance"]

# region -> its boundary segments (s, 4); a few regions at most per growth
_SEGMENTS: dict[int, tuple[object, np.ndarray]] = {}


@numba.njit(cache=True)
def point_segments_distance(px, py, segs):  # pragma: no cover - numba
    """The least distance from each point (px[q], py[q]) to the segments ``segs``
    (s, 4: ax, ay, bx, by), computed as GEOS computes a point's distance to a
    segment; (n,) float."""
    n = px.shape[0]
    out = np.empty(n)
    for q in range(n):
        x = px[q]
        y = py[q]
        best = np.inf
        for k in range(segs.shape[0]):
            ax = segs[k, 0]
            ay = segs[k, 1]
            bx = segs[k, 2]
            by = segs[k, 3]
            if ax == bx and ay == by:
                dx = x - ax
                dy = y - ay
                d = math.sqrt(dx * dx + dy * dy)
            else:
                len2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay)
                r = ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / len2
                if r <= 0.0:
                    dx = x - ax
                    dy = y - ay
                    d = math.sqrt(dx * dx + dy * dy)
                elif r >= 1.0:
                    dx = x - bx
                    dy = y - by
                    d = math.sqrt(dx * dx + dy * dy)
                else:
                    s = ((ay - y) * (bx - ax) - (ax - x) * (by - ay)) / len2
                    d = abs(s) * math.sqrt(len2)
            if d < best:
                best = d
        out[q] = best
    return out


def _segments(region) -> np.ndarray | None:
    """The straight segments of ``region``'s boundary lines (s, 4), or None where the
    boundary is not made of line strings."""
    got = _SEGMENTS.get(id(region))
    if got is not None and got[0] is region:
        return got[1]
    parts = shapely.get_parts(region.boundary)
    if not len(parts) or not np.isin(shapely.get_type_id(parts), (1, 2)).all():  # (LineString, LinearRing)
        return None
    segs = []
    for line in parts:
        c = shapely.get_coordinates(line)
        if len(c) >= 2:
            segs.append(np.concatenate([c[:-1], c[1:]], axis=1))
    if not segs:
        return None
    out = np.ascontiguousarray(np.concatenate(segs), dtype=np.float64)
    if len(_SEGMENTS) >= 8:
        _SEGMENTS.clear()
    _SEGMENTS[id(region)] = (region, out)  # (the region kept: its id is not reused)
    return out


def boundary_distance(region, points: np.ndarray) -> np.ndarray:
    """``region.distance_to_boundary(points)``, the same floats (see the module)."""
    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    segs = _segments(region)
    if segs is None:
        return region.distance_to_boundary(pts)
    return point_segments_distance(np.ascontiguousarray(pts[:, 0]), np.ascontiguousarray(pts[:, 1]), segs)

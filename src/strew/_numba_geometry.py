"""Small numba geometry helpers shared by the compiled loops of several methods."""

from __future__ import annotations

import numba

__all__ = ["seg_dist2"]


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

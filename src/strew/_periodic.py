"""Periodic (repeat-tile) arrangements: the shared contract of issue 18.

A periodic arrangement fills the torus ``[x0, x0 + W) x [y0, y0 + H)``. It records the
tile in ``meta["periodic"] = [x0, y0, W, H]`` and keeps each element once, at its
canonical position (centre inside the half-open tile). An element whose footprint
crosses the tile's edge wraps in at the opposite edge: :func:`images` adds those
wrapped copies (for drawing the tile and for overlap checks), and :func:`tiled_copies`
lays ``nx x ny`` copies side by side (for previews and for tests of the repeat).

Every method that takes ``periodic=True`` writes the frame with :func:`mark`; io, the
renderer and the metrics read it with :func:`frame`. This module sits with the core
types: it imports numpy and :mod:`strew.arrangement` only.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from ._errors import InputError

if TYPE_CHECKING:  # pragma: no cover
    from .arrangement import Arrangement

__all__ = [
    "META_KEY",
    "Frame",
    "frame",
    "frame_of_region",
    "mark",
    "canonical",
    "wrap_delta",
    "images",
    "tiled_copies",
    "translations",
]

META_KEY = "periodic"

Frame = tuple[float, float, float, float]  # x0, y0, width, height


def _as_frame(value: Any, what: str = "periodic") -> Frame:
    try:
        x0, y0, w, h = (float(v) for v in value)
    except (TypeError, ValueError):
        raise InputError(f"{what}: must be [x0, y0, width, height], got {value!r}") from None
    if not all(np.isfinite([x0, y0, w, h])):
        raise InputError(f"{what}: must be finite numbers, got {value!r}")
    if w <= 0 or h <= 0:
        raise InputError(f"{what}: width and height must be positive, got {w:g} x {h:g}")
    return (x0, y0, w, h)


def frame(arr_or_meta: Arrangement | Mapping[str, Any]) -> Frame | None:
    """The tile ``(x0, y0, W, H)`` of a periodic arrangement, or None if it is not periodic.

    Parameters
    ----------
    arr_or_meta : Arrangement or mapping
        An arrangement or its ``meta``.
    """
    meta = arr_or_meta if isinstance(arr_or_meta, Mapping) else arr_or_meta.meta
    value = meta.get(META_KEY)
    if value is None or value is False:
        return None
    return _as_frame(value, f"meta.{META_KEY}")


def frame_of_region(region: Any) -> Frame:
    """The tile of a rectangular region; refuses any other shape.

    Parameters
    ----------
    region : Region
        Must be an axis-aligned rectangle (as ``--size WxH`` gives).
    """
    import shapely

    poly = region.geometry if hasattr(region, "geometry") else region
    x0, y0, x1, y1 = shapely.bounds(poly).tolist()
    box_area = (x1 - x0) * (y1 - y0)
    if box_area <= 0 or abs(float(shapely.area(poly)) - box_area) > 1e-9 * box_area:
        raise InputError(
            "periodic: a repeat tile needs a rectangular region (--size WxH), "
            f"got a region of area {float(shapely.area(poly)):g} in a {x1 - x0:g} x {y1 - y0:g} box"
        )
    return (float(x0), float(y0), float(x1 - x0), float(y1 - y0))


def mark(arr: Arrangement, tile: Sequence[float]) -> Arrangement:
    """Copy of ``arr`` with its positions made canonical and ``meta["periodic"]`` set."""
    f = _as_frame(tile)
    x, y = canonical(arr.x, arr.y, f)
    return arr.replace(x=x, y=y, meta={**arr.meta, META_KEY: list(f)})


def canonical(x: np.ndarray, y: np.ndarray, tile: Sequence[float]) -> tuple[np.ndarray, np.ndarray]:
    """Positions wrapped into the half-open tile.

    Parameters
    ----------
    x, y : (n,) float
    tile : (4,) float
        ``x0, y0, W, H``.

    Returns
    -------
    x, y : (n,) float
        In ``[x0, x0 + W) x [y0, y0 + H)``.
    """
    x0, y0, w, h = _as_frame(tile)
    cx = x0 + np.mod(np.asarray(x, dtype=float) - x0, w)
    cy = y0 + np.mod(np.asarray(y, dtype=float) - y0, h)
    # mod can return exactly w for tiny negative inputs
    cx = np.where(cx >= x0 + w, x0, cx)
    cy = np.where(cy >= y0 + h, y0, cy)
    return cx, cy


def wrap_delta(d: np.ndarray, period: float) -> np.ndarray:
    """Shortest signed difference on a circle of length ``period``: in ``[-period/2, period/2)``."""
    d = np.asarray(d, dtype=float)
    return d - period * np.floor(d / period + 0.5)


def translations(nx: int = 3, ny: int = 3) -> np.ndarray:
    """Integer tile offsets ``(i, j)`` of an ``nx x ny`` block centred on the tile, (nx*ny, 2)."""
    i = np.arange(nx) - (nx - 1) // 2
    j = np.arange(ny) - (ny - 1) // 2
    return np.array([(a, b) for b in j for a in i], dtype=float)


def _shifted(arr: Arrangement, idx: np.ndarray, dx: np.ndarray, dy: np.ndarray) -> Arrangement:
    sub = arr.select(idx)
    return sub.replace(x=sub.x + dx, y=sub.y + dy)


def images(arr: Arrangement, tile: Sequence[float] | None = None) -> Arrangement:
    """The tile's elements plus the wrapped copies whose footprint reaches into the tile.

    The first ``len(arr)`` rows are ``arr`` itself; the copies follow, in the order of
    :func:`translations` (3 x 3, the centre left out). Drawing the result clipped to the
    tile gives a complete tile; any overlap among its elements is an overlap of the
    repeat.

    Parameters
    ----------
    arr : Arrangement
        A periodic arrangement (or any arrangement, with ``tile`` given).
    tile : (4,) float, optional
        ``x0, y0, W, H``; default ``frame(arr)``.
    """
    f = frame(arr) if tile is None else _as_frame(tile)
    if f is None:
        raise InputError("images: the arrangement is not periodic (no meta.periodic)")
    x0, y0, w, h = f
    if len(arr) == 0:
        return arr
    import shapely

    b = shapely.bounds(arr.geometry)  # (n, 4)
    parts = [arr]
    for i, j in translations(3, 3):
        if i == 0 and j == 0:
            continue
        dx, dy = i * w, j * h
        hit = (b[:, 2] + dx > x0) & (b[:, 0] + dx < x0 + w) & (b[:, 3] + dy > y0) & (b[:, 1] + dy < y0 + h)
        idx = np.flatnonzero(hit)
        if len(idx):
            parts.append(_shifted(arr, idx, np.full(len(idx), dx), np.full(len(idx), dy)))
    from .arrangement import concat

    return concat(parts) if len(parts) > 1 else arr


def tiled_copies(arr: Arrangement, nx: int = 3, ny: int = 3, tile: Sequence[float] | None = None) -> Arrangement:
    """``nx x ny`` copies of the tile laid side by side, the original at the block's centre.

    The result is not periodic itself (``meta["periodic"]`` is dropped) and its region
    is None; use it to check a repeat with :func:`strew.metrics.overlaps` or to preview it.

    Parameters
    ----------
    arr : Arrangement
    nx, ny : int
        Copies across and down (each at least 1).
    tile : (4,) float, optional
        Default ``frame(arr)``.
    """
    f = frame(arr) if tile is None else _as_frame(tile)
    if f is None:
        raise InputError("tiled_copies: the arrangement is not periodic (no meta.periodic)")
    if int(nx) < 1 or int(ny) < 1:
        raise InputError(f"repeat: needs at least 1 x 1 copies, got {nx} x {ny}")
    _, _, w, h = f
    n = len(arr)
    offs = translations(int(nx), int(ny))
    dx = np.repeat(offs[:, 0] * w, n)
    dy = np.repeat(offs[:, 1] * h, n)
    idx = np.tile(np.arange(n), len(offs))
    out = _shifted(arr, idx, dx, dy)
    meta = {k: v for k, v in arr.meta.items() if k != META_KEY}
    return out.replace(meta=meta, region=None)

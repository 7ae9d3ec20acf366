"""Helpers of tests/worlds (no conftest.py there): overlaps and border-strip statistics."""

from __future__ import annotations

import numpy as np
import shapely


def overlapping_pairs(arr, tol: float = 1e-9) -> int:
    """Pairs of elements whose areas overlap by more than ``tol``."""
    g = arr.geometry_of("geometry")
    tree = shapely.STRtree(g)
    left, right = tree.query(g, predicate="intersects")
    m = left < right
    if not m.any():
        return 0
    return int((shapely.area(shapely.intersection(g[left[m]], g[right[m]])) > tol).sum())


def border_strips(arr, size, tile_size: float, width: float, margin: float):
    """(strip mask, interior mask, strip area, interior area) of element centres.

    The strips are the bands of half-width ``width`` about the tiles' inner borders; the
    interior is the rest; both leave out the world's own edge band ``margin``.
    """
    w, h = size
    x, y = arr.x, arr.y
    inside = (x >= margin) & (x <= w - margin) & (y >= margin) & (y <= h - margin)
    lines_x = np.arange(tile_size, w - 1e-9, tile_size)
    lines_y = np.arange(tile_size, h - 1e-9, tile_size)
    near = np.zeros(len(arr), bool)
    for lx in lines_x:
        near |= np.abs(x - lx) < width
    for ly in lines_y:
        near |= np.abs(y - ly) < width
    # areas by a fine raster of the same sets
    gx, gy = np.meshgrid(np.linspace(0, w, 1201)[:-1] + w / 2400, np.linspace(0, h, 1201)[:-1] + h / 2400)
    gin = (gx >= margin) & (gx <= w - margin) & (gy >= margin) & (gy <= h - margin)
    gnear = np.zeros_like(gin)
    for lx in lines_x:
        gnear |= np.abs(gx - lx) < width
    for ly in lines_y:
        gnear |= np.abs(gy - ly) < width
    cell = (w / 1200) * (h / 1200)
    return inside & near, inside & ~near, (gin & gnear).sum() * cell, (gin & ~gnear).sum() * cell

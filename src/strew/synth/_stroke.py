"""Brush strokes from files, resampled into brush points (§5.4)."""

from __future__ import annotations

import os

import numpy as np
import shapely

from .._errors import InputError
from ..io.strokes import read_strokes

__all__ = ["read_stroke", "brush_points"]


def brush_points(polylines: list[np.ndarray], radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Brush points ``(bp_i, br_i)`` every ``radius / 2`` along polylines.

    Parameters
    ----------
    polylines : list of (m, 2) float
    radius : float

    Returns
    -------
    points : (p, 2) float
    radii : (p,) float
    """
    if not radius > 0:
        raise InputError(f"brush_radius: must be positive, got {radius:g}")
    out = []
    for line in polylines:
        line = np.asarray(line, float).reshape(-1, 2)
        if len(line) == 1:
            out.append(line)
            continue
        ls = shapely.LineString(line)
        n = max(2, int(np.ceil(ls.length / (0.5 * radius))) + 1)
        pts = shapely.line_interpolate_point(ls, np.linspace(0.0, ls.length, n))
        out.append(shapely.get_coordinates(pts))
    if not out:
        raise InputError("brush: the stroke has no points")
    pts = np.concatenate(out)
    return pts, np.full(len(pts), float(radius))


def read_stroke(path: str | os.PathLike[str], what: str = "brush") -> list[np.ndarray]:
    """Polylines of a brush stroke file (§5.4's generative brush path).

    ``.json``: ``{"points": [[x, y], ...]}``, ``{"paths": [{"points": ...}, ...]}``, a bare
    list of points, or a strew document (its elements' outlines in world space, holes'
    outlines included). ``.svg``: every drawn path, in world space. The reader is
    :func:`strew.io.strokes.read_strokes` (shared with grow's tools).

    Returns
    -------
    list of (k, 2) float
    """
    return read_strokes(path, what)

"""Brush strokes from files, resampled into brush points (§5.4)."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import shapely

from .._errors import InputError

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
        raise InputError(f"--brush-radius: must be positive, got {radius:g}")
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


def read_stroke(path: str | os.PathLike[str]) -> list[np.ndarray]:
    """Polylines of a brush stroke file.

    ``.json``: ``{"points": [[x, y], ...]}``, ``{"paths": [{"points": ...}, ...]}``, a bare
    list of points, or a strew document (its elements' outlines in world space).
    ``.svg``: every drawn path, in world space.
    """
    p = Path(path)
    suffix = p.suffix.lower()
    if suffix == ".json":
        try:
            doc = json.loads(p.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise InputError(f"{str(path)!r}: no such file") from None
        except json.JSONDecodeError as exc:
            raise InputError(f"{p.name}: malformed JSON: {exc.msg} at line {exc.lineno}") from None
        if isinstance(doc, list):
            return [_points(doc, p.name)]
        if isinstance(doc, dict) and "points" in doc:
            return [_points(doc["points"], p.name)]
        if isinstance(doc, dict) and "paths" in doc and doc.get("format") != "strew.arrangement":
            return [_points(q.get("points") if isinstance(q, dict) else q, p.name) for q in doc["paths"]]
    elif suffix != ".svg":
        raise InputError(f"brush {str(path)!r}: unsupported extension {suffix or '(none)'!r}; use .svg or .json")
    from ..io import load

    arr = load(p)
    lines = []
    for g in arr.geometry:
        for part in shapely.get_parts(g):
            if isinstance(part, shapely.Polygon):
                part = part.exterior
            c = shapely.get_coordinates(part)
            if len(c):
                lines.append(c)
    if not lines and arr.region is not None:
        lines = [shapely.get_coordinates(shapely.get_parts(arr.region.geometry)[0].exterior)]
    if not lines:
        raise InputError(f"{p.name}: no stroke found")
    return lines


def _points(data: object, where: str) -> np.ndarray:
    try:
        pts = np.asarray(data, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{where}: points: expected [[x, y], ...]") from None
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) == 0:
        raise InputError(f"{where}: points: expected [[x, y], ...]")
    if not np.all(np.isfinite(pts)):
        raise InputError(f"{where}: points: NaN or inf coordinate")
    return pts

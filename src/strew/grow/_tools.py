"""Reading the strokes of the interaction tools (Ijiri et al. 2008, §3, Fig. 1).

Flow-field strokes, boundary strokes and spray paths are polylines in world space. They
come from an SVG (every drawn path, transforms applied) or a JSON file: either
``{"paths": [{"points": [[x, y], ...]}, ...]}`` or a strew document whose elements'
world geometry gives the strokes.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import shapely

from .._errors import InputError

__all__ = ["load_strokes", "strokes_of_geometry"]


def strokes_of_geometry(geoms: np.ndarray) -> list[np.ndarray]:
    """Polylines (k, 2) of world geometries: lines as they are, polygons by their rings."""
    out: list[np.ndarray] = []
    for g in np.atleast_1d(geoms):
        if g is None or g.is_empty:
            continue
        for part in shapely.get_parts(g):
            if isinstance(part, shapely.Polygon):
                for ring in [part.exterior, *part.interiors]:
                    out.append(np.asarray(ring.coords, dtype=float))
            elif isinstance(part, (shapely.LineString, shapely.LinearRing)):
                out.append(np.asarray(part.coords, dtype=float))
            elif isinstance(part, shapely.GeometryCollection):
                out.extend(strokes_of_geometry(np.array(list(shapely.get_parts(part)), dtype=object)))
    return out


def load_strokes(path: str | os.PathLike[str], what: str = "strokes") -> list[np.ndarray]:
    """Polylines from an SVG or JSON file; ``what`` names the option in messages.

    Returns
    -------
    list of (k, 2) float
    """
    from ..io import load

    p = Path(path)
    if p.suffix.lower() == ".json":
        try:
            doc = json.loads(p.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise InputError(f"{what} {str(path)!r}: no such file") from None
        except json.JSONDecodeError as exc:
            raise InputError(f"{what} {p.name}: malformed JSON: {exc.msg} at line {exc.lineno}") from None
        if isinstance(doc, dict) and "paths" in doc and doc.get("format") is None:
            paths = doc["paths"]
            if not isinstance(paths, list):
                raise InputError(f"{what} {p.name}: paths: must be a list")
            out = []
            for i, item in enumerate(paths):
                pts = item.get("points") if isinstance(item, dict) else item
                try:
                    arr = np.asarray(pts, dtype=float)
                except (TypeError, ValueError):
                    raise InputError(f"{what} {p.name}: paths[{i}]: points must be [[x, y], ...]") from None
                if arr.ndim != 2 or arr.shape[1] != 2 or not np.all(np.isfinite(arr)):
                    raise InputError(f"{what} {p.name}: paths[{i}]: points must be finite [[x, y], ...]")
                if isinstance(item, dict) and item.get("closed"):
                    arr = np.vstack([arr, arr[:1]])
                out.append(arr)
            strokes = out
        else:
            strokes = strokes_of_geometry(load(p).geometry)
    else:
        strokes = strokes_of_geometry(load(p).geometry)
    strokes = [s for s in strokes if len(s) >= 1]
    if not strokes:
        raise InputError(f"{what} {p.name}: no stroke found")
    return strokes

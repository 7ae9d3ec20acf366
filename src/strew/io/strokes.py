"""Stroke files: the polylines that tools draw in world space.

One reader for every method that takes strokes: grow's flow-field, boundary and spray
strokes (Ijiri et al. 2008, §3, Fig. 1) and synth's generative brush (Davison et al. 2018,
§5.4). A stroke file is

- an SVG (``.svg``/``.svgz``): every drawn path, transforms applied;
- a JSON file holding a bare list of points ``[[x, y], ...]``, an object
  ``{"points": [[x, y], ...]}``, or ``{"paths": [{"points": [...], "closed": bool}, ...]}``
  (an item may also be a bare list of points);
- a strew document (``"format": "strew.arrangement"``): its elements' world geometry.

Geometry becomes strokes ring by ring: a polygon gives its outline *and each hole's
outline*. A hole's ring is a line the user drew, so it is a stroke like any other: a
boundary along it walls the hole off for grow (§3's boundary strokes confine growth to
what the lines enclose), and a brush along it paints around the hole for synth. (grow's
reader kept holes and synth's dropped them; the shared reader keeps them, so synth's
brush follows a holed outline in full. Outlines without holes read as before.)
A file whose geometry has no element but a region gives the region's rings.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from .._limits import check_file

__all__ = ["read_strokes", "strokes_of_geometry"]

_SUFFIXES = (".json", ".svg", ".svgz")


def strokes_of_geometry(geoms: Any) -> list[np.ndarray]:
    """Polylines of world geometries: lines as they are, polygons ring by ring (holes too).

    Parameters
    ----------
    geoms : shapely geometry or (n,) object array of them
        ``None`` and empty geometries are skipped.

    Returns
    -------
    list of (k, 2) float
        One polyline per line or ring, in the order of ``geoms`` and their parts.

    Examples
    --------
    >>> import shapely
    >>> sq = shapely.box(0, 0, 4, 4).difference(shapely.box(1, 1, 2, 2))
    >>> [len(s) for s in strokes_of_geometry(sq)]
    [5, 5]
    """
    out: list[np.ndarray] = []
    for g in np.atleast_1d(np.asarray(geoms, dtype=object)):
        if g is None or g.is_empty:
            continue
        for part in shapely.get_parts(g):
            if isinstance(part, shapely.Polygon):
                for ring in [part.exterior, *part.interiors]:
                    out.append(np.asarray(ring.coords, dtype=float))
            elif isinstance(part, (shapely.LineString, shapely.LinearRing)):
                out.append(np.asarray(part.coords, dtype=float))
            elif isinstance(part, shapely.Point):
                out.append(np.asarray(part.coords, dtype=float).reshape(-1, 2))
            elif isinstance(part, shapely.GeometryCollection):
                out.extend(strokes_of_geometry(np.array(list(shapely.get_parts(part)), dtype=object)))
    return [s for s in out if len(s) >= 1]


def read_strokes(path: str | os.PathLike[str], what: str = "strokes") -> list[np.ndarray]:
    """Polylines of a stroke file (SVG, JSON points or paths, or a strew document).

    Parameters
    ----------
    path : str or path-like
        ``.svg``, ``.svgz`` or ``.json`` (see the module docstring for the JSON shapes).
    what : str
        What the strokes are for, named at the start of every message (a parameter
        name such as ``"flow"`` or ``"brush"``; the CLI passes its flag).

    Returns
    -------
    list of (k, 2) float
        One polyline per path or ring, ``k >= 1``, finite coordinates, world space.

    Raises
    ------
    InputError
        Unsupported extension, missing or malformed file, a field that is not a list of
        finite ``[x, y]`` pairs (the message names the field, e.g. ``paths[2].points``),
        or a file with no stroke.

    Examples
    --------
    >>> import json, tempfile
    >>> from pathlib import Path
    >>> f = Path(tempfile.mkdtemp()) / "s.json"
    >>> _ = f.write_text(json.dumps({"paths": [{"points": [[0, 0], [5, 0]]}]}))
    >>> read_strokes(f)[0].shape
    (2, 2)
    """
    p = Path(path)
    suffix = p.suffix.lower()
    if suffix not in _SUFFIXES:
        raise InputError(f"{what} {str(path)!r}: unsupported extension {suffix or '(none)'!r}; use .svg or .json")
    strokes: list[np.ndarray] | None = None
    if suffix == ".json":
        check_file(p, f"{what} {p.name}")
        try:
            doc = json.loads(p.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise InputError(f"{what} {str(path)!r}: no such file") from None
        except IsADirectoryError:
            raise InputError(f"{what} {str(path)!r}: is a folder, expected a file") from None
        except UnicodeDecodeError:
            raise InputError(f"{what} {str(path)!r}: not UTF-8 text") from None
        except json.JSONDecodeError as exc:
            raise InputError(f"{what} {p.name}: malformed JSON: {exc.msg} at line {exc.lineno}") from None
        except RecursionError:
            raise InputError(f"{what} {p.name}: malformed JSON: nested too deeply") from None
        where = f"{what} {p.name}"
        if isinstance(doc, list):
            strokes = [_points(doc, f"{where}: points")]
        elif isinstance(doc, dict) and doc.get("format") is None and "points" in doc:
            strokes = [_points(doc["points"], f"{where}: points")]
        elif isinstance(doc, dict) and doc.get("format") is None and "paths" in doc:
            paths = doc["paths"]
            if not isinstance(paths, list):
                raise InputError(f"{where}: paths: must be a list")
            strokes = []
            for i, item in enumerate(paths):
                if isinstance(item, dict):
                    arr = _points(item.get("points"), f"{where}: paths[{i}].points")
                    if item.get("closed"):
                        arr = np.vstack([arr, arr[:1]])
                else:
                    arr = _points(item, f"{where}: paths[{i}]")
                strokes.append(arr)
    if strokes is None:
        from . import load

        try:
            arr = load(p)
        except InputError as exc:
            raise InputError(f"{what}: {exc}") from None
        strokes = strokes_of_geometry(arr.geometry)
        if not strokes and arr.region is not None:
            strokes = strokes_of_geometry(arr.region.geometry)
    if not strokes:
        raise InputError(f"{what} {p.name}: no stroke found")
    return strokes


def _points(data: object, where: str) -> np.ndarray:
    """``data`` as (k, 2) finite float with k >= 1; ``where`` names the field."""
    try:
        pts = np.asarray(data, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{where}: expected [[x, y], ...]") from None
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) == 0:
        raise InputError(f"{where}: expected [[x, y], ...]")
    if not np.all(np.isfinite(pts)):
        raise InputError(f"{where}: NaN or inf coordinate")
    return pts

"""SVG drawings as labelled curves and points: the reading behind ``program.import_svg``
(Loi et al. 2015, Table 5: ImportSVG), kept in :mod:`strew.io` with the other SVG reading
(issue 15 point 5).

Unlike :func:`strew.io.svg.read_svg`, which reads an exemplar (elements with shapes and
poses, in the document's user units, curves sampled by a chord-error bound), this reads
construction lines for the programmable model: every path and basic shape, in viewport
coordinates (svgelements' reified geometry), one polyline per sub-path, curved segments
sampled every ``tolerance`` of arc length. The two readings are not merged yet, because
merging would move every imported curve (the viewBox offset, other sample points) and so
change every program output that imports an SVG.
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InputError
from .._limits import check_file

__all__ = ["read_svg_curves"]

_AUTO_ID = re.compile(r"^(path|rect|circle|ellipse|polyline|polygon|line|g|layer|svg|use|text|tspan|shape)[-_]?\d+$")
_INKSCAPE_LABEL = "{http://www.inkscape.org/namespaces/inkscape}label"


def _element_label(el: Any) -> str | None:
    values = getattr(el, "values", {}) or {}
    lab = values.get(_INKSCAPE_LABEL) or values.get("inkscape:label")
    if lab:
        return str(lab)
    ident = getattr(el, "id", None)
    if ident and not _AUTO_ID.match(str(ident)):
        return str(ident)
    return None


def _flatten(seg: Any, tol: float) -> np.ndarray:
    import svgelements as se

    if isinstance(seg, (se.Line, se.Close)):
        return np.array([[seg.end.x, seg.end.y]], dtype=float)
    length = float(seg.length(error=1e-4))
    n = max(2, int(math.ceil(length / tol)))
    ts = np.linspace(0.0, 1.0, n + 1)[1:]
    pts = seg.npoint(ts)
    return np.asarray(pts, dtype=float).reshape(-1, 2)


def read_svg_curves(
    filename: str | os.PathLike[str], *, tolerance: float | None = None, what: str = "svg"
) -> tuple[list[tuple[np.ndarray, bool, str | None]], dict[str, tuple[float, float]]]:
    """Curves and labelled points of an SVG drawing, every transform applied.

    Every path and basic shape gives one curve per sub-path, flattened to a polyline
    (a sub-path ending in ``Z``, or whose ends meet, is closed and its last point dropped).
    An element's Inkscape label, or else its id when the id is not an editor's automatic
    one (``path123``), labels its curves. A labelled ``<circle>`` or ``<ellipse>`` is a
    labelled point at its centre instead.

    Parameters
    ----------
    filename : path
    tolerance : float, optional
        Sampling step along curved segments (default: 1/40 of the drawing's diagonal).
    what : str
        Names the caller at the start of every message (``import_svg``).

    Returns
    -------
    curves : list of ((k, 2) float, bool, str or None)
        Points (``k >= 2``), closed, label; in document order.
    points : dict of str to (float, float)
        Labelled points.
    """
    import svgelements as se

    path = Path(filename)
    if not path.exists():
        raise InputError(f"{what}: {str(filename)!r}: no such file")
    check_file(path, f"{what}: {path.name}")
    try:
        svg = se.SVG.parse(str(path), reify=True)
    except Exception as exc:  # svgelements raises various errors on bad files
        raise InputError(f"{what}: {path.name}: not a readable SVG ({type(exc).__name__}: {exc})") from None
    shapes = []
    points: dict[str, tuple[float, float]] = {}
    for el in svg.elements():
        if not isinstance(el, se.Shape) or isinstance(el, se.SVG):
            continue
        label = _element_label(el)
        if label is not None and isinstance(el, (se.Circle, se.Ellipse)):
            points[label] = (float(el.cx), float(el.cy))
            continue
        shapes.append((el, label))
    bbs = [se.Path(el).bbox() for el, _ in shapes]
    bbs = [b for b in bbs if b is not None]
    if tolerance is None:
        if bbs:
            arr = np.array(bbs, dtype=float)
            diag = math.hypot(arr[:, 2].max() - arr[:, 0].min(), arr[:, 3].max() - arr[:, 1].min())
        else:
            diag = 1.0
        tol = max(diag, 1e-9) / 40.0
    else:
        tol = float(tolerance)
        if not (tol > 0):
            raise InputError(f"{what}: tolerance must be positive, got {tolerance!r}")
    curves: list[tuple[np.ndarray, bool, str | None]] = []
    for el, label in shapes:
        p = se.Path(el)
        for sub in p.as_subpaths():
            sub = se.Path(sub)
            pts: list[np.ndarray] = []
            closed = False
            for seg in sub:
                if isinstance(seg, se.Move):
                    pts = [np.array([[seg.end.x, seg.end.y]], dtype=float)]
                    continue
                if isinstance(seg, se.Close):
                    closed = True
                    continue
                pts.append(_flatten(seg, tol))
            if not pts:
                continue
            xy = np.concatenate(pts)
            if len(xy) > 1 and np.allclose(xy[0], xy[-1]):
                closed = True
                xy = xy[:-1]
            if len(xy) < 2:
                continue
            curves.append((xy, closed, label))
    return curves, points

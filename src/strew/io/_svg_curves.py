"""SVG drawings as labelled curves and points: the reading behind ``program.import_svg``
(Loi et al. 2015, Table 5: ImportSVG), a thin layer over the exemplar reader (issue 15
point 5).

The document is read as :func:`strew.io.svg.read_svg` reads it (:class:`._svg_tree._Doc`):
the same size, path-count and coordinate limits, ``.svgz`` within the same file-size
limit, the same tree walk (layers, groups, ``<use>`` of objects and symbols, hidden
layers and objects), and the same flattening (:mod:`._svg_flatten`, a chord-error bound
after all transforms). Positions are in the document's *user units*, the numbers the
file is written in (the root's ``viewBox`` and ``width``/``height`` are ignored), as in
every other strew reading of SVG.

What differs from the exemplar reading is only what is made of the drawn parts: every
sub-path of every drawn part is one curve (no kinds, no poses), and a labelled
``<circle>`` or ``<ellipse>`` is a labelled point.

Before issue 15, ``import_svg`` read curves through svgelements' reified geometry: a
second reading of SVG, in *viewport* coordinates (a ``viewBox="0 -20 200 40"`` moved
every curve down by 20, a ``width`` in mm scaled it), with curves sampled every
``tolerance`` of arc length (default 1/40 of the drawing's diagonal), and of the
reader's limits only the file size. Now ``tolerance`` is the chord-error bound of every
strew reading of SVG; the default, 1/2000 of the diagonal, gives the example drawings
about as many points as before (blob 92 -> 84, wiggles 133 -> 107, puzzle tab 29 -> 45), and a step
of 2 on the petal's circle of radius 13 (42 points) is ``tolerance=0.04`` (the same 42
points). The example scripts of ``examples/program`` place every imported curve through
its labelled points (``match_points``, ``match_point``, ``match_face``), so the viewBox
offset does not move them; only the sample points of curved segments differ (by at
most 0.25 of the drawings' units, the puzzle tab's).
"""

from __future__ import annotations

import math
import os
import xml.etree.ElementTree as ET
from collections.abc import Callable
from typing import Any

import numpy as np

from .._errors import InputError
from ._svg_flatten import ARC
from ._svg_tree import _AUTO_ID, _IDENTITY, HIDDEN_CHOICES, _apply, _Doc, _guarded, _href, _label, _local, _Part

__all__ = ["read_svg_curves", "DEFAULT_RELATIVE_TOLERANCE"]

#: The default ``tolerance`` as a fraction of the drawing's diagonal: a curve 200 units
#: across is flattened within 0.1 units of itself.
DEFAULT_RELATIVE_TOLERANCE = 1 / 2000


def _curve_label(el: ET.Element | None) -> str | None:
    """An element's Inkscape label, or else its id when that is not an editor's automatic
    one (``path123``: the exemplar reader's rule, :data:`._svg_tree._AUTO_ID`)."""
    if el is None:
        return None
    lab = _label(el)
    if lab is not None and lab.strip():
        return lab.strip()
    ident = el.get("id")
    if ident and ident.strip() and not _AUTO_ID.match(ident.strip()):
        return ident.strip()
    return None


def _drawn(doc: _Doc, hidden: str) -> list[tuple[_Part, str | None]]:
    """The drawn parts of the document, each with the label of the object it belongs to."""
    out: list[tuple[_Part, str | None]] = []
    for what, el, m, _ in doc.walk(hidden):
        void = what.startswith("void-")
        if void and hidden == "skip":
            continue  # a hidden object draws nothing
        # an object's label labels its parts that have none: a labelled group, or a
        # clone (its own label, else that of what it clones)
        label = _curve_label(el)
        if label is None and _local(el.tag) == "use":
            ref = _href(el)
            label = _curve_label(doc.ids.get(ref) if ref else None)
        out.extend((part, label) for part in doc.parts(el, m, {}, show=void))
    return out


def _default_tolerance(doc: _Doc, parts: list[_Part]) -> float:
    """:data:`DEFAULT_RELATIVE_TOLERANCE` of the diagonal of the points that define the
    drawn segments (ends and control points; an arc's centre give or take its radius)."""
    boxes = []
    for part in parts:
        if part.label is not None:
            continue
        segs = doc.segments(part.el)
        if not len(segs.code):
            continue
        arc = segs.code == ARC
        # ends and control points; an arc by its ends and its centre give or take its radius
        pts = np.concatenate([segs.pts[~arc].reshape(-1, 2), segs.pts[arc][:, [0, 3]].reshape(-1, 2)])
        if arc.any():
            r = np.max(np.abs(segs.arc[arc, :2]), axis=1)[:, None]
            pts = np.concatenate([pts, segs.pts[arc, 1] - r, segs.pts[arc, 1] + r])
        lo, hi = np.nanmin(pts, axis=0), np.nanmax(pts, axis=0)
        corners = _apply(part.m, np.array([lo, [lo[0], hi[1]], hi, [hi[0], lo[1]]]))
        boxes.append(np.r_[corners.min(axis=0), corners.max(axis=0)])
    if not boxes:
        return 1.0
    b = np.array(boxes)
    diag = math.hypot(b[:, 2].max() - b[:, 0].min(), b[:, 3].max() - b[:, 1].min())
    return max(diag, 1e-9) * DEFAULT_RELATIVE_TOLERANCE if math.isfinite(diag) else 1.0


@_guarded
def _read(source: Any, tolerance: float | None, hidden: str, should_cancel: Callable[[], bool] | None) -> tuple[list[tuple[np.ndarray, bool, str | None]], dict[str, tuple[float, float]]]:
    # the document's own tolerance only decides which groups are one object (their
    # parts are the same either way); the curves are flattened with the one chosen below
    doc = _Doc(source, 1.0 if tolerance is None else tolerance, should_cancel, hidden)
    drawn = _drawn(doc, hidden)
    doc.warn_dangling()
    tol = _default_tolerance(doc, [p for p, _ in drawn]) if tolerance is None else doc.tolerance
    points: dict[str, tuple[float, float]] = {}
    lines: list[tuple[_Part, str | None]] = []
    for part, outer in drawn:
        tag = _local(part.el.tag)
        own = _curve_label(part.el)
        if part.label is not None or (own is not None and tag in ("circle", "ellipse")):
            # a labelled point: a circle with data-label (strew's convention), or a
            # labelled circle or ellipse (an artist's "start", "end", "center")
            name = part.label if part.label is not None else own
            c = _apply(part.m, np.array([[doc.length(part.el, "cx"), doc.length(part.el, "cy")]]))[0]
            points[str(name)] = (float(c[0]), float(c[1]))
        else:
            lines.append((part, own if own is not None else outer))
    # every part flattened in one batch, as the exemplar reader does (the same paths as
    # doc.flatten part by part)
    flats = doc.flatten_all([([part], tol) for part, _ in lines])
    curves = [(path.points, bool(path.closed), label) for (_, label), flat in zip(lines, flats) for path in flat.paths]
    return curves, points


def read_svg_curves(
    source: str | bytes | os.PathLike[str],
    *,
    tolerance: float | None = None,
    hidden: str = "skip",
    should_cancel: Callable[[], bool] | None = None,
    what: str = "svg",
) -> tuple[list[tuple[np.ndarray, bool, str | None]], dict[str, tuple[float, float]]]:
    """Curves and labelled points of an SVG drawing, in its user units, every transform applied.

    The document is read as :func:`read_svg` reads an exemplar (the same limits, tree
    walk, clones and flattening; see the module docstring). Every sub-path of every
    drawn path or basic shape is one curve, flattened to a polyline; it is closed when it
    ends in ``Z`` or when it has at least four points and its ends meet (the last point
    is then dropped). A curve's label is its element's Inkscape label, or else the
    element's id when the id is not an editor's automatic one (``path123``), or else the
    label of the object it belongs to (a labelled group, or a clone and what it clones).
    A labelled ``<circle>`` or ``<ellipse>`` (or a ``<circle data-label=...>``) is a
    labelled point at its centre instead.

    Parameters
    ----------
    source : path, or SVG text (a ``str`` starting with ``<``, or bytes)
    tolerance : float, optional
        Largest distance, in user units after all transforms, between a curve and its
        flattening (as in :func:`read_svg`). Default: 1/2000 of the diagonal of the
        drawing's extent (its end and control points). Straight segments are kept as
        they are at any tolerance.
    hidden : {"skip", "include"}
        Hidden (``display:none``) layers, groups and objects: ``"skip"`` (default) reads
        only what is drawn, as :func:`read_svg_region` does; ``"include"`` reads them as
        if shown.
    should_cancel : callable () -> bool, optional
        Polled after parsing and once per object (raises :class:`~strew._errors.Cancelled`).
    what : str
        Names the caller at the start of every message (``import_svg``).

    Returns
    -------
    curves : list of ((k, 2) float, bool, str or None)
        Points (``k >= 2``), closed, label; in document order.
    points : dict of str to (float, float)
        Labelled points.

    Raises
    ------
    InputError
        Malformed XML, a file over the size or path limits, coordinates over
        ``MAX_COORD``, a bad ``tolerance`` or ``hidden``.

    Examples
    --------
    >>> curves, points = read_svg_curves(
    ...     '<svg xmlns="http://www.w3.org/2000/svg" viewBox="-50 -50 100 100">'
    ...     '<path id="arm" d="M 0 0 L 20 0"/><circle id="center" r="2"/></svg>')
    >>> [(xy.tolist(), closed, label) for xy, closed, label in curves], points
    ([([[0.0, 0.0], [20.0, 0.0]], False, 'arm')], {'center': (0.0, 0.0)})
    """
    if tolerance is not None and (isinstance(tolerance, bool) or not isinstance(tolerance, (int, float)) or not (math.isfinite(tolerance) and tolerance > 0)):
        raise InputError(f"{what}: tolerance: must be a positive number, got {tolerance!r}")
    if hidden not in HIDDEN_CHOICES:
        raise InputError(f"{what}: hidden: expected one of {', '.join(HIDDEN_CHOICES)}, got {hidden!r}")
    try:
        return _read(source, tolerance, hidden, should_cancel)
    except InputError as exc:
        if str(exc).startswith(f"{what}: "):
            raise
        raise type(exc)(f"{what}: {exc}") from None

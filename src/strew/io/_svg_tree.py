"""SVG import, the document: parsing, the rendering tree and the flattening of its parts.

:class:`_Doc` parses an SVG (or ``.svgz``) within the size and path-count limits
(:mod:`strew._limits`), indexes its ids and parents, reads transforms and lengths, walks
the rendering tree into the top-level objects that become elements (:meth:`_Doc.walk`:
containers, layers, hidden layers and the region), expands an object into its drawable
parts with their maps (clones and symbols included, :meth:`_Doc.parts`) and flattens
parts into paths (:meth:`_Doc.flatten`, and :meth:`_Doc.flatten_all` for many objects
in one batch of :mod:`._svg_flatten`). See :mod:`._svg_import` for how objects become
elements and kinds.
"""

from __future__ import annotations

import gc
import gzip
import json
import math
import os
import re
import warnings
import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path as FsPath
from typing import Any

import numpy as np

from .._errors import Cancelled, InputError
from .._limits import MAX_COORD, check_decompressed, check_file, check_paths, check_text, get_limit
from ..shape import Path
from ._svg_flatten import EMPTY as _EMPTY
from ._svg_flatten import _fmt
from ._svg_flatten import Segments, flatten, flatten_many, from_svgelements, parse_path, parse_transform, path_d, points_many, shape_segments, too_large
from ._svg_match import _SIGNATURE_TOLERANCE, _Signature, _connected, _geometry, _signatures

__all__ = ["HIDDEN_CHOICES", "SVGImportWarning"]

#: What to do with objects in hidden (``display:none``) layers and groups.
HIDDEN_CHOICES = ("include", "skip")


class SVGImportWarning(UserWarning):
    """Something in an SVG was skipped (a ``<use>`` of a missing id)."""

SVG_NS = "http://www.w3.org/2000/svg"
XLINK_NS = "http://www.w3.org/1999/xlink"
INKSCAPE_NS = "http://www.inkscape.org/namespaces/inkscape"
STREW_NS = "urn:strew:document"

_SHAPE_TAGS = {"path", "rect", "circle", "ellipse", "line", "polyline", "polygon"}
_GROUP_TAGS = {"g", "a", "switch", "svg"}
# The attributes that give a basic shape's or path's geometry: an object that carries no
# other (no id, name, transform, style or data) needs none of their lookups (issue 17.3)
_GEOMETRY_ATTRS = {
    "path": frozenset({"d"}),
    "rect": frozenset({"x", "y", "width", "height", "rx", "ry"}),
    "circle": frozenset({"cx", "cy", "r"}),
    "ellipse": frozenset({"cx", "cy", "rx", "ry"}),
    "line": frozenset({"x1", "y1", "x2", "y2"}),
    "polyline": frozenset({"points"}),
    "polygon": frozenset({"points"}),
}
# Not rendered in place (or not geometry strew can use).
_SKIP_TAGS = {
    "defs", "symbol", "metadata", "title", "desc", "style", "script", "clipPath", "mask",
    "pattern", "marker", "linearGradient", "radialGradient", "filter", "text", "image",
    "foreignObject", "view", "cursor", "font", "font-face",
}
_AUTO_ID = re.compile(
    r"^(path|rect|circle|ellipse|line|polyline|polygon|g|group|use|clone|symbol|svg|layer|"
    r"text|tspan|image|defs|shape|object|copy)[-_]?\d*([-_]\d+)*$",
    re.IGNORECASE,
)
_UNITS = {"": 1.0, "px": 1.0, "mm": 96 / 25.4, "cm": 96 / 2.54, "in": 96.0, "pt": 96 / 72, "pc": 16.0}
_LENGTH = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([a-z]*)\s*$")
_IDENTITY = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])


# -- small helpers --------------------------------------------------------------------
def _local(tag: Any) -> str | None:
    """Local name of an SVG-namespace (or un-namespaced) tag; None for other namespaces."""
    try:
        return _LOCAL[tag]  # asked for every object several times (issue 17.3)
    except (KeyError, TypeError):
        pass
    if not isinstance(tag, str):  # comments, processing instructions
        return None
    if tag.startswith("{"):
        ns, _, name = tag[1:].partition("}")
        local = name if ns == SVG_NS else None
    else:
        local = tag
    if len(_LOCAL) < 4096:
        _LOCAL[tag] = local
    return local


_LOCAL: dict[str, str | None] = {}  # tag -> _local(tag), for the tags seen so far (a few dozen)


def _compose(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """2x3 affine ``a @ b`` (apply ``b`` first), in floats (a third of numpy's cost on 2x3)."""
    (a00, a01, a02), (a10, a11, a12) = a.tolist()
    (b00, b01, b02), (b10, b11, b12) = b.tolist()
    return np.array([[a00 * b00 + a01 * b10, a00 * b01 + a01 * b11, a00 * b02 + a01 * b12 + a02],
                     [a10 * b00 + a11 * b10, a10 * b01 + a11 * b11, a10 * b02 + a11 * b12 + a12]])


def _det(m: np.ndarray) -> float:
    """Determinant of the 2x2 linear part of a 2x3 map."""
    return float(m[0, 0]) * float(m[1, 1]) - float(m[0, 1]) * float(m[1, 0])


def _invert(m: np.ndarray) -> np.ndarray:
    """Inverse of a 2x3 affine map (closed form for the 2x2 part)."""
    a, b, c, d = float(m[0, 0]), float(m[0, 1]), float(m[1, 0]), float(m[1, 1])
    det = a * d - b * c
    if det == 0:
        raise np.linalg.LinAlgError("singular matrix")
    ia, ib, ic, id_ = d / det, -b / det, -c / det, a / det
    e, f = float(m[0, 2]), float(m[1, 2])
    return np.array([[ia, ib, -(ia * e + ib * f)], [ic, id_, -(ic * e + id_ * f)]])


def _translate(x: float, y: float) -> np.ndarray:
    return np.array([[1.0, 0.0, x], [0.0, 1.0, y]])


def _apply(m: np.ndarray, pts: np.ndarray) -> np.ndarray:
    return pts @ m[:, :2].T + m[:, 2]


def _sigma_max(m: np.ndarray) -> float:
    """Largest singular value of the 2x2 linear part (closed form; ``np.linalg.norm(., 2)`` runs an SVD)."""
    a, b, c, d = float(m[0, 0]), float(m[0, 1]), float(m[1, 0]), float(m[1, 1])
    q = a * a + b * b + c * c + d * d
    det = a * d - b * c
    return math.sqrt(max(0.0, (q + math.sqrt(max(0.0, q * q - 4 * det * det))) / 2))


def _similarity(lin: np.ndarray) -> tuple[float, float]:
    """Rotation (radians) and scale of the similarity closest to a 2x2 matrix (least squares)."""
    (a, b), (c, d) = lin.tolist()
    p, q = a + d, c - b
    return math.atan2(q, p), math.hypot(p, q) / 2


def _parse_style(text: str | None) -> dict[str, str]:
    out: dict[str, str] = {}
    for item in (text or "").split(";"):
        key, sep, val = item.partition(":")
        if sep:
            out[key.strip()] = val.strip()
    return out


def _props(el: ET.Element) -> dict[str, str]:
    """Presentation properties of an element: attributes, overridden by ``style``."""
    props = {k: v for k in ("fill", "stroke", "stroke-width", "display", "fill-rule") if (v := el.get(k)) is not None}
    style = el.get("style")
    if style:
        props.update({k: v for k, v in _parse_style(style).items() if k in ("fill", "stroke", "stroke-width", "display", "fill-rule")})
    return props


def _hidden(el: ET.Element) -> bool:
    style = el.get("style")
    if el.get("display") is None and (style is None or "display" not in style):
        return False  # most objects: no display property at all
    return _props(el).get("display", "").strip() == "none"


def _label(el: ET.Element) -> str | None:
    return el.get(f"{{{INKSCAPE_NS}}}label")


def _is_layer(el: ET.Element) -> bool:
    return el.get(f"{{{INKSCAPE_NS}}}groupmode") == "layer"


def _href(el: ET.Element) -> str | None:
    ref = el.get(f"{{{XLINK_NS}}}href") or el.get("href")
    if ref is None:
        return None
    ref = ref.strip()
    return ref[1:] if ref.startswith("#") else ref


def _key_of(el: ET.Element) -> str | None:
    """The name an artist gave an object: ``data-kind``, ``inkscape:label`` or a chosen id."""
    for key in (el.get("data-kind"), _label(el)):
        if key is not None and key.strip():
            return key.strip()
    ident = el.get("id")
    if ident and not _AUTO_ID.match(ident):
        # ids are unique, so artists number them: stone-1, stone-2 name one kind "stone".
        base = re.sub(r"[-_.]?\d+$", "", ident)
        return base or ident
    return None


def _name_of_target(el: ET.Element) -> str | None:
    """Kind name of a cloned symbol or object: its ``data-kind``, label or id."""
    for key in (el.get("data-kind"), _label(el), el.get("id")):
        if key is not None and key.strip():
            return key.strip()
    return None


def _is_region_el(el: ET.Element, strew_doc: bool) -> bool:
    """The region: id ``strew-region``; outside strew's own files also id or label ``region``."""
    ident = (el.get("id") or "").lower()
    if strew_doc:  # in a strew export a kind may be called "region": only the layer's id counts
        return ident == "strew-region"
    return ident in ("region", "strew-region") or (_label(el) or "").lower() == "region"


# -- the document -----------------------------------------------------------------------
@dataclass
class _Part:
    """One drawable leaf (or a label point) with its map to the frame it is read in."""

    el: ET.Element
    m: np.ndarray  # (2, 3) element coordinates -> frame
    props: dict[str, str]
    label: str | None = None  # a ``<circle data-label=..>``: a named point, not geometry


@dataclass
class _Flat:
    """Flattened parts: paths in the frame, labels, and whether any segment was a curve."""

    paths: list[Path]
    labels: dict[str, tuple[float, float]]
    curves: bool
    bounds: tuple[float, float, float, float] | None = None  # of the paths' points, where known


class _Doc:
    def __init__(self, source: Any, tolerance: float, should_cancel: Callable[[], bool] | None = None, hidden: str = "include") -> None:
        if should_cancel is not None and not callable(should_cancel):
            raise InputError(f"should_cancel: must be callable, got {type(should_cancel).__name__}")
        if hidden not in HIDDEN_CHOICES:
            raise InputError(f"hidden: expected one of {', '.join(HIDDEN_CHOICES)}, got {hidden!r}")
        self.hidden = hidden
        # <use>s whose target is missing: skipped, and named in one warning (issue 22)
        self.dangling: list[str] = []
        self.should_cancel = should_cancel
        if isinstance(tolerance, bool) or not isinstance(tolerance, (int, float)) or not (math.isfinite(tolerance) and tolerance > 0):
            raise InputError(f"tolerance: must be a positive number, got {tolerance!r}")
        self.tolerance = float(tolerance)
        self.name, text = _source_text(source)
        check_text(text, self.name)
        # Refuse too many objects before parsing (a 30 MB file of 687k paths took 6 s to
        # parse only to be refused): start tags are "<" less "</", "<!" and "<?"; a "<"
        # in a comment or CDATA counts too, so this can only overstate, by those.
        lt, close, bang, pi = (b"<", b"</", b"<!", b"<?") if isinstance(text, bytes) else ("<", "</", "<!", "<?")
        tags = text.count(lt) - text.count(close) - text.count(bang) - text.count(pi)  # type: ignore[arg-type]
        if tags > get_limit("paths"):
            check_paths(tags, self.name)
        try:
            self.root = ET.fromstring(text)
        except ET.ParseError as exc:
            raise InputError(f"{self.name}: malformed XML: {exc}") from None
        # Work grows with the number of objects; refuse documents beyond the limit.
        check_paths(sum(1 for _ in self.root.iter()), self.name)
        self.poll()
        if _local(self.root.tag) != "svg":
            raise InputError(f"{self.name}: not an SVG document (root element is <{self.root.tag}>)")
        self.parent: dict[ET.Element, ET.Element] = {}
        self.ids: dict[str, ET.Element] = {}
        for el in self.root.iter():
            for child in el:
                self.parent[child] = el
            ident = el.get("id")
            if ident is not None and ident not in self.ids:
                self.ids[ident] = el
        self.meta: dict[str, Any] | None = None
        for md in self.root.iter(f"{{{SVG_NS}}}metadata"):
            # strew writes meta as JSON in <dc:description id="strew-meta"> (older: <strew:meta>).
            for node in md.iter():
                if node.get("id") != "strew-meta" and node.tag != f"{{{STREW_NS}}}meta":
                    continue
                try:
                    meta = json.loads(node.text or "{}")
                except json.JSONDecodeError as exc:
                    raise InputError(f"{self.name}: <strew:meta>: malformed JSON: {exc.msg}") from None
                if not isinstance(meta, dict):
                    raise InputError(f"{self.name}: <strew:meta>: must be a JSON object")
                self.meta = meta
        # A document written by strew keeps each symbol's own origin as the local origin.
        self.is_strew = self.meta is not None
        self._transforms: dict[int, np.ndarray] = {}
        # svgelements' parse of each element's geometry, done once: an object is flattened
        # two to four times (kind test, signature, shape) and a symbol once per clone.
        self._segments: dict[int, Segments] = {}
        self._inherited: dict[int, dict[str, str]] = {}  # id(element) -> the properties its children inherit
        self.referenced = {_href(el) for el in self.root.iter() if _local(el.tag) == "use"}

    def poll(self) -> None:
        """Raise :class:`~strew._errors.Cancelled` when the caller's ``should_cancel`` says so.

        Called once per top-level object (and after parsing), so a load stops within the
        cost of one object.
        """
        if self.should_cancel is not None and self.should_cancel():
            raise Cancelled(f"{self.name}: SVG import cancelled")

    # -- transforms ---------------------------------------------------------------------
    def transform(self, el: ET.Element) -> np.ndarray:
        """(2, 3) the element's own ``transform`` (and a nested ``<svg>``'s x, y)."""
        key = id(el)
        cached = self._transforms.get(key)
        if cached is not None:
            return cached
        m = _IDENTITY
        text = el.get("transform")
        if text and text.strip():
            fast = parse_transform(text)
            if fast is not None:
                m = fast
            else:  # units, CSS functions, stray text: svgelements' reading
                import svgelements as se

                try:
                    sm = se.Matrix(text)
                except (ValueError, IndexError, TypeError):
                    raise InputError(f"{self.name}: {self.where(el)}: bad transform {text!r}") from None
                m = np.array([[sm.a, sm.c, sm.e], [sm.b, sm.d, sm.f]], dtype=float)
            if not all(map(math.isfinite, m.ravel().tolist())):
                raise InputError(f"{self.name}: {self.where(el)}: transform {text!r} is not finite")
        if _local(el.tag) == "svg" and el is not self.root:
            # A nested <svg> is read as a group moved by (x, y); its viewBox is ignored.
            m = _compose(m, _translate(self.length(el, "x"), self.length(el, "y")))
        self._transforms[key] = m
        return m

    def world(self, el: ET.Element) -> np.ndarray:
        """(2, 3) map from the element's own coordinates (after its transform) to user units.

        The root's viewBox and size are ignored: positions are in the root's user units.
        """
        m = _IDENTITY
        node: ET.Element | None = el
        while node is not None and node is not self.root:
            m = _compose(self.transform(node), m)
            node = self.parent.get(node)
        return m

    def where(self, el: ET.Element) -> str:
        ident = el.get("id")
        tag = _local(el.tag) or str(el.tag)
        return f"<{tag} id={ident!r}>" if ident else f"<{tag}>"

    def length(self, el: ET.Element, attr: str, default: float = 0.0) -> float:
        text = el.get(attr)
        if text is None or not text.strip():
            return default
        m = _LENGTH.match(text)
        if not m or m.group(2) not in _UNITS:
            raise InputError(f"{self.name}: {self.where(el)}: {attr}={text!r} is not a length in user units")
        v = float(m.group(1)) * _UNITS[m.group(2)]
        if not math.isfinite(v):
            raise InputError(f"{self.name}: {self.where(el)}: {attr}={text!r} is not finite")
        return v

    def target(self, use: ET.Element) -> ET.Element | None:
        """The element a ``<use>`` refers to; None (recorded in :attr:`dangling`) when it is missing.

        A clone of something that is not there draws nothing in a browser or Inkscape, so
        it is skipped with a warning rather than rejecting the file (Inkscape's own
        ``AigaSymbols.svg`` has one).
        """
        ref = _href(use)
        tgt = self.ids.get(ref) if ref else None
        if tgt is None:
            what = f"{self.where(use)} without href" if not ref else f"{self.where(use)} refers to missing #{ref}"
            if what not in self.dangling:
                self.dangling.append(what)
        return tgt

    def warn_dangling(self) -> None:
        """One warning naming the skipped ``<use>`` elements, if any."""
        if self.dangling:
            n = len(self.dangling)
            listed = "; ".join(self.dangling[:3]) + ("; ..." if n > 3 else "")
            warnings.warn(f"{self.name}: skipped {n} <use> element{'s' if n > 1 else ''} whose target is missing: {listed}", SVGImportWarning, stacklevel=4)

    def missing_note(self) -> str:
        """For a 'no shapes found' message: the clones that were skipped."""
        return f"; skipped: {'; '.join(self.dangling[:3])}" if self.dangling else ""

    def use_matrix(self, use: ET.Element, outer: np.ndarray) -> np.ndarray:
        """Map from the referenced element's coordinates to ``outer``'s frame."""
        t = self.transform(use)
        m = outer if t is _IDENTITY else _compose(outer, t)
        x, y = self.length(use, "x"), self.length(use, "y")
        return m if x == 0.0 and y == 0.0 else _compose(m, _translate(x, y))

    def symbol_viewport(self, use: ET.Element, symbol: ET.Element) -> np.ndarray:
        """Map from a symbol's viewBox to the viewport a ``<use>`` gives it (identity without one).

        Only a viewBox with an explicit ``width`` and ``height`` on the use (or the symbol)
        is honoured, with the default ``preserveAspectRatio`` (xMidYMid meet); anything
        else keeps the symbol's own coordinates.
        """
        box = (symbol.get("viewBox") or "").replace(",", " ").split()
        w = use.get("width") or symbol.get("width")
        h = use.get("height") or symbol.get("height")
        if len(box) != 4 or w is None or h is None or "%" in w or "%" in h:
            return _IDENTITY
        try:
            bx, by, bw, bh = (float(v) for v in box)
        except ValueError:
            return _IDENTITY
        holder = use if use.get("width") is not None else symbol
        vw, vh = self.length(holder, "width"), self.length(holder, "height")
        if not (bw > 0 and bh > 0 and vw > 0 and vh > 0):
            return _IDENTITY
        k = min(vw / bw, vh / bh)
        if (symbol.get("preserveAspectRatio") or "").strip().startswith("none"):
            return np.array([[vw / bw, 0.0, -bx * vw / bw], [0.0, vh / bh, -by * vh / bh]])
        return np.array([[k, 0.0, (vw - k * bw) / 2 - k * bx], [0.0, k, (vh - k * bh) / 2 - k * by]])

    # -- parts --------------------------------------------------------------------------
    def parts(self, el: ET.Element, m: np.ndarray, props: dict[str, str], stack: tuple[int, ...] = (), show: bool = False) -> list[_Part]:
        """Drawable leaves below ``el`` (clones expanded); ``m`` maps ``el``'s parent frame.

        ``show`` reads ``el`` itself as if shown (a hidden object read as hidden or void).
        """
        tag = _local(el.tag)
        if tag is None or tag in _SKIP_TAGS:  # a <symbol> is drawn only through a <use>
            return []
        own = _props(el)
        if tag == "circle" and el.get("data-label") is not None:
            return [_Part(el, _compose(m, self.transform(el)), props, label=el.get("data-label"))]
        if own.get("display", "").strip() == "none" and not show:
            return []
        props = {**props, **{k: v for k, v in own.items() if k != "display"}}
        if tag in _SHAPE_TAGS:
            return [_Part(el, _compose(m, self.transform(el)), props)]
        if tag == "use":
            if id(el) in stack:
                raise InputError(f"{self.name}: {self.where(el)}: <use> refers to itself")
            tgt = self.target(el)
            if tgt is None:
                return []
            inner = self.use_matrix(el, m)
            if _local(tgt.tag) == "symbol":
                view = self.symbol_viewport(el, tgt)
                inner = inner if view is _IDENTITY else _compose(inner, view)
                return [p for child in tgt for p in self.parts(child, inner, props, (*stack, id(el)))]
            return self.parts(tgt, inner, props, (*stack, id(el)))
        if tag in _GROUP_TAGS:
            inner = _compose(m, self.transform(el))
            return [p for child in el for p in self.parts(child, inner, props, stack)]
        return []

    def group_key(self, el: ET.Element) -> str | None:
        """``data-kind`` of the nearest layer or group around ``el`` (strew's kind layers carry one)."""
        node = self.parent.get(el)
        while node is not None and node is not self.root:
            key = node.get("data-kind")
            if key is not None and key.strip():
                return key.strip()
            node = self.parent.get(node)
        return None

    def inherited_props(self, el: ET.Element) -> dict[str, str]:
        """Presentation properties ``el`` inherits from its ancestors (``display`` left out).

        Each ancestor's are computed once (issue 17.3: objects of one layer share them).
        """
        chain = []
        node = self.parent.get(el)
        cache = self._inherited
        while node is not None and id(node) not in cache:
            chain.append(node)
            node = self.parent.get(node)
        props: dict[str, str] = dict(cache[id(node)]) if node is not None else {}
        for node in reversed(chain):
            props.update({k: v for k, v in _props(node).items() if k != "display"})
            cache[id(node)] = dict(props)
        return props

    def flatten(self, parts: list[_Part], frame: np.ndarray, tolerance: float) -> _Flat:
        """Flatten parts into ``frame`` (a 2x3 map applied after each part's own map)."""
        paths: list[Path] = []
        labels: dict[str, tuple[float, float]] = {}
        curves = False
        for part in parts:
            m = _compose(frame, part.m)
            if part.label is not None:
                pt = _apply(m, np.array([[self.length(part.el, "cx"), self.length(part.el, "cy")]]))[0]
                labels[part.label] = (float(pt[0]), float(pt[1]))
                continue
            smax = _sigma_max(m)
            if smax == 0:
                continue
            for pts, closed, curved in self.flatten_element(part.el, tolerance / smax):
                curves |= curved
                paths.append(Path(_apply(m, pts), closed))
        return _Flat(paths, labels, curves)

    def flatten_all(self, jobs: list[tuple[list[_Part], float]], checked: bool = False) -> list[_Flat]:
        """``[self.flatten(parts, _IDENTITY, tol) for parts, tol in jobs]``, the curves of
        every part sampled in one :func:`._svg_flatten.flatten_many` call (issue 17.3).

        The same paths, point for point; the first part whose coordinates are too large
        raises, as in the loop (``checked``: the caller has made sure none is).
        """
        tables: list[Segments] = []
        tols: list[float] = []
        where: list[tuple[int, np.ndarray]] = []
        labels: list[dict[str, tuple[float, float]]] = [{} for _ in jobs]
        for i, (parts, tol) in enumerate(jobs):
            for part in parts:
                m = part.m
                if part.label is not None:
                    pt = _apply(m, np.array([[self.length(part.el, "cx"), self.length(part.el, "cy")]]))[0]
                    labels[i][part.label] = (float(pt[0]), float(pt[1]))
                    continue
                smax = 1.0 if m is _IDENTITY else _sigma_max(m)
                if smax == 0:
                    continue
                segs = self.segments(part.el)
                if not checked and too_large(segs, MAX_COORD):
                    raise InputError(f"{self.name}: {self.where(part.el)}: coordinate magnitude over {MAX_COORD:.0e}")
                tables.append(segs)
                tols.append(tol / smax)
                where.append((i, m))
        paths: list[list[Path]] = [[] for _ in jobs]
        curves = [False] * len(jobs)
        # the identity (objects drawn in the root's frame) maps each point to itself + 0.0,
        # bit for bit (-0.0 becomes 0.0, as in the product): added to all points at once
        ident = all(m is _IDENTITY for _, m in where)
        for (i, m), flat in zip(where, flatten_many(tables, np.array(tols), plus_zero=ident)):
            for pts, closed, curved in flat:
                curves[i] |= curved
                paths[i].append(Path(pts if ident else pts + 0.0 if m is _IDENTITY else _apply(m, pts), closed))
        return [_Flat(p, lab, c) for p, lab, c in zip(paths, labels, curves)]

    def segments(self, el: ET.Element) -> Segments:
        """Segments of a path or basic shape, in the element's coordinates (parsed once)."""
        key = id(el)
        segs = self._segments.get(key)
        if segs is None:
            segs = self._segments[key] = self._parse_segments(el)
        return segs

    def preparse(self, els: list[ET.Element]) -> None:
        """Parse the ``points`` of many polygons and polylines at once into the cache of
        :meth:`segments` (:func:`._svg_flatten.points_many`); what that leaves (unusual
        text) is parsed one by one when asked for."""
        els = [el for el in els if id(el) not in self._segments]
        if not els:
            return
        cache = self._segments
        # in blocks of 4096 (each text's reading is its own; one block's arrays stay small)
        for lo in range(0, len(els), 4096):
            block = els[lo : lo + 4096]
            found = points_many([el.get("points") or "" for el in block], [_local(el.tag) == "polygon" for el in block])
            if found is None:
                continue
            for el, segs in zip(block, found):
                if segs is not None:
                    cache[id(el)] = segs

    def _parse_segments(self, el: ET.Element) -> Segments:
        tag = _local(el.tag)
        try:
            if tag == "path":
                d = el.get("d") or ""
                fast = parse_path(d)
                return fast if fast is not None else self._svgelements(el, d)
            if tag not in ("rect", "circle", "ellipse", "line", "polyline", "polygon"):
                return _EMPTY
            names = {"rect": ("x", "y", "width", "height"), "circle": ("cx", "cy", "r"), "ellipse": ("cx", "cy", "rx", "ry"),
                     "line": ("x1", "y1", "x2", "y2")}.get(tag, ())
            # rounded to 12 digits, as the numbers svgelements was given
            num = {a: float(_fmt(self.length(el, a))) for a in names}
            if tag == "rect":
                if num["width"] <= 0 or num["height"] <= 0:
                    return _EMPTY
                if el.get("rx") is not None or el.get("ry") is not None:
                    return self._svgelements(el, None)
            elif tag == "circle" and num["r"] <= 0:
                return _EMPTY
            elif tag == "ellipse" and (num["rx"] <= 0 or num["ry"] <= 0):
                return _EMPTY
            fast = shape_segments(tag, num, el.get("points"))
            return fast if fast is not None else self._svgelements(el, None)
        except InputError:
            raise
        except Exception as exc:  # bad numbers
            raise InputError(f"{self.name}: {self.where(el)}: cannot read its geometry ({type(exc).__name__})") from None

    def _svgelements(self, el: ET.Element, d: str | None) -> Segments:
        """svgelements' reading of what :mod:`._svg_flatten` leaves to it (odd path data, rounded rects)."""
        import svgelements as se

        tag = _local(el.tag)
        try:
            if d is not None:
                return from_svgelements(list(se.Path(d).segments()))
            num = {a: _fmt(self.length(el, a)) for a in ("x", "y", "width", "height")}
            if tag == "rect":
                vals = {k: num[k] for k in ("x", "y", "width", "height")}
                for k in ("rx", "ry"):
                    if el.get(k) is not None:
                        vals[k] = _fmt(self.length(el, k))
                shape = se.Rect(vals)
            elif tag == "polyline":
                shape = se.Polyline({"points": el.get("points") or ""})
            elif tag == "polygon":
                shape = se.Polygon({"points": el.get("points") or ""})
            else:
                return _EMPTY
            return from_svgelements(list(se.Path(shape).segments()))
        except InputError:
            raise
        except Exception as exc:  # svgelements raises assorted errors on bad path data
            raise InputError(f"{self.name}: {self.where(el)}: cannot read its geometry ({type(exc).__name__})") from None

    def flatten_element(self, el: ET.Element, tol: float) -> list[tuple[np.ndarray, bool, bool]]:
        """Subpaths of one element as ``(points (n, 2), closed, curved)`` in its coordinates.

        Curves are sampled uniformly in their parameter with ``n`` steps chosen so that the
        chord error ``h^2 max|B''| / 8`` stays within ``tol`` (all curves of the element in
        one batch, see :func:`._svg_flatten.flatten`).
        """
        segs = self.segments(el)
        if too_large(segs, MAX_COORD):
            raise InputError(f"{self.name}: {self.where(el)}: coordinate magnitude over {MAX_COORD:.0e}")
        return flatten(segs, tol)

    def signature(self, parts: list[_Part], coarse: _Flat) -> _Signature | None:
        """Similarity invariants of ``parts``, flattened relative to their size (see _SIGNATURE_TOLERANCE)."""
        return self.signatures([(parts, coarse)])[0]

    def signatures(self, batch: list[tuple[list[_Part], _Flat]]) -> list[_Signature | None]:
        """:meth:`signature` of many objects, the moments computed in one batch (see :func:`_signatures`)."""
        todo: list[tuple[int, list[Path], float]] = []
        have = [i for i, (_, coarse) in enumerate(batch) if coarse.paths]
        if not have:
            return [None] * len(batch)
        # every object's largest distance from its mean vertex, for all at once: the
        # same sums (numpy adds the rows of an (n, 2) array one after another) and roots
        pts = np.concatenate([p.points for i in have for p in batch[i][1].paths])
        # (one path per object, mostly: its length without a generator)
        count = np.array([len(ps[0].points) if len(ps) == 1 else sum(len(p.points) for p in ps) for ps in (batch[i][1].paths for i in have)])
        start = np.cumsum(count) - count
        mean = np.add.reduceat(pts, start, axis=0) / count[:, None]
        dist = np.sqrt(((pts - np.repeat(mean, count, axis=0)) ** 2).sum(axis=1))
        radii = np.maximum.reduceat(dist, start).tolist()
        for i, radius in zip(have, radii):
            parts, coarse = batch[i]
            if not radius > 0:
                continue
            tol = _SIGNATURE_TOLERANCE * radius
            # without curves the flattening does not depend on the tolerance: reuse it
            todo.append((i, coarse.paths, tol))
        curved = [j for j, (i, _, _) in enumerate(todo) if batch[i][1].curves]
        # these parts were flattened once already, so their coordinates were checked
        for j, fine in zip(curved, self.flatten_all([(batch[todo[j][0]][0], todo[j][2]) for j in curved], checked=True)):
            todo[j] = (todo[j][0], fine.paths, todo[j][2])
        out: list[_Signature | None] = [None] * len(batch)
        for (i, _, tol), sig in zip(todo, _signatures([paths for _, paths, _ in todo])):
            if sig is not None:
                sig.tolerance = tol
                out[i] = sig
        return out

    def path_data(self, parts: list[_Part], frame: np.ndarray) -> str | None:
        """Exact path data of ``parts`` mapped by ``frame``, or None where it cannot be exact.

        A part whose map is the identity keeps its ``d`` text; a similarity map is applied
        to the segments (arcs included); anything else (skew, non-uniform scale,
        reflection) gives None.
        """
        pieces: list[str] = []
        for part in parts:
            if part.label is not None:
                continue
            m = _compose(frame, part.m)
            if _local(part.el.tag) == "path" and np.allclose(m, _IDENTITY, rtol=0, atol=1e-12):
                pieces.append((part.el.get("d") or "").strip())
                continue
            lin = m[:, :2]
            rot, s = _similarity(lin)
            if s == 0 or np.linalg.det(lin) < 0 or not np.allclose(lin, s * np.array([[math.cos(rot), -math.sin(rot)], [math.sin(rot), math.cos(rot)]]), atol=1e-9 * max(1.0, s)):
                return None

            pieces.append(path_d(self.segments(part.el), m, rot, s))
        text = " ".join(p for p in pieces if p)
        return text or None

    # -- the rendering tree -------------------------------------------------------------
    def walk(self, hidden: str | None = None) -> Iterator[tuple[str, ET.Element, np.ndarray, bool]]:
        """Top-level objects in document order: ``(what, element, parent_matrix, in_hidden)``.

        ``what`` is ``"use"``, ``"object"``, ``"void-use"``, ``"void-object"`` or ``"region"``;
        ``in_hidden`` says the object lies in a hidden (``display:none``) layer or group,
        which is walked into with ``hidden="include"`` and skipped with ``"skip"``
        (default: the document's option).
        """
        yield from self._walk_children(self.root, _IDENTITY, hidden or self.hidden, False)

    def _walk_children(self, el: ET.Element, m: np.ndarray, hidden_mode: str, in_hidden: bool) -> Iterator[tuple[str, ET.Element, np.ndarray, bool]]:
        for child in el:
            self.poll()
            tag = _local(child.tag)
            if tag is None or tag in _SKIP_TAGS:
                continue
            if tag not in _SHAPE_TAGS and tag not in _GROUP_TAGS and tag != "use":
                continue
            if tag in _GEOMETRY_ATTRS and not self.is_strew and child.attrib.keys() <= _GEOMETRY_ATTRS[tag]:
                # geometry only: not the region (no id or label), not hidden, no data-label
                yield ("object", child, m, in_hidden)
                continue
            if _is_region_el(child, self.is_strew):
                yield ("region", child, m, in_hidden)
                continue
            if self.is_strew and child.get("id") in ("strew-guides", "strew-wrap"):
                continue  # tool strokes (extra["guides"]) and a repeat tile's wrapped copies, not elements
            if el is self.root and self.is_strew and tag == "rect" and self._is_background(child):
                continue
            hidden = _hidden(child)
            if tag == "use":
                yield ("void-use" if hidden else "use", child, m, in_hidden)
            elif tag in _SHAPE_TAGS:
                if child.get("data-label") is None:
                    yield ("void-object" if hidden else "object", child, m, in_hidden)
            elif hidden and hidden_mode == "skip":
                continue  # a sketch or reference layer, left out on request
            elif hidden and (_is_layer(child) or self._is_container(child, m)):
                # By default a hidden layer or group holds elements an artist has hidden
                # while editing the others (issue 22): they are read, and marked ``hidden``.
                yield from self._walk_children(child, _compose(m, self.transform(child)), hidden_mode, True)
            elif hidden:
                yield ("object", child, m, True)
            elif self._is_container(child, m):
                yield from self._walk_children(child, _compose(m, self.transform(child)), hidden_mode, in_hidden)
            else:
                yield ("object", child, m, in_hidden)

    def _is_background(self, rect: ET.Element) -> bool:
        """Whether a rect covers exactly the viewBox: the background ``to_svg`` may draw."""
        box = (self.root.get("viewBox") or "").replace(",", " ").split()
        try:
            want = [float(v) for v in box]
            got = [self.length(rect, a) for a in ("x", "y", "width", "height")]
        except (ValueError, InputError):
            return False
        return len(want) == 4 and np.allclose(got, want, rtol=1e-9, atol=1e-9)

    def _is_container(self, el: ET.Element, m: np.ndarray) -> bool:
        if el is self.root or _is_layer(el) or _local(el.tag) in ("a", "switch"):
            return True
        if el.get("data-kind") is not None or _label(el) is not None:
            return False
        kids = [c for c in el if _local(c.tag) in _SHAPE_TAGS | _GROUP_TAGS | {"use"} and not _hidden(c)]
        if len(kids) <= 1:  # a group around one thing is that thing, moved
            return True
        if any(_local(d.tag) == "use" for d in el.iter()):  # clones are elements of their own
            return True
        # A group is one object when its children touch one another (one connected piece).
        inner = _compose(m, self.transform(el))
        geoms = []
        for c in kids:
            flat = self.flatten(self.parts(c, inner, {}), _IDENTITY, self.tolerance)
            g = _geometry(flat.paths)
            if not g.is_empty:
                geoms.append(g)
        if len(geoms) <= 1:
            return False
        return not _connected(geoms)


def _source_text(source: Any) -> tuple[str, str | bytes]:
    if isinstance(source, bytes):
        return "<svg text>", _gunzip(source, "<svg text>")
    if isinstance(source, str) and source.lstrip("\ufeff \t\r\n").startswith("<"):
        return "<svg text>", source
    if not isinstance(source, (str, os.PathLike)):
        raise InputError(f"source: expected a path or SVG text, got {type(source).__name__}")
    path = FsPath(source)
    check_file(path, path.name)
    try:
        return path.name, _gunzip(path.read_bytes(), path.name)
    except FileNotFoundError:
        raise InputError(f"{str(source)!r}: no such file") from None
    except IsADirectoryError:
        raise InputError(f"{str(source)!r}: is a folder, expected a file") from None
    except OSError as exc:
        raise InputError(f"{str(source)!r}: cannot read ({exc.strerror or type(exc).__name__})") from None


def _gunzip(data: bytes, name: str) -> bytes:
    """``data`` itself, or its decompression when it is gzip (``.svgz``), within the file size limit.

    The decompressed size is bounded by the same ``file_size`` limit as a plain file: only
    that many bytes are ever inflated, so a gzip bomb is refused without filling memory.
    """
    if not data.startswith(b"\x1f\x8b"):
        return data
    import io
    import zlib

    limit = int(get_limit("file_size"))
    try:
        with gzip.GzipFile(fileobj=io.BytesIO(data)) as f:
            out = f.read(limit + 1)
    except (OSError, EOFError, zlib.error) as exc:
        raise InputError(f"{name}: not a readable gzip-compressed SVG (.svgz): {exc}") from None
    check_decompressed(len(out), name)
    return out


def _guarded(fn: Any) -> Any:
    """Turn a ``RecursionError`` (elements nested thousands deep) into :class:`InputError`."""
    import functools

    @functools.wraps(fn)
    def wrapper(source: Any, *args: Any, **kwargs: Any) -> Any:
        # The reading makes a few small objects per SVG object and frees none of them
        # until it returns, so the cyclic collector's passes over them find nothing; they
        # cost 10-15% of a large file's reading (issue 17.3). Collection resumes after.
        paused = gc.isenabled()
        if paused:
            gc.disable()
        try:
            return fn(source, *args, **kwargs)
        except RecursionError:
            name = FsPath(source).name if isinstance(source, os.PathLike) or (isinstance(source, str) and not source.lstrip().startswith("<")) else "<svg text>"
            raise InputError(f"{name}: elements nested too deeply") from None
        finally:
            if paused:
                gc.enable()

    return wrapper


def _props_no_display(el: ET.Element) -> dict[str, str]:
    return {k: v for k, v in _props(el).items() if k != "display"}


def _visible_parts(doc: _Doc, el: ET.Element, m: np.ndarray) -> list[_Part]:
    """Parts of a hidden (void) object, read as if it were shown."""
    props = doc.inherited_props(el)
    tag = _local(el.tag)
    if tag in _SHAPE_TAGS:
        own = {k: v for k, v in _props(el).items() if k != "display"}
        return [_Part(el, _compose(m, doc.transform(el)), {**props, **own})]
    return []


def _bounds(paths: list[Path]) -> tuple[float, float, float, float]:
    if not paths:
        return (0.0, 0.0, 0.0, 0.0)
    pts = np.concatenate([p.points for p in paths])
    return (float(pts[:, 0].min()), float(pts[:, 1].min()), float(pts[:, 0].max()), float(pts[:, 1].max()))


def _style(doc: _Doc, parts: list[_Part]) -> dict[str, Any]:
    """``fill``, ``stroke`` and ``stroke_width`` of the first drawable part (in the kind's frame)."""
    for part in parts:
        if part.label is not None:
            continue
        style: dict[str, Any] = {}
        for key in ("fill", "stroke"):
            if key in part.props:
                style[key] = part.props[key]
        if "stroke-width" in part.props:
            m = _LENGTH.match(part.props["stroke-width"])
            if m and m.group(2) in _UNITS:
                scale = math.sqrt(abs(np.linalg.det(part.m[:, :2])))
                style["stroke_width"] = float(m.group(1)) * _UNITS[m.group(2)] * scale
        return style
    return {}


def _data_attrs(el: ET.Element) -> dict[str, str]:
    return {k[5:]: v for k, v in el.attrib.items() if k.startswith("data-") and k not in ("data-kind", "data-label")}

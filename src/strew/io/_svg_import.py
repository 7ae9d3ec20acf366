"""SVG import: exemplars, shape libraries and regions from SVG (or gzip-compressed ``.svgz``).

Three entry points share one reading of the document:

- :func:`read_svg` reads an *exemplar* as an artist draws it in Inkscape (or as
  :func:`strew.io.svg.to_svg` writes it) into an :class:`~strew.arrangement.Arrangement`;
- :func:`read_svg_shapes` reads the distinct shapes of any SVG into a shape library;
- :func:`read_svg_region` reads the closed paths of an SVG into a :class:`~strew.region.Region`.

How elements and kinds are found
--------------------------------
The XML tree is walked with :mod:`xml.etree.ElementTree`; path data, basic shapes and
transforms are read into arrays by :mod:`._svg_flatten` (svgelements' geometry, without
its per-segment objects; svgelements itself reads only unusual syntax). Curves are
flattened so that the largest deviation *after* all transforms is at most ``tolerance``
user units. A ``.svgz`` file (gzip) is inflated first, within the same ``file_size``
limit as a plain file (:mod:`strew._limits`), so a gzip bomb is refused.

*Elements* are the objects drawn outside ``<defs>``: every ``<use>`` (a clone), every
basic shape or path, and every group that is one object. The root, Inkscape layers
(``inkscape:groupmode="layer"``), ``<a>`` and ``<switch>`` are containers; a plain ``<g>``
is one object when it carries ``data-kind`` or ``inkscape:label``, or when its children
touch one another (a leaf drawn as blade + vein); a group of separate objects, or one
holding clones, is a container. Objects inside a hidden (``display:none``) layer or group
are read and marked in a ``hidden`` column (``hidden="include"``, the default: artists
hide a layer while editing the others), or left out (``hidden="skip"``: a sketch or a
reference); a hidden element itself counts, with ``void = True`` (strew exports void
elements so). A ``<use>`` of a missing id draws nothing: it is skipped with one
:class:`SVGImportWarning` naming it, as Inkscape and browsers skip it.

*Kinds* come, in this order, from

1. clones: a ``<use>`` of a ``<symbol>`` or of another object gives the kind of what it
   refers to (named by that object's ``data-kind``, ``inkscape:label`` or id); the clone's
   full transform (parent groups, the use's own transform and its ``x``/``y``) gives the
   element's x, y, rotation and scale;
2. ``data-kind``, else ``inkscape:label``, else an id that is not an editor's automatic
   one (``path123``), with a trailing number dropped (``stone-3`` -> ``stone``); else the
   ``data-kind`` of the layer or group around it (strew writes one layer per kind, so an
   unlinked clone in it keeps its kind even after its symbol is cleaned away);
3. identical geometry: objects equal up to a similarity transform (translation, rotation,
   uniform scale) share a kind, and their rotation and scale are recovered. An object
   is also matched against the symbols no clone has used yet: Inkscape's *Unlink Clone*
   turns a ``<use>`` into a ``<g>`` holding copies of the symbol's paths, and that
   object keeps the symbol's kind and the clone's pose (issue 22). The scale
   comes from the area (or length) ratio and the rotation from the phase of the complex
   moments ``c_k = integral (z - centroid)^k dA``, which turn by ``k t`` under a rotation
   by ``t``; each candidate pose is then verified by the largest outline distance both
   ways. Mirror images are different kinds.

Objects with the same name but different geometry are split into ``name``, ``name-2``, ...,
since a kind has one shape. Positions are in the root's user units (its viewBox and size
are ignored); ``<text>``, ``<image>``, CSS ``<style>`` sheets and clip paths are ignored.
A symbol's viewBox is honoured only when the ``<use>`` gives an explicit width and height.

Transforms that are not similarities
------------------------------------
The strew convention ``p_world = (x, y) + s R(t) p_local`` has no skew, no non-uniform
scale and no reflection. A clone's linear part ``L`` is replaced by the closest
similarity in the least-squares sense (mean scale, ``t = atan2(L10 - L01, L00 + L11)``).
A *reflected* clone (``det L < 0``) gets its own kind, ``NAME-mirrored``, whose shape is
the kind's shape mirrored in its local x axis, so that its geometry stays exact.
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
from dataclasses import dataclass, field
from pathlib import Path as FsPath
from typing import Any

import numpy as np
import shapely

from .._errors import Cancelled, InputError
from .._limits import MAX_COORD, check_decompressed, check_file, check_paths, check_text, get_limit
from ..arrangement import Arrangement
from ..region import Region
from ..shape import Path, Shape, paths_to_polygon
from ._svg_flatten import EMPTY as _EMPTY
from ._svg_flatten import _fmt
from ._svg_flatten import ARC, Segments, flatten, flatten_many, from_svgelements, parse_path, parse_transform, path_d, points_many, shape_segments, too_large

__all__ = ["read_svg", "read_svg_shapes", "read_svg_region", "SVGImportWarning", "HIDDEN_CHOICES"]

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
# Matching flattens each object at this fraction of its own radius: a scale-invariant
# tolerance samples similar copies at the same curve parameters, so that their vertex sets
# are similar too and scale and rotation come out exact.
_SIGNATURE_TOLERANCE = 1e-3
_IDENTITY = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
# Most objects whose signatures are computed in one batch (see _Reader.object_signature);
# 1 computes them one by one and prepares nothing in bulk (_Reader.prepare), as the tests compare.
_MAX_BATCH = 256
_MIRROR = np.array([[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
# Objects prepared per chunk in _Reader.prepare.
_CHUNK = 4096


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
    props.update({k: v for k, v in _parse_style(el.get("style")).items() if k in ("fill", "stroke", "stroke-width", "display", "fill-rule")})
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
        for (i, m), flat in zip(where, flatten_many(tables, np.array(tols))):
            for pts, closed, curved in flat:
                curves[i] |= curved
                # the identity (an object drawn in the root's frame) maps each point to
                # itself + 0.0, bit for bit (-0.0 becomes 0.0, as in the product)
                paths[i].append(Path(pts + 0.0 if m is _IDENTITY else _apply(m, pts), closed))
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
        found = points_many([el.get("points") or "" for el in els], [_local(el.tag) == "polygon" for el in els])
        if found is None:
            return
        cache = self._segments
        for el, segs in zip(els, found):
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
        count = np.array([sum(len(p.points) for p in batch[i][1].paths) for i in have])
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


# -- geometry: moments and similarity matching ----------------------------------------
def _geometry(paths: list[Path]) -> shapely.Geometry:
    if len(paths) == 1 and paths[0].closed and len(paths[0].points) >= 3:
        # one closed path (most objects): what paths_to_polygon returns for a valid ring of
        # positive area, in two shapely calls instead of about ten (issue 17.3)
        ring = shapely.Polygon(paths[0].points)
        if shapely.is_valid(ring) and shapely.area(ring) > 0:
            return ring
    area = paths_to_polygon(paths)
    if not area.is_empty:
        return area
    lines = [shapely.LineString(p.points) for p in paths if not p.closed and len(p.points) >= 2]
    lines += [shapely.LinearRing(p.points) for p in paths if p.closed and len(p.points) >= 3]
    if not lines:
        return shapely.LineString()
    return lines[0] if len(lines) == 1 else shapely.MultiLineString([shapely.LineString(g.coords) for g in lines])


def _connected(geoms: list[shapely.Geometry]) -> bool:
    """Whether geometries form one piece (each linked to the rest by intersections)."""
    n = len(geoms)
    tree = shapely.STRtree(geoms)
    i, j = tree.query(geoms, predicate="intersects")
    parent = list(range(n))

    def find(a: int) -> int:
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b in zip(i.tolist(), j.tolist()):
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[ra] = rb
    return len({find(a) for a in range(n)}) == 1


# Five Gauss-Legendre points integrate polynomials of degree 9 exactly: the integrands
# below, conj(z) z^k dz and z^k ds along a straight edge, have degree k + 1 <= _KMAX + 1.
_GL_X, _GL_W = np.polynomial.legendre.leggauss(5)
_GL_T = (_GL_X + 1) / 2
_GL_W = _GL_W / 2
_KMAX = 8


@dataclass(slots=True)
class _Signature:
    """Similarity invariants of a flattened geometry (complex moments about its centroid)."""

    points: np.ndarray  # (n, 2) all vertices
    outline: shapely.Geometry  # boundary lines, for distance checks
    size: float  # area, or length for line-only geometry
    is_area: bool
    centroid: np.ndarray  # (2,)
    moments: np.ndarray  # (_KMAX + 1,) complex: c_k = integral of (z - centroid)^k
    gyration: float  # radius of gyration
    radius: float  # largest vertex distance from the centroid
    tolerance: float = 0.0  # the flattening tolerance it was computed at


def _edges(geom: shapely.Geometry, is_area: bool) -> tuple[np.ndarray, np.ndarray]:
    """(m,) complex start and end points of the oriented edges of a geometry.

    In a few vectorised shapely calls (parts, rings, coordinates with their ring index)
    instead of a Python loop over rings (issue 17.3); the same edges in the same order.
    """
    if is_area:
        geom = shapely.orient_polygons(geom) if hasattr(shapely, "orient_polygons") else _orient(geom)
        rings = shapely.get_rings(shapely.get_parts(geom))
    else:
        rings = shapely.get_parts(geom)
    c, idx = shapely.get_coordinates(rings, return_index=True)
    if len(c) < 2:
        return np.zeros(0, complex), np.zeros(0, complex)
    z = c[:, 0] + 1j * c[:, 1]
    same = idx[1:] == idx[:-1]  # consecutive vertices of one ring
    return z[:-1][same], z[1:][same]


def _orient(geom: shapely.Geometry) -> shapely.Geometry:
    from shapely.geometry.polygon import orient

    polys = [orient(p, 1.0) for p in shapely.get_parts(geom)]
    return polys[0] if len(polys) == 1 else shapely.MultiPolygon(polys)


def _moments(a: np.ndarray, b: np.ndarray, is_area: bool, shift: complex, kmax: int = _KMAX) -> tuple[np.ndarray, float]:
    """Complex moments ``c_k`` (k = 0..kmax) and the polar moment about ``shift``.

    Area moments use Green's theorem, ``integral z^k dA = 1/(2i) contour z^k conj(z) dz``;
    line moments integrate ``z^k ds``. Both are exact for polygons (Gauss-Legendre). The
    powers ``z^k`` come from one running product and the sums from one matrix product
    (issue 17.3: a tenth of the cost of a ``(m, q, K)`` power array on small shapes).
    """
    a = a - shift
    b = b - shift
    d = b - a
    z = (a[:, None] + _GL_T[None, :] * d[:, None]).ravel()  # (m q,)
    if is_area:
        w = (np.conj(z) * np.repeat(d, len(_GL_T))) * np.tile(_GL_W, len(d))  # conj(z) dz
    else:
        w = np.repeat(np.abs(d), len(_GL_T)) * np.tile(_GL_W, len(d))  # ds
    zk = np.empty((len(z), kmax + 1), complex)
    zk[:, 0] = 1.0
    if kmax >= 1:
        for k in range(1, kmax + 1):  # the running product (np.cumprod's order, at a tenth of its cost)
            np.multiply(zk[:, k - 1], z, out=zk[:, k])
    c = w @ zk
    zz = (z * np.conj(z)).real
    if is_area:
        c = c / 2j
        polar = float(np.real((zz * w).sum() / 2 / 2j))
    else:
        polar = float((zz * w).sum())
    return c, polar


def _area_centroid(a: np.ndarray, b: np.ndarray, is_area: bool) -> tuple[complex, complex]:
    """``c_0`` and ``c_1`` of :func:`_moments` about 0 in closed form (exact for polygons).

    Per edge ``z = a + t d``: ``integral conj(z) dz = d (conj(a) + conj(d) / 2)`` and
    ``integral z conj(z) dz = d (|a|^2 + Re(a conj(d)) + |d|^2 / 3)``; for lines
    ``|d|`` and ``|d| (a + b) / 2``. A third of the cost of the quadrature (issue 17.3).
    """
    d = b - a
    if is_area:
        c0 = complex((d * (np.conj(a) + np.conj(d) / 2)).sum()) / 2j
        c1 = complex((d * ((a * np.conj(a)).real + (a * np.conj(d)).real + (d * np.conj(d)).real / 3)).sum()) / 2j
    else:
        ds = np.abs(d)
        c0 = complex(ds.sum())
        c1 = complex((ds * (a + b)).sum()) / 2
    return c0, c1


def _signature(paths: list[Path]) -> _Signature | None:
    geom = _geometry(paths)
    if geom.is_empty:
        return None
    is_area = geom.geom_type in ("Polygon", "MultiPolygon")
    a, b = _edges(geom, is_area)
    c0 = _area_centroid(a, b, is_area)
    size = float(np.real(c0[0]))
    if not size > 0:
        return None
    centroid = complex(c0[1] / c0[0])
    c, polar = _moments(a, b, is_area, centroid)
    pts = np.concatenate([p.points for p in paths])
    cen = np.array([centroid.real, centroid.imag])
    outline = geom.boundary if is_area else geom
    return _Signature(
        points=pts,
        outline=outline,
        size=size,
        is_area=is_area,
        centroid=cen,
        moments=c,
        gyration=math.sqrt(max(polar, 0.0) / size),
        radius=float(np.sqrt(((pts - cen) ** 2).sum(axis=1)).max()),
    )


def _signatures(batch: list[list[Path]]) -> list[_Signature | None]:
    """:func:`_signature` of many objects at once (issue 17.3).

    Objects drawn by one closed path whose polygon is valid (most objects), or whose
    self-intersecting polygon shapely's ``make_valid`` repairs into polygons, go through
    shapely's array functions and numpy once for the whole batch: polygons, validity,
    repair, orientation, edges, then the moments of every edge, summed per object; the
    rest go through :func:`_signature` one by one. The same figures up to rounding (the sums run
    in another order).
    """
    out: list[_Signature | None] = [None] * len(batch)
    one = [i for i, paths in enumerate(batch) if len(paths) == 1 and paths[0].closed and len(paths[0].points) >= 3]
    polys = np.zeros(0, dtype=object)
    valid = good = np.zeros(0, dtype=bool)
    if one:
        pts_list = [batch[i][0].points for i in one]
        lens = np.array([len(p) for p in pts_list])
        coords = np.concatenate(pts_list)
        last = np.cumsum(lens) - 1
        open_ring = (coords[last - lens + 1] != coords[last]).any(axis=1)  # first point not repeated at the end
        if not open_ring.all():
            one = [i for i, o in zip(one, open_ring.tolist()) if o]
            pts_list = [p for p, o in zip(pts_list, open_ring.tolist()) if o]
            lens = lens[open_ring]
            coords = np.concatenate(pts_list) if pts_list else np.zeros((0, 2))
    if one:
        polys = shapely.polygons(shapely.linearrings(coords, indices=np.repeat(np.arange(len(one)), lens)))
        valid = shapely.is_valid(polys)
        good = valid & (shapely.area(polys) > 0)
    # Self-intersecting rings: repaired as paths_to_polygon repairs them (make_valid, its
    # polygons of positive area), all at once; where that gives anything but polygons,
    # or nothing, the object goes through _signature.
    geom_of = {k: g for k, g in zip(np.flatnonzero(good).tolist(), polys[good])}
    broken = np.flatnonzero(~valid)
    if len(broken):
        parts, owner = shapely.get_parts(shapely.make_valid(polys[broken]), return_index=True)
        kind = shapely.get_type_id(parts)
        odd = set(owner[(kind != 3) & (kind != 1) & (kind != 0) & (kind != 5) & (kind != 4)].tolist())  # not polygon, line or point
        areal = (kind == 3) & (shapely.area(parts) > 0)
        for j in sorted(set(owner[areal].tolist()) - odd):
            found = parts[areal & (owner == j)]
            geom_of[int(broken[j])] = found[0] if len(found) == 1 else shapely.MultiPolygon(list(found))
    sel = np.array(sorted(geom_of), dtype=np.intp)
    rest = set(range(len(batch))) - {one[k] for k in sel.tolist()}
    for i in sorted(rest):
        out[i] = _signature(batch[i])
    if not len(sel):
        return out
    polys = np.array([geom_of[k] for k in sel.tolist()], dtype=object)
    n = len(sel)
    # Valid one-ring polygons: their edges straight from the path's points, in the path's
    # direction; a clockwise ring's contour integrals change sign, and are turned back
    # below (what orienting it first gives, up to rounding, at no shapely call).
    simple = np.isin(sel, np.flatnonzero(good))
    js = np.flatnonzero(simple)
    cnt_s = lens[sel[js]]
    first_s = (np.cumsum(lens) - lens)[sel[js]]
    pos = np.repeat(first_s - (np.cumsum(cnt_s) - cnt_s), cnt_s) + np.arange(int(cnt_s.sum()))
    nxt = pos + 1
    ring_end = np.cumsum(cnt_s) - 1  # each ring's last point is followed by its first
    nxt[ring_end] = first_s
    zs = coords[:, 0] + 1j * coords[:, 1]
    a_s, b_s, obj_s = zs[pos], zs[nxt], np.repeat(js, cnt_s)
    # the others (repaired): every ring of every oriented polygon, holes clockwise
    jr = np.flatnonzero(~simple)
    if len(jr):
        parts, part_owner = shapely.get_parts(shapely.orient_polygons(polys[jr]), return_index=True)
        rings, ring_part = shapely.get_rings(parts, return_index=True)
        c, ridx = shapely.get_coordinates(rings, return_index=True)
        z = c[:, 0] + 1j * c[:, 1]
        same = ridx[1:] == ridx[:-1]
        order = np.argsort(np.r_[obj_s, jr[part_owner[ring_part[ridx[:-1][same]]]]], kind="stable")
        a = np.r_[a_s, z[:-1][same]][order]
        b = np.r_[b_s, z[1:][same]][order]
        obj = np.r_[obj_s, jr[part_owner[ring_part[ridx[:-1][same]]]]][order]
    else:
        a, b, obj = a_s, b_s, obj_s
    d = b - a
    # area and centroid in closed form (as _area_centroid), summed per object
    e0 = d * (np.conj(a) + np.conj(d) / 2) / 2j
    e1 = d * ((a * np.conj(a)).real + (a * np.conj(d)).real + (d * np.conj(d)).real / 3) / 2j
    c0 = np.bincount(obj, e0.real, n) + 1j * np.bincount(obj, e0.imag, n)
    c1 = np.bincount(obj, e1.real, n) + 1j * np.bincount(obj, e1.imag, n)
    turn = np.where(c0.real < 0, -1.0, 1.0)  # clockwise rings: every contour integral negated
    c0, c1 = c0 * turn, c1 * turn
    size = c0.real
    centroid = c1 / c0
    # moments about each object's centroid (as _moments, area case)
    q = len(_GL_T)
    a, b = a - centroid[obj], b - centroid[obj]
    d = b - a
    zq = (a[:, None] + _GL_T[None, :] * d[:, None]).ravel()
    w = (np.conj(zq) * np.repeat(d, q)) * np.tile(_GL_W, len(d))
    # w z^k for k = 0, 1, ... in one running product, summed per object as it goes (one
    # array of the quadrature points, not one per power: large fresh arrays cost more in
    # page faults than in arithmetic)
    starts = np.searchsorted(obj, np.arange(n)) * q  # edges come object by object
    mom = np.empty((n, _KMAX + 1), complex)
    acc = w.copy()
    for k in range(_KMAX + 1):
        mom[:, k] = np.add.reduceat(acc, starts)
        if k < _KMAX:
            acc *= zq
    mom /= 2j
    mom *= turn[:, None]
    polar = (np.add.reduceat((zq * np.conj(zq)).real * w, starts) / 2 / 2j).real * turn
    outlines = shapely.boundary(polys)
    pts_all = coords if len(sel) == len(one) else np.concatenate([pts_list[k] for k in sel.tolist()])
    cnt = lens[sel]
    first = np.cumsum(cnt) - cnt
    cen_all = np.c_[centroid.real, centroid.imag]
    radius = np.maximum.reduceat(np.sqrt(((pts_all - np.repeat(cen_all, cnt, axis=0)) ** 2).sum(axis=1)), first)
    for k, outline, cen, mom_j, size_j, polar_j, radius_j in zip(sel.tolist(), outlines.tolist(), cen_all, mom, size.tolist(), polar.tolist(), radius.tolist()):
        if not size_j > 0:
            continue
        i = one[k]
        out[i] = _Signature(batch[i][0].points, outline, size_j, True, cen, mom_j, math.sqrt(max(polar_j, 0.0) / size_j), radius_j)
    return out


def _invariants(sig: _Signature | None) -> list[float]:
    """size, radius, gyration, tolerance, +-1 (area or lines), then ``|c_k| / (size gyration^k)``
    for k = 2 .. _KMAX: the similarity invariants :meth:`_Reader.candidate_kinds` compares."""
    if sig is None or not sig.size > 0:
        return [math.nan] * 4 + [0.0] + [math.nan] * (_KMAX - 1)
    g = max(sig.gyration, 1e-300)
    mags = [abs(sig.moments[k]) / (sig.size * g**k) for k in range(2, _KMAX + 1)]
    return [sig.size, sig.radius, sig.gyration, sig.tolerance, 1.0 if sig.is_area else -1.0, *mags]


def _invariants_many(sigs: list[_Signature | None]) -> np.ndarray:
    """(n, 5 + _KMAX - 1) the rows :func:`_invariants` gives, for many signatures at once
    (the same arithmetic elementwise, so the same numbers)."""
    rows = np.empty((len(sigs), 5 + _KMAX - 1))
    rows[:] = _invariants(None)
    ok = [i for i, sig in enumerate(sigs) if sig is not None and sig.size > 0]
    if not ok:
        return rows
    have = [sigs[i] for i in ok]
    size = np.array([sig.size for sig in have])  # type: ignore[union-attr]
    g = np.maximum(np.array([sig.gyration for sig in have]), 1e-300)  # type: ignore[union-attr]
    mom = np.array([sig.moments[2:] for sig in have])  # type: ignore[union-attr]
    # Python's powers and hypot (numpy's array power and complex abs round otherwise)
    power = np.array([[v**k for k in range(2, _KMAX + 1)] for v in g.tolist()])
    rows[ok, 0] = size
    rows[ok, 1] = [sig.radius for sig in have]  # type: ignore[union-attr]
    rows[ok, 2] = [sig.gyration for sig in have]  # type: ignore[union-attr]
    rows[ok, 3] = [sig.tolerance for sig in have]  # type: ignore[union-attr]
    rows[ok, 4] = [1.0 if sig.is_area else -1.0 for sig in have]  # type: ignore[union-attr]
    rows[ok, 5:] = np.hypot(mom.real, mom.imag) / (size[:, None] * power)
    return rows


def _match(ref: _Signature, other: _Signature) -> tuple[float, float] | None:
    """Similarity ``other = s R(t) (ref - ref.centroid) + other.centroid``, or None.

    The rotation comes from the phase of the first complex moment ``c_k`` (k >= 2) that
    the shape's symmetry does not cancel: ``c_k`` turns by ``k t`` under a rotation by ``t``.
    Each candidate is checked by the largest vertex-to-outline distance both ways.
    """
    if ref.is_area != other.is_area:
        return None
    s = math.sqrt(other.size / ref.size) if ref.is_area else other.size / ref.size
    tolerance = max(other.tolerance, s * ref.tolerance)
    if abs(other.radius - s * ref.radius) > 2 * tolerance + 0.02 * other.radius:
        return None
    if abs(other.gyration - s * ref.gyration) > 2 * tolerance + 0.02 * other.gyration:
        return None
    candidates: list[float] = []
    first_wins = False
    used = 0
    norm_r = ref.size * max(ref.gyration, 1e-300)
    norm_o = other.size * max(other.gyration, 1e-300)
    for k in range(2, _KMAX + 1):
        mr = abs(ref.moments[k]) / (norm_r * ref.gyration ** (k - 1))
        mo = abs(other.moments[k]) / (norm_o * other.gyration ** (k - 1))
        if mr > 0.02 and mo > 0.02:
            base = (np.angle(other.moments[k]) - np.angle(ref.moments[k])) / k
            candidates.extend(base + 2 * math.pi * j / k for j in range(k))
            used += 1
            if used == 2:  # a second order guards against a noisy phase in the first
                break
    if not candidates:
        # Nearly round: align the farthest vertex, else try no rotation.
        far = np.argmax(((other.points - other.centroid) ** 2).sum(axis=1))
        vo = other.points[far] - other.centroid
        vr = ref.points - ref.centroid
        rr = np.sqrt((vr**2).sum(axis=1))
        near = np.flatnonzero(np.abs(s * rr - np.hypot(*vo)) <= 2 * tolerance + 0.01 * other.radius)
        candidates = [0.0] + [math.atan2(vo[1], vo[0]) - math.atan2(vr[i, 1], vr[i, 0]) for i in near[:32]]
        first_wins = True  # a round shape: keep rotation 0 when it fits
    # Both outlines lie within ``tolerance`` of the true curves; allow a little more for
    # the pose estimate and for rounding in the file's numbers.
    limit = 3 * tolerance + 1e-4 * other.radius
    best: tuple[float, float] | None = None
    best_err = math.inf
    for t in candidates:
        c, sn = math.cos(t), math.sin(t)
        rot = s * np.array([[c, -sn], [sn, c]])
        moved = (ref.points - ref.centroid) @ rot.T + other.centroid
        err = float(shapely.distance(other.outline, shapely.points(moved)).max())
        if err > limit:
            continue
        outline = shapely.transform(ref.outline, lambda p, rot=rot: (p - ref.centroid) @ rot.T + other.centroid)
        err = max(err, float(shapely.distance(outline, shapely.points(other.points)).max()))
        if err <= limit and err < best_err:
            best, best_err = (float(math.atan2(sn, c)), s), err
            if first_wins:
                break
    return best


# -- kinds and elements -----------------------------------------------------------------
@dataclass
class _Kind:
    name: str
    key: str | None  # the name it was asked for (None: geometry only)
    parts: list[_Part]  # in the reference frame
    origin: np.ndarray  # (2,) local origin in the reference frame
    mirrored: bool = False
    style: dict[str, Any] = field(default_factory=dict)
    signature: _Signature | None = None
    max_scale: float = 1.0
    matchable: bool = True
    strew_symbol: bool = False  # one of a strew export's kind symbols (kept even when unused)
    flat: _Flat | None = None  # its parts flattened in the reference frame, where new_kind had them


@dataclass
class _Element:
    kind: _Kind
    x: float
    y: float
    rotation: float
    scale: float
    void: bool
    attrs: dict[str, str]
    hidden: bool = False  # in a hidden layer or group (see ``hidden=``)


class _Reader:
    """Find the elements and kinds of a document (see the module docstring)."""

    def __init__(self, doc: _Doc) -> None:
        self.doc = doc
        self.kinds: list[_Kind] = []
        self.by_target: dict[tuple[int, bool], _Kind] = {}
        self.symbol_names: dict[str, _Kind] = {}  # a strew export's kinds by data-kind
        self.names: set[str] = set()
        self.elements: list[_Element] = []
        self.region_els: list[tuple[ET.Element, np.ndarray]] = []
        self._table = np.zeros((16, 5 + _KMAX - 1))  # per kind: see candidate_kinds (rows beyond _rows unused)
        self._grid: dict[tuple[int, ...], list[int]] = {}  # kinds by their first moment invariants
        # Symbols no clone has used yet, as kinds that are not listed: an object that is an
        # unlinked clone (Inkscape's Unlink Clone copies the symbol's paths into a <g>) takes
        # its symbol's kind even before, or without, any clone of it (issue 22).
        self.latent: dict[int, tuple[ET.Element, _Kind]] = {}
        self._latent_made = False
        # geometry text of single-part objects -> (kind, kind frame -> object coordinates, object map)
        self.sources: dict[tuple[str, ...], list[Any]] = {}
        # control-point hash of single-part objects -> (kind, kind frame -> world, world control points)
        self.outlines: dict[tuple[Any, ...], tuple[_Kind, np.ndarray, np.ndarray]] = {}
        self._rows = 0
        self._lrows: list[list[float]] = []  # the table's rows as Python lists (see _candidates_few)
        self._next: dict[str, int] = {}
        # signatures computed ahead, in batches (see :meth:`object_signature`)
        self._ahead: list[tuple[str, ET.Element, np.ndarray, bool]] = []
        self._pos = 0  # index in _ahead of the object being read
        self._batch = 1
        self._fetched: dict[int, tuple[list[_Part], _Flat]] = {}
        self._sigs: dict[int, _Signature | None] = {}
        # objects prepared in bulk before reading (see :meth:`prepare`): id(el) -> parts,
        # flattening, signature; their control outlines; their kind candidates
        self._prepared: dict[int, tuple[list[_Part], _Flat, _Signature | None]] = {}
        self._outline_of: dict[int, tuple[tuple[Any, ...], np.ndarray] | None] = {}
        self._key_source: dict[int, tuple[str | None, tuple[str, ...] | None]] = {}
        self._prep_index: dict[int, int] = {}  # id(el) -> index among the prepared objects
        self._partners: tuple[list[int], np.ndarray] | None = None  # CSR: earlier prepared objects that may match
        self._kind_at: dict[int, int] = {}  # prepared index -> index in kinds of the kind it made

    def unique(self, name: str) -> str:
        if name not in self.names:
            self.names.add(name)
            return name
        # the next free number after the last one given for this name (a scan from 2 made
        # n distinct unnamed shapes cost n^2 / 2 set lookups)
        i = self._next.get(name, 2)
        while f"{name}-{i}" in self.names:
            i += 1
        self._next[name] = i + 1
        self.names.add(f"{name}-{i}")
        return f"{name}-{i}"

    def new_kind(
        self, name: str, key: str | None, parts: list[_Part], *, keep_origin: bool, mirrored: bool = False, known: tuple[_Flat, _Signature | None] | None = None,
        register: bool = True,
    ) -> _Kind:
        """A kind drawn by ``parts``; ``known`` is their flattening and signature where the caller has them.

        With ``register=False`` the kind is made but not named or listed (see :meth:`latent_kind`).
        """
        flat = self.doc.flatten(parts, _IDENTITY, self.doc.tolerance) if known is None else known[0]
        if keep_origin:
            origin = np.zeros(2)
        else:
            bounds = flat.bounds if flat.bounds is not None else _bounds(flat.paths)
            origin = np.array([(bounds[0] + bounds[2]) / 2, (bounds[1] + bounds[3]) / 2])
        kind = _Kind(self.unique(name) if register else name, key, parts, origin, mirrored, style=_style(self.doc, parts))
        kind.signature = self.doc.signature(parts, flat) if known is None else known[1]
        kind.flat = flat
        if register:
            self.kinds.append(kind)
        return kind

    def register(self, kind: _Kind) -> _Kind:
        """List a kind made with ``register=False``, under a name of its own."""
        kind.name = self.unique(kind.name)
        self.kinds.append(kind)
        return kind

    def symbol_kinds(self) -> None:
        """Every ``<symbol>`` is a kind, in document order (unused ones too)."""
        for el in self.doc.root.iter():
            if _local(el.tag) == "symbol":
                kind = self.target_kind(el, mirrored=False)
                kind.strew_symbol = self.doc.is_strew and el.get("data-kind") is not None
                self.symbol_names.setdefault(el.get("data-kind") or kind.name, kind)

    def add_parts(self, el: ET.Element, m: np.ndarray, kind: _Kind, void: bool) -> None:
        """An element of a strew export drawn with its own geometry: a ``<g data-kind>``
        of one path per part (the ``parts`` column, see :class:`~strew.Arrangement`)."""
        doc = self.doc
        props = {**doc.inherited_props(el), **{k: v for k, v in _props(el).items() if k != "display"}}
        parts = []
        for child in el:
            leaves = doc.parts(child, _IDENTITY, props)
            flat = doc.flatten(leaves, _IDENTITY, doc.tolerance)
            if flat.paths:
                paths = [{"points": p.points.tolist(), "closed": bool(p.closed)} for p in flat.paths]
                parts.append({"paths": paths, "style": _style(doc, leaves)})
        n = len(self.elements)
        self.place(kind, _compose(m, doc.transform(el)), void, el)
        if parts and len(self.elements) > n:
            self.elements[-1].attrs["parts"] = json.dumps(parts)

    def target_kind(self, tgt: ET.Element, mirrored: bool) -> _Kind:
        key = (id(tgt), mirrored)
        kind = self.by_target.get(key)
        if kind is not None:
            return kind
        if mirrored:
            base = self.target_kind(tgt, False)
            kind = _Kind(self.unique(f"{base.name}-mirrored"), None, base.parts, base.origin, True, dict(base.style), None, 1.0, False)
            self.kinds.append(kind)
        elif id(tgt) in self.latent:  # made earlier to match unlinked copies against
            kind = self.register(self.latent.pop(id(tgt))[1])
        else:
            is_symbol = _local(tgt.tag) == "symbol"
            if is_symbol:
                parts = [p for child in tgt for p in self.doc.parts(child, _IDENTITY, _props_no_display(tgt))]
            else:
                parent = self.doc.parent.get(tgt)
                pm = self.doc.world(parent) if parent is not None else _IDENTITY
                parts = self.doc.parts(tgt, pm, self.doc.inherited_props(tgt))
            name = _name_of_target(tgt) or "kind"
            kind = self.new_kind(name, _name_of_target(tgt), parts, keep_origin=is_symbol and self.doc.is_strew)
        self.by_target[key] = kind
        return kind

    def add_clone(self, use: ET.Element, m: np.ndarray, void: bool, hidden: bool = False) -> None:
        doc = self.doc
        g = doc.use_matrix(use, m)
        last, tgt = use, doc.target(use)
        seen = {id(use)}
        while tgt is not None and _local(tgt.tag) == "use":  # a clone of a clone
            if id(tgt) in seen:
                raise InputError(f"{doc.name}: {doc.where(use)}: <use> refers to itself")
            seen.add(id(tgt))
            g = doc.use_matrix(tgt, g)
            last, tgt = tgt, doc.target(tgt)
        if tgt is None:  # dangling: skipped, and named in a warning
            return
        if _local(tgt.tag) == "symbol":
            view = doc.symbol_viewport(last, tgt)
            g = g if view is _IDENTITY else _compose(g, view)
        else:
            # The clone draws the object with the object's own transform but not its
            # parents'; relative to the object as drawn, it is moved by g T W_ref^-1.
            ref = doc.world(tgt)
            if abs(_det(ref)) < 1e-300:
                return
            g = _compose(_compose(g, doc.transform(tgt)), _invert(ref))
        mirrored = _det(g) < 0
        kind = self.target_kind(tgt, mirrored)
        self.place(kind, g, void, use, hidden)

    def place(self, kind: _Kind, g: np.ndarray, void: bool, el: ET.Element, hidden: bool = False) -> None:
        """Element of ``kind`` drawn by ``g`` (reference frame -> world)."""
        if g is _IDENTITY and not kind.mirrored:  # an object that drew its own kind: what the lines below give
            rot, s = 0.0, 1.0
            x, y = kind.origin.tolist()
            x, y = x + 0.0, y + 0.0
        else:
            lin = g[:, :2] @ _MIRROR[:, :2] if kind.mirrored else g[:, :2]
            rot, s = _similarity(lin)
            if not (s > 0):
                return
            x, y = _apply(g, kind.origin[None, :])[0]
        kind.max_scale = max(kind.max_scale, s)
        self.elements.append(_Element(kind, float(x), float(y), rot, s, void, _data_attrs(el), hidden))

    def add_object(self, el: ET.Element, m: np.ndarray, void: bool, hidden: bool = False) -> None:
        doc = self.doc
        if doc.is_strew and _local(el.tag) == "g" and el.get("data-kind") in self.symbol_names:
            self.add_parts(el, m, self.symbol_names[el.get("data-kind")], void)  # type: ignore[index]
            if hidden and self.elements:
                self.elements[-1].hidden = True
            return
        if (id(el), False) in self.by_target:  # the original of clones: its own kind
            self.place(self.by_target[(id(el), False)], _IDENTITY, void, el, hidden)
            return
        if el.get("id") is not None and el.get("id") in doc.referenced:
            self.place(self.target_kind(el, False), _IDENTITY, void, el, hidden)
            return
        # its own name, else the data-kind of its layer or group: an unlinked clone in a
        # strew export's kind layer keeps that kind (issue 22)
        known = self._key_source.pop(id(el), None)
        if known is not None:
            key, source = known
        else:
            key = _key_of(el) or self.doc.group_key(el)
            source = _source_key(el, key)
        if source is not None and self.copy_of(source, el, m, void, hidden):
            return
        if source is None:
            outline = None
        elif id(el) in self._outline_of:
            outline = self._outline_of.pop(id(el))
        else:
            outline = self.control_outline(el, m, key)
        if outline is not None and self.moved_copy(outline, el, void, hidden):
            return
        parts, flat, sig = self.object_signature(el, m, void)
        if not flat.paths:
            return
        placed: tuple[_Kind, np.ndarray] | None = None
        if sig is not None:
            found = self.prepared_candidates(el)
            for i in self.candidate_kinds(sig) if found is None else found:
                kind = self.kinds[i]
                if not kind.matchable or kind.signature is None or (key is not None and kind.key != key):
                    continue
                g = _pose(kind, sig)
                if g is not None:
                    placed = (kind, g)
                    break
            if placed is None:
                for tgt, kind in self.latent_kinds(sig, key):
                    g = _pose(kind, sig)
                    if g is not None:
                        placed = (self.target_kind(tgt, False), g)
                        break
        if placed is None:
            placed = (self.new_kind(key or "shape", key, parts, keep_origin=False, known=(flat, sig)), _IDENTITY)
            j = self._prep_index.get(id(el))
            if j is not None:
                self._kind_at[j] = len(self.kinds) - 1
        self.place(placed[0], placed[1], void, el, hidden)
        if source is not None and len(parts) == 1 and source not in self.sources:
            # for later objects with the same geometry text (see copy_of)
            self.sources[source] = [placed[0], placed[1], (m, el), None]  # (m, el): the map is composed if a copy comes
        if outline is not None and len(parts) == 1 and outline[0] not in self.outlines:
            self.outlines[outline[0]] = (placed[0], placed[1], outline[1])

    def _parts_flat(self, el: ET.Element, m: np.ndarray, void: bool) -> tuple[list[_Part], _Flat]:
        doc = self.doc
        parts = doc.parts(el, m, doc.inherited_props(el), show=True) if not void else _visible_parts(doc, el, m)
        return parts, doc.flatten(parts, _IDENTITY, doc.tolerance)

    def object_signature(self, el: ET.Element, m: np.ndarray, void: bool) -> tuple[list[_Part], _Flat, _Signature | None]:
        """Parts, flattening and signature of the object being read (``_ahead[_pos]``).

        Signatures are computed for this object and up to ``_batch - 1`` of the objects
        after it at once (:meth:`_Doc.signatures`; issue 17.3: per object, the numpy and
        shapely calls cost more than their arithmetic). The batch doubles while every
        object computed ahead needs its signature and falls back to 1 when one did not (a
        copy placed by :meth:`copy_of` or :meth:`moved_copy`), so that files of copies do
        not pay for signatures they never use. Objects ahead whose reading fails are left
        to be read (and to fail) in their turn.
        """
        key = id(el)
        if key in self._prepared:
            return self._prepared.pop(key)
        if key in self._sigs:
            parts, flat = self._fetched.pop(key)
            return parts, flat, self._sigs.pop(key)
        if self._fetched or self._sigs:  # computed ahead and not used: a copy took them
            self._fetched.clear()
            self._sigs.clear()
            self._batch = 1
        batch = [(el, *self._parts_flat(el, m, void))]
        doc = self.doc
        for what, other, om, _ in self._ahead[self._pos + 1:]:
            if len(batch) >= self._batch:
                break
            # paths and basic shapes only: a group's parts may look up clones, whose
            # missing targets must be noted in document order
            if what not in ("object", "void-object") or _local(other.tag) not in _SHAPE_TAGS or (id(other), False) in self.by_target:
                continue
            if id(other) in self._prepared:
                continue
            if other.get("id") is not None and other.get("id") in doc.referenced:
                continue
            try:
                batch.append((other, *self._parts_flat(other, om, what == "void-object")))
            except (InputError, ValueError, FloatingPointError):
                break
        sigs = doc.signatures([(parts, flat) if flat.paths else ([], _Flat([], {}, False)) for _, parts, flat in batch])
        for (other, parts, flat), sig in zip(batch[1:], sigs[1:]):
            self._fetched[id(other)] = (parts, flat)
            self._sigs[id(other)] = sig
        if len(batch) == self._batch:
            self._batch = min(2 * self._batch, _MAX_BATCH)
        return batch[0][1], batch[0][2], sigs[0]

    def prepare(self) -> None:
        """Parts, flattening, signature and kind candidates of the plain objects ahead, in bulk.

        Issue 17.3: per object, the numpy and shapely calls cost more than their arithmetic.
        Before reading, every path or basic shape that :meth:`add_object` would flatten and
        match is prepared at once: its control outline (:meth:`control_outline`), its
        flattening, its signature (one :meth:`_Doc.signatures` call for all), and the
        earlier prepared objects whose invariants pass :func:`_candidates`' tests against
        it (:func:`_candidate_pairs`, on a grid of the invariants instead of a lookup per
        object). Objects that repeat an earlier one's geometry text or control-outline
        hash are left out (:meth:`copy_of` and :meth:`moved_copy` place them without a
        signature); so are objects whose reading fails (they fail in their turn). The
        reading itself, its order and its decisions are unchanged.
        """
        doc = self.doc
        seen_source: set[tuple[str, ...]] = set()
        todo: list[tuple[ET.Element, bool, str | None, Segments, np.ndarray]] = []
        doc.preparse([el for what, el, _, _ in self._ahead if what in ("object", "void-object") and _local(el.tag) in ("polygon", "polyline")])
        for what, el, m, _ in self._ahead:
            if what not in ("object", "void-object") or _local(el.tag) not in _SHAPE_TAGS:
                continue
            ident = el.get("id")
            if ident is not None and ident in doc.referenced:
                continue
            key = _key_of(el) or doc.group_key(el)
            source = _source_key(el, key)
            self._key_source[id(el)] = (key, source)
            if source is None or source in seen_source:
                continue
            seen_source.add(source)
            if len(todo) % 256 == 255:
                doc.poll()
            try:
                segs = doc.segments(el)
                t = doc.transform(el)
                own = m if t is _IDENTITY else _compose(m, t)
            except Cancelled:
                raise
            except Exception:  # read (and failed) in its turn
                continue
            todo.append((el, what == "void-object", key, segs, own))
        if not todo:
            return
        # coordinates too large: read (and refused) in their turn; the largest magnitude
        # of each element at once, too_large itself only where it is over the limit
        counts = np.array([len(t[3].code) for t in todo])
        if counts.any():
            has = counts > 0
            top = np.zeros(len(todo))
            mags = np.abs(np.concatenate([t[3].pts for t in todo])).reshape(-1, 8).max(axis=1)
            top[has] = np.maximum.reduceat(mags, (np.cumsum(counts) - counts)[has])
            over = np.flatnonzero(~(top <= MAX_COORD)).tolist()
            if over:
                drop = {i for i in over if too_large(todo[i][3], MAX_COORD)}
                todo = [t for i, t in enumerate(todo) if i not in drop]
        seen_outline: set[tuple[Any, ...]] = set()
        rows: list[np.ndarray] = []
        valid: list[bool] = []
        # in chunks, so that the arrays of one chunk stay small (fresh large arrays cost
        # more in page faults than in arithmetic: 10 MB in one batch read 1.3x slower per MB)
        for lo in range(0, len(todo), _CHUNK):
            chunk = todo[lo : lo + _CHUNK]
            items: list[tuple[ET.Element, list[_Part]]] = []
            for (el, void, key, segs, own), outline in zip(chunk, _control_outlines([(t[2], t[3], t[4]) for t in chunk])):
                self._outline_of[id(el)] = outline
                if outline is not None:
                    if outline[0] in seen_outline:
                        continue  # a moved copy: moved_copy places it
                    seen_outline.add(outline[0])
                props = {**doc.inherited_props(el), **{k: v for k, v in _props(el).items() if k != "display"}}
                items.append((el, [_Part(el, own, props)]))
            if not items:
                continue
            doc.poll()
            flats = doc.flatten_all([(parts, doc.tolerance) for _, parts in items], checked=True)  # too_large above
            have = [f for f in flats if f.paths]
            if have:  # bounds for new_kind, all at once (min and max are exact)
                pts = np.concatenate([p.points for f in have for p in f.paths])
                count = np.array([sum(len(p.points) for p in f.paths) for f in have])
                start = np.cumsum(count) - count
                low, high = np.minimum.reduceat(pts, start, axis=0).tolist(), np.maximum.reduceat(pts, start, axis=0).tolist()
                for f, (x0, y0), (x1, y1) in zip(have, low, high):
                    f.bounds = (x0, y0, x1, y1)
            sigs = doc.signatures([(parts, flat) if flat.paths else ([], _Flat([], {}, False)) for (_, parts), flat in zip(items, flats)])
            for (el, parts), flat, sig in zip(items, flats, sigs):
                self._prepared[id(el)] = (parts, flat, sig)
                self._prep_index[id(el)] = len(valid)
                valid.append(sig is not None)
            rows.append(_invariants_many(sigs))
        if not rows:
            return
        found = _candidate_pairs(np.concatenate(rows), np.array(valid))
        self._partners = None if found is None else (found[0].tolist(), found[1])

    def prepared_candidates(self, el: ET.Element) -> list[int] | None:
        """:meth:`candidate_kinds` of a prepared object from :meth:`prepare`'s pairs, or None.

        Valid while every kind so far was made by a prepared object (then the kinds that
        pass the tests are exactly the kinds of its partners); otherwise None, and the
        caller asks :meth:`candidate_kinds`.
        """
        j = self._prep_index.get(id(el))
        if j is None or self._partners is None or len(self._kind_at) != len(self.kinds):
            return None
        start, earlier = self._partners
        lo, hi = start[j], start[j + 1]
        if lo == hi:
            return []
        kind_at = self._kind_at
        return [kind_at[i] for i in earlier[lo:hi].tolist() if i in kind_at]

    def control_outline(self, el: ET.Element, m: np.ndarray, key: str | None) -> tuple[tuple[Any, ...], np.ndarray] | None:
        """``(hash, points)``: the control points of a path or basic shape in world coordinates
        (complex, ``(n,)``) and a hash of their shape up to a similarity, or None.

        The hash holds the segment kinds and the points in the frame that puts the first
        point at 0 and the farthest one at 1, rounded to 1% of the size: copies that
        Inkscape moved, turned or scaled by writing new numbers into the path data hash
        alike (see :meth:`moved_copy`). Arcs are left out (their radii are not points).
        """
        return self.control_outline_of(key, self.doc.segments(el), _compose(m, self.doc.transform(el)))

    @staticmethod
    def control_outline_of(key: str | None, segs: Segments, own: np.ndarray) -> tuple[tuple[Any, ...], np.ndarray] | None:
        """:meth:`control_outline` of segments ``segs`` drawn by the map ``own``."""
        n = len(segs.code)
        if n == 0 or n > 512 or ARC in segs.code:
            return None
        if own[0, 0] * own[1, 1] - own[0, 1] * own[1, 0] <= 0:
            return None  # a mirror image is another kind: leave it to the matcher
        if segs.code.any():
            used = np.ones((n, 4), dtype=bool)
            used[:, 1] = segs.code != 0
            used[:, 2] = segs.code == 2
            local = segs.pts[used]
        else:  # lines only: starts and ends
            local = segs.pts[:, ::3].reshape(-1, 2)
        z = (local[:, 0] * own[0, 0] + local[:, 1] * own[0, 1] + own[0, 2]) + 1j * (local[:, 0] * own[1, 0] + local[:, 1] * own[1, 1] + own[1, 2])
        rel = z - z[0]
        d = np.abs(rel)
        far = int(np.argmax(d))
        if not (d[far] > 0) or not math.isfinite(float(d[far])):
            return None
        canon = rel / rel[far]
        q = np.round(canon.view(np.float64) * 100).astype(np.int64)
        return (key or "", segs.code.tobytes(), segs.sub.tobytes(), segs.closed.tobytes(), far, q.tobytes()), z

    def moved_copy(self, outline: tuple[tuple[Any, ...], np.ndarray], el: ET.Element, void: bool, hidden: bool) -> bool:
        """Place ``el`` as a moved, turned and scaled copy of an earlier object, if it is one.

        The similarity ``z -> a z + b`` that best maps the earlier object's control points
        onto this one's (least squares) must put every point within 1e-3 of the object's
        size: a Bezier curve lies in the hull of its control points, so the outlines then
        agree as closely as :func:`_match` asks (3e-3 of the size), and the pose is exact
        to the file's rounding instead of to the flattening (issue 17.3). Round kinds are
        left to the matcher, which keeps their rotation 0.
        """
        known = self.outlines.get(outline[0])
        if known is None:
            return False
        kind, pose, zp = known
        z = outline[1]
        if len(z) != len(zp) or not kind.matchable or not _has_orientation(kind):
            return False
        if len(z) <= 64:  # in plain complex numbers: numpy's call cost outweighs a few points
            zl, pl = z.tolist(), zp.tolist()
            mp, mz = sum(pl) / len(pl), sum(zl) / len(zl)
            ul = [w - mp for w in pl]
            vl = [w - mz for w in zl]
            den = sum(w.real * w.real + w.imag * w.imag for w in ul)
            if not den > 0:
                return False
            a = sum(x.conjugate() * y for x, y in zip(ul, vl)) / den
            size = max(abs(w) for w in vl)
            if not abs(a) > 0 or max(abs(a * x - y) for x, y in zip(ul, vl)) > 1e-3 * size:
                return False
        else:
            mp, mz = complex(zp.mean()), complex(z.mean())
            u, v = zp - mp, z - mz
            den = float(np.vdot(u, u).real)
            if not den > 0:
                return False
            a = complex(np.vdot(u, v)) / den
            size = float(np.abs(v).max())
            if not abs(a) > 0 or float(np.abs(a * u - v).max()) > 1e-3 * size:
                return False
        sim = np.array([[a.real, -a.imag, 0.0], [a.imag, a.real, 0.0]])
        sim[:, 2] = [mz.real - (a * mp).real, mz.imag - (a * mp).imag]
        self.place(kind, _compose(sim, pose), void, el, hidden)
        return True

    def copy_of(self, source: tuple[str, ...], el: ET.Element, m: np.ndarray, void: bool, hidden: bool) -> bool:
        """Place ``el`` as a copy of an earlier object with the same geometry text, if it is one.

        Objects whose path data (or basic-shape attributes) are the very same text as an
        earlier object's, drawn under a transform that differs from that object's by a
        similarity, are that object moved: the pose is the transform itself, without
        flattening or matching (issue 17.3: tools and scripts repeat one ``d`` under many
        transforms). Round kinds are left to the matcher, which keeps their rotation 0; a
        shape with symmetry gets the rotation of the transform, one of the poses the
        matcher could have returned.
        """
        known = self.sources.get(source)
        if known is None:
            return False
        kind, pose, first, frame = known[:4]
        if not kind.matchable or not _has_orientation(kind):
            return False
        if frame is None:  # kind frame -> the first object's own coordinates
            first = _compose(first[0], self.doc.transform(first[1]))
            if abs(_det(first)) < 1e-300:
                return False
            frame = known[3] = _compose(_invert(first), pose)
            known.append(_invert(first)[:, :2].tolist())
        t = self.doc.transform(el)
        own = m if t is _IDENTITY else _compose(m, t)
        # the change from the first copy: lin = L_own L_first^-1 must be a rotation and scale
        (p00, p01), (p10, p11) = known[4]
        (o00, o01, _), (o10, o11, _) = own.tolist()
        a, b = o00 * p00 + o01 * p10, o00 * p01 + o01 * p11
        c, d = o10 * p00 + o11 * p10, o10 * p01 + o11 * p11
        size = math.hypot(a, c)
        if not (size > 0) or abs(a - d) > 1e-12 * size or abs(b + c) > 1e-12 * size:
            return False
        self.place(kind, _compose(own, frame), void, el, hidden)
        return True

    def latent_kinds(self, sig: _Signature, key: str | None) -> list[tuple[ET.Element, _Kind]]:
        """Unused symbols (as unlisted kinds) that may match ``sig`` under ``key``, in document order."""
        if not self._latent_made:
            self._latent_made = True
            for el in self.doc.root.iter():
                if _local(el.tag) == "symbol" and (id(el), False) not in self.by_target:
                    self.doc.poll()
                    parts = [p for child in el for p in self.doc.parts(child, _IDENTITY, _props_no_display(el))]
                    name = _name_of_target(el)
                    kind = self.new_kind(name or "kind", name, parts, keep_origin=self.doc.is_strew, register=False)
                    if kind.signature is not None:
                        self.latent[id(el)] = (el, kind)
        if not self.latent:
            return []
        items = [(tgt, k) for tgt, k in self.latent.values() if key is None or k.key == key]
        if not items:
            return []
        table = np.array([_invariants(k.signature) for _, k in items])
        return [items[i] for i in _candidates(table, sig)]

    def candidate_kinds(self, sig: _Signature) -> np.ndarray:
        """Indices, in order, of the kinds that may match ``sig`` (see :func:`_match`).

        On arrays of every kind at once: ``_match``'s own size, radius and gyration tests,
        and the rotation-invariant moment magnitudes ``|c_k| / (size gyration^k)``, which
        similar shapes share (up to the flattening; 0.01 + 2% allowed). Without it a
        drawing of n distinct shapes costs n^2 / 2 full matches (issue 17).
        """
        n = len(self.kinds)
        if self._rows < n:  # rows for the kinds added since the last call (capacity doubles)
            if n > len(self._table):
                grown = np.zeros((2 * n, self._table.shape[1]))
                grown[: self._rows] = self._table[: self._rows]
                self._table = grown
            for i in range(self._rows, n):
                k = self.kinds[i]
                row = self._table[i] = _invariants(k.signature if k.matchable else None)
                self._lrows.append(row)
                if math.isfinite(row[0]):
                    self._grid.setdefault(_cell(row), []).append(i)
            self._rows = n
        if n == 0:
            return np.zeros(0, dtype=np.intp)
        if n <= 64:
            return _candidates(self._table[:n], sig)
        # Only kinds in grid cells within the moment tolerance can pass (a drawing of n
        # distinct shapes would otherwise test n kinds per object: n^2 in all).
        grid = self._grid
        inv = _invariants(sig)
        near = [grid[c] for c in _cells_near(inv) if c in grid]
        if not near:
            return np.zeros(0, dtype=np.intp)
        if sum(len(v) for v in near) <= 16:  # a few kinds: plain floats beat numpy's call cost
            return _candidates_few(self._lrows, sorted(i for v in near for i in v), sig, inv)
        rows = np.sort(np.concatenate([np.asarray(v, dtype=np.intp) for v in near]))
        return rows[_candidates(self._table[rows], sig, inv)]

    def read(self, *, all_symbols: bool) -> None:
        doc = self.doc
        if all_symbols:
            self.symbol_kinds()
        self._ahead = list(doc.walk())  # walk() polls should_cancel per object
        if _MAX_BATCH > 1:
            self.prepare()
        for self._pos, (what, el, m, hidden) in enumerate(self._ahead):
            if what == "region":
                self.region_els.append((el, m))
            elif what in ("use", "void-use"):
                self.add_clone(el, m, what == "void-use", hidden)
            else:
                self.add_object(el, m, what == "void-object", hidden)

    def shape(self, kind: _Kind, *, centred: bool) -> Shape:
        """The kind's shape in its local frame (flattened finely enough for its largest copy)."""
        doc = self.doc
        origin = kind.origin
        known = kind.flat
        if known is not None and known.paths and not known.curves and not known.labels and not kind.mirrored and not centred:
            # straight lines flatten alike at any tolerance: move the kind's own flattening
            # into its frame instead of flattening again (issue 17.3; the same points up to
            # rounding: one translation after the parts' maps instead of one composed map)
            return Shape(tuple(Path(p.points - origin, p.closed) for p in known.paths), None, kind.style, {})
        frame = _translate(-origin[0], -origin[1])
        if kind.mirrored:
            frame = _compose(_MIRROR, frame)
        tol = doc.tolerance / max(1.0, kind.max_scale)
        flat = doc.flatten(kind.parts, frame, tol)
        if centred:
            b = _bounds(flat.paths)
            shift = _translate(-(b[0] + b[2]) / 2, -(b[1] + b[3]) / 2)
            if not np.allclose(shift[:, 2], 0, atol=1e-12):
                frame = _compose(shift, frame)
                flat = doc.flatten(kind.parts, frame, tol)
        d = doc.path_data(kind.parts, frame) if flat.curves else None
        return Shape(tuple(flat.paths), d, kind.style, flat.labels)


_GRID = 0.05  # cell size of the kinds' grid on the invariants |c_k| / (size gyration^k), k = 2, 3, 4
_GRID_DIMS = (5, 6, 7)  # their columns in :func:`_invariants`' rows


def _cell(row: list[float] | np.ndarray) -> tuple[int, ...]:
    return tuple(int(math.floor(float(row[j]) / _GRID)) for j in _GRID_DIMS)


def _cells_near(row: list[float]) -> list[tuple[int, ...]]:
    """Cells holding every value ``a`` that :func:`_candidates` accepts next to ``b``:
    ``|a - b| <= 0.01 + 0.02 max(a, b)``, so ``0.98 b - 0.01 <= a <= (b + 0.01) / 0.98``."""
    if not all(math.isfinite(row[j]) for j in _GRID_DIMS):
        return []
    spans = []
    for j in _GRID_DIMS:
        b = float(row[j])
        lo, hi = 0.98 * b - 0.01, (b + 0.01) / 0.98  # widened below by far more than rounding
        spans.append(range(int(math.floor((lo - 1e-6) / _GRID)), int(math.floor((hi + 1e-6) / _GRID)) + 1))
    return [(i, j, k) for i in spans[0] for j in spans[1] for k in spans[2]]


def _candidates(table: np.ndarray, sig: _Signature, row: list[float] | None = None) -> np.ndarray:
    """Rows of ``table`` (kinds' :func:`_invariants`) that may match ``sig`` (see :meth:`_Reader.candidate_kinds`);
    ``row`` is ``_invariants(sig)`` where the caller has it."""
    if row is None:
        row = _invariants(sig)
    size, radius, gyration, tol, area = table[:, :5].T
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        scale = np.sqrt(sig.size / size) if sig.is_area else sig.size / size
        t = np.maximum(sig.tolerance, scale * tol)
        ok = (area == row[4]) & np.isfinite(size)
        ok &= ~(np.abs(sig.radius - scale * radius) > 2 * t + 0.02 * sig.radius)
        ok &= ~(np.abs(sig.gyration - scale * gyration) > 2 * t + 0.02 * sig.gyration)
        mk, mo = table[:, 5:], np.array(row[5:])
        # 0.01 + 2%: copies matched in the tests differ by at most 0.001 + 0.25% (their
        # flattenings differ); 0.05 + 10% let a growing share of n distinct shapes reach
        # the full match, n^2 in all (10 MB of distinct polygons: 28 s/MB against 11 at 1 MB)
        ok &= ~(np.abs(mk - mo) > 0.01 + 0.02 * np.maximum(mk, mo)).any(axis=1)
    return np.flatnonzero(ok)


def _control_outlines(items: list[tuple[str | None, Segments, np.ndarray]]) -> list[tuple[tuple[Any, ...], np.ndarray] | None]:
    """:meth:`_Reader.control_outline` of many objects, ``(key, segments, own map)`` each,
    in one batch of numpy (issue 17.3): the same hashes and points, elementwise the same
    arithmetic. Objects with a point that is not finite are left to the method."""
    out: list[tuple[tuple[Any, ...], np.ndarray] | None] = [None] * len(items)
    if not items:
        return out
    counts = np.array([len(segs.code) for _, segs, _ in items])
    maps = np.array([own for _, _, own in items]).reshape(len(items), 2, 3)
    det = maps[:, 0, 0] * maps[:, 1, 1] - maps[:, 0, 1] * maps[:, 1, 0]
    arcs = np.zeros(len(items), dtype=bool)
    if counts.any():
        codes = np.concatenate([segs.code for _, segs, _ in items])
        has = counts > 0
        arcs[has] = np.logical_or.reduceat(codes == ARC, (np.cumsum(counts) - counts)[has])
    # no arcs, at most 512 segments; a mirror image (det <= 0) is another kind: left to the matcher
    sel = np.flatnonzero((counts > 0) & (counts <= 512) & ~arcs & (det > 0)).tolist()
    if not sel:
        return out
    code = np.concatenate([items[i][1].code for i in sel])
    pts = np.concatenate([items[i][1].pts for i in sel])
    nseg = np.array([len(items[i][1].code) for i in sel])
    used = np.ones((len(code), 4), dtype=bool)
    used[:, 1] = code != 0
    used[:, 2] = code == 2
    local = pts[used]
    npts = np.bincount(np.repeat(np.arange(len(sel)), nseg), used.sum(axis=1), len(sel)).astype(np.intp)
    own = np.array([items[i][2] for i in sel])[np.repeat(np.arange(len(sel)), npts)]
    z = (local[:, 0] * own[:, 0, 0] + local[:, 1] * own[:, 0, 1] + own[:, 0, 2]) + 1j * (local[:, 0] * own[:, 1, 0] + local[:, 1] * own[:, 1, 1] + own[:, 1, 2])
    start = np.cumsum(npts) - npts
    obj = np.repeat(np.arange(len(sel)), npts)
    rel = z - z[start][obj]
    d = np.abs(rel)
    finite = np.isfinite(rel)
    bad = np.r_[0, np.cumsum(~finite)]
    end = start + npts
    top = np.maximum.reduceat(d, start)
    # the first point at the largest distance (np.argmax's choice)
    is_top = d == top[obj]
    far_at = np.minimum.reduceat(np.where(is_top, np.arange(len(d)), len(d)), start)
    far = far_at - start
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        canon = rel / rel[far_at][obj]
        q = np.round(canon.view(np.float64) * 100).astype(np.int64)
    # the hash's bytes cut from the bytes of all objects at once (the same bytes as each
    # object's own arrays give)
    qb = q.tobytes()
    codeb = code.tobytes()
    subb = np.concatenate([items[i][1].sub for i in sel]).tobytes()
    closed = [items[i][1].closed for i in sel]
    nclosed = np.fromiter(map(len, closed), dtype=np.intp, count=len(sel))
    closedb = np.concatenate(closed).tobytes()
    seg0 = (np.cumsum(nseg) - nseg).tolist()
    cl0 = (np.cumsum(nclosed) - nclosed).tolist()
    bad_l, top_l, far_l = bad.tolist(), top.tolist(), far.tolist()
    wq, wcode, wsub, wcl = q.itemsize * 2, code.itemsize, subb and len(subb) // len(code), closedb and len(closedb) // max(1, int(nclosed.sum()))
    for j, (i, s0, s1, a0, na, c0, nc) in enumerate(zip(sel, start.tolist(), end.tolist(), seg0, nseg.tolist(), cl0, nclosed.tolist())):
        if bad_l[s1] != bad_l[s0] or not math.isfinite(top_l[j]):
            out[i] = _Reader.control_outline_of(*items[i])
            continue
        if not top_l[j] > 0:
            continue
        key = (items[i][0] or "", codeb[wcode * a0 : wcode * (a0 + na)], subb[wsub * a0 : wsub * (a0 + na)], closedb[wcl * c0 : wcl * (c0 + nc)], far_l[j], qb[wq * s0 : wq * s1])
        out[i] = (key, z[s0:s1])
    return out


def _candidate_pairs(rows: np.ndarray, valid: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """For each object ``j``, the earlier objects ``i < j`` whose :func:`_invariants` row
    passes :func:`_candidates`' tests as a kind against ``j``'s signature (issue 17.3).

    ``rows`` (n, 5 + _KMAX - 1) are the objects' invariants; ``valid`` (n,) says which
    have a signature (the others are neither kinds that can match nor matched). Pairs
    are found on a grid of the moment invariants k = 2, 3, 4 whose cells are as wide as
    the largest difference :func:`_candidates` accepts, so only neighbouring cells are
    compared, then tested with :func:`_candidates`' own arithmetic on the pairs.

    Returns
    -------
    (start (n + 1,), earlier (m,)) or None
        Object ``j``'s candidates are ``earlier[start[j]:start[j + 1]]``, ascending. None
        when an invariant is not finite (:func:`_candidates`' NaN rules are left to it)
        or the grid would be too large.
    """
    n = len(rows)
    idx = np.flatnonzero(valid)
    if len(idx) and not np.isfinite(rows[idx]).all():
        return None
    if len(idx) < 2:
        return np.zeros(n + 1, dtype=np.intp), np.zeros(0, dtype=np.intp)
    sub = rows[idx]
    # |a - b| <= 0.01 + 0.02 max(a, b) (a, b >= 0) gives min + 0.5 >= 0.98 (max + 0.5):
    # on log(v + 0.5) every accepted pair is within -log(0.98) in each dimension
    with np.errstate(invalid="ignore"):
        pts = np.log(sub[:, list(_GRID_DIMS)] + 0.5)
    if not np.isfinite(pts).all():
        return None
    r = -math.log(0.98) * (1 + 1e-6) + 1e-9
    cell = np.floor(pts / r).astype(np.int64)
    cell -= cell.min(axis=0)
    span = cell.max(axis=0) + 3
    if float(span[0]) * float(span[1]) * float(span[2]) > 2.0**60:
        return None
    key = ((cell[:, 0] + 1) * span[1] + (cell[:, 1] + 1)) * span[2] + (cell[:, 2] + 1)
    order = np.argsort(key, kind="stable")
    sorted_key = key[order]
    # the occupied cells, each with its first position in sorted_key and its count: one
    # search per neighbouring cell instead of two (issue 17.3)
    cells, cell_lo = np.unique(sorted_key, return_index=True)
    cell_cnt = np.diff(np.r_[cell_lo, len(sorted_key)])
    last_cell = len(cells) - 1
    qs, ks = [], []
    m = len(idx)
    # Queries in blocks, each block's pairs tested before the next block's are made, so
    # that memory holds one block's neighbours, not all (on 50 MB of distinct polygons,
    # 460k objects, every neighbour at once took 20 GB).
    for b0 in range(0, m, _PAIR_BLOCK):
        qkey = key[b0 : b0 + _PAIR_BLOCK]
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    target = qkey + (dx * span[1] + dy) * span[2] + dz
                    at = np.minimum(np.searchsorted(cells, target), last_cell)
                    hit = cells[at] == target
                    lo = cell_lo[at]
                    cnt = np.where(hit, cell_cnt[at], 0)
                    total = int(cnt.sum())
                    if not total:
                        continue
                    q = np.repeat(np.arange(b0, b0 + len(qkey)), cnt)
                    k = order[np.repeat(lo - (np.cumsum(cnt) - cnt), cnt) + np.arange(total)]
                    keep = k < q  # the kind is the earlier object
                    q, k = q[keep], k[keep]
                    ok = _pair_test(sub[k], sub[q])
                    qs.append(q[ok])
                    ks.append(k[ok])
    q = np.concatenate(qs) if qs else np.zeros(0, dtype=np.intp)
    k = np.concatenate(ks) if ks else np.zeros(0, dtype=np.intp)
    q, k = idx[q], idx[k]
    order = np.lexsort((k, q))
    q, k = q[order], k[order]
    start = np.searchsorted(q, np.arange(n + 1), "left")
    return start.astype(np.intp), k.astype(np.intp)


_PAIR_BLOCK = 4096  # queries per block in _candidate_pairs


def _pair_test(kr: np.ndarray, qr: np.ndarray) -> np.ndarray:
    """_candidates' tests of kind rows ``kr`` against the rows ``qr`` of the signatures,
    pair by pair, in its arithmetic: (m,) bool."""
    size, radius, gyration, tol, area = kr[:, :5].T
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        scale = np.where(qr[:, 4] == 1.0, np.sqrt(qr[:, 0] / size), qr[:, 0] / size)
        t = np.maximum(qr[:, 3], scale * tol)
        ok = (area == qr[:, 4]) & np.isfinite(size)
        ok &= ~(np.abs(qr[:, 1] - scale * radius) > 2 * t + 0.02 * qr[:, 1])
        ok &= ~(np.abs(qr[:, 2] - scale * gyration) > 2 * t + 0.02 * qr[:, 2])
        mk, mo = kr[:, 5:], qr[:, 5:]
        ok &= ~(np.abs(mk - mo) > 0.01 + 0.02 * np.maximum(mk, mo)).any(axis=1)
    return ok


def _candidates_few(table: list[list[float]], rows: list[int], sig: _Signature, row: list[float]) -> list[int]:
    """:func:`_candidates` on a few rows of the table, in plain floats (the same tests and the
    same answers; a non-finite number anywhere goes to :func:`_candidates`, whose NaN rules
    it then keeps)."""
    vals = [table[i] for i in rows]
    if not all(math.isfinite(v) for r in vals for v in r) or not all(math.isfinite(v) for v in row):
        sub = np.array(vals).reshape(len(vals), len(row))
        return [rows[j] for j in _candidates(sub, sig, row)]
    out = []
    mo = row[5:]
    for i, r in zip(rows, vals):
        size, radius, gyration, tol, area = r[:5]
        if area != row[4]:
            continue
        if not size > 0:  # an infinite scale: numpy's rules
            out.extend(i for _ in _candidates(np.array([r]), sig, row))
            continue
        scale = math.sqrt(sig.size / size) if sig.is_area else sig.size / size
        t = max(sig.tolerance, scale * tol)
        if abs(sig.radius - scale * radius) > 2 * t + 0.02 * sig.radius:
            continue
        if abs(sig.gyration - scale * gyration) > 2 * t + 0.02 * sig.gyration:
            continue
        if any(abs(a - b) > 0.01 + 0.02 * max(a, b) for a, b in zip(r[5:], mo)):
            continue
        out.append(i)
    return out


_SOURCE_ATTRS = {
    "path": ("d",),
    "rect": ("x", "y", "width", "height", "rx", "ry"),
    "circle": ("cx", "cy", "r"),
    "ellipse": ("cx", "cy", "rx", "ry"),
    "line": ("x1", "y1", "x2", "y2"),
    "polyline": ("points",),
    "polygon": ("points",),
}


def _source_key(el: ET.Element, key: str | None) -> tuple[str, ...] | None:
    """The text that defines a basic shape's or path's geometry (with its kind name), or None."""
    tag = _local(el.tag)
    attrs = _SOURCE_ATTRS.get(tag or "")
    if attrs is None:
        return None
    return (tag, key or "", *(el.get(a) or "" for a in attrs))  # type: ignore[return-value]


def _has_orientation(kind: _Kind) -> bool:
    """Whether :func:`_match` finds ``kind``'s rotation from its moments (it is not nearly round)."""
    cached = getattr(kind, "_oriented", None)
    if cached is None:
        sig = kind.signature
        cached = False
        if sig is not None and sig.size > 0 and sig.gyration > 0:
            norm = sig.size * sig.gyration
            cached = any(abs(sig.moments[k]) / (norm * sig.gyration ** (k - 1)) > 0.02 for k in range(2, _KMAX + 1))
        kind._oriented = cached  # type: ignore[attr-defined]
    return bool(cached)


def _pose(kind: _Kind, sig: _Signature) -> np.ndarray | None:
    """(2, 3) map from ``kind``'s reference frame to the object of signature ``sig``, or None."""
    found = _match(kind.signature, sig)  # type: ignore[arg-type]
    if found is None:
        return None
    t, s = found
    c, sn = math.cos(t), math.sin(t)
    lin = s * np.array([[c, -sn], [sn, c]])
    # world = lin (p_ref - ref.centroid) + centroid: a map from the reference frame.
    return np.c_[lin, sig.centroid - lin @ kind.signature.centroid]  # type: ignore[union-attr]


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


def _decode(text: str) -> Any:
    try:
        return json.loads(text)
    except (json.JSONDecodeError, ValueError):
        return text


# -- public functions -------------------------------------------------------------------
@_guarded
def read_svg(
    source: str | bytes | os.PathLike[str], *, tolerance: float = 0.1, should_cancel: Callable[[], bool] | None = None, hidden: str = "include"
) -> Arrangement:
    """Read an exemplar (or a strew SVG export) into an arrangement.

    Parameters
    ----------
    source : path, or SVG text (a ``str`` starting with ``<``, or bytes)
    tolerance : float
        Largest distance, in user units after all transforms, between a curve and its
        flattening. Recorded in ``meta["svg_import"]["tolerance"]``.
    should_cancel : callable () -> bool, optional
        Polled after parsing and once per object; when it returns True the import stops
        with :class:`~strew._errors.Cancelled` (the studio's "stop").
    hidden : {"include", "skip"}
        Objects in hidden (``display:none``) layers and groups: ``"include"`` reads them
        and marks them in a boolean ``hidden`` column (an artist often hides a layer
        while editing the others); ``"skip"`` leaves them out (a sketch or reference
        layer). A hidden object itself is always read, as a void element.

    Returns
    -------
    Arrangement
        One element per clone or object (see the module docstring for how kinds are
        found); x, y, rotation (radians) and scale follow
        ``p_world = (x, y) + s R(t) p_local``. A layer or path with id ``strew-region``
        or ``region`` (or label ``region``) becomes the region. From a strew export,
        ``<metadata><strew:meta>`` becomes ``meta``, ``data-<col>`` attributes (JSON)
        become columns and ``data-index`` restores the element order; symbol circles
        with ``data-label`` become ``Shape.labels``. Hidden elements count, with
        ``void = True``. Kinds are those with elements, and in a strew export also its
        own kind symbols (``<symbol data-kind>``), used or not.

    Raises
    ------
    InputError
        Malformed XML, no shapes, bad lengths; a file over the size or path limits
        (``.svgz`` is read too, and its decompressed size is held to the same limit).

    Warns
    -----
    SVGImportWarning
        A ``<use>`` of a missing id is skipped (it draws nothing).
    Cancelled
        When ``should_cancel`` returned True.

    Examples
    --------
    >>> svg = '''<svg xmlns="http://www.w3.org/2000/svg"><defs>
    ...   <symbol id="dot"><circle r="1"/></symbol></defs>
    ...   <use href="#dot" transform="translate(5 2) rotate(90)"/>
    ...   <use href="#dot" x="9"/></svg>'''
    >>> arr = read_svg(svg)
    >>> arr.kinds, arr.x.tolist(), arr.y.tolist()
    (('dot',), [5.0, 9.0], [2.0, 0.0])
    >>> round(float(arr.rotation[0]), 6)
    1.570796
    """
    doc = _Doc(source, tolerance, should_cancel, hidden)
    reader = _Reader(doc)
    reader.read(all_symbols=doc.is_strew)
    elements = reader.elements
    if not elements and not doc.is_strew:
        raise InputError(f"{doc.name}: no shapes found (no path, basic shape or clone outside <defs>){doc.missing_note()}")
    doc.warn_dangling()
    used = {id(e.kind) for e in elements}
    kinds = [k for k in reader.kinds if id(k) in used or k.strew_symbol]
    shapes = {k.name: reader.shape(k, centred=False) for k in kinds}
    order = np.arange(len(elements))
    index = [e.attrs.get("index") for e in elements]
    if elements and all(i is not None for i in index):
        try:
            idx = np.array([int(i) for i in index])  # type: ignore[arg-type]
        except ValueError:
            idx = None
        if idx is not None and np.array_equal(np.sort(idx), np.arange(len(idx))):
            order = np.argsort(idx, kind="stable")
    elements = [elements[i] for i in order]
    columns: dict[str, list[Any]] = {}
    names = [n for n in dict.fromkeys(k for e in elements for k in e.attrs) if n != "index" and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_.-]*", n)]
    for n in names:
        columns[n] = [_decode(e.attrs[n]) if n in e.attrs else None for e in elements]
    if any(e.void for e in elements) and "void" not in columns:
        columns["void"] = [e.void for e in elements]
    if any(e.hidden for e in elements):
        given = columns.get("hidden", [None] * len(elements))
        columns["hidden"] = [bool(e.hidden or g is True) for e, g in zip(elements, given)]
    region = _region_of(doc, reader.region_els) if reader.region_els else None
    meta = dict(doc.meta or {})
    meta["svg_import"] = {"source": doc.name, "tolerance": doc.tolerance}
    try:
        return Arrangement(
            shapes,
            [e.kind.name for e in elements],
            [e.x for e in elements],
            [e.y for e in elements],
            [e.rotation for e in elements],
            [e.scale for e in elements],
            columns=columns,
            region=region,
            meta=meta,
        )
    except InputError as exc:
        raise InputError(f"{doc.name}: {exc}") from None


@_guarded
def read_svg_shapes(
    source: str | bytes | os.PathLike[str], *, tolerance: float = 0.1, should_cancel: Callable[[], bool] | None = None, hidden: str = "include"
) -> dict[str, Shape]:
    """The distinct shapes of any SVG, one per kind, centred on their bounding boxes.

    Paths (curves and arcs flattened within ``tolerance`` user units after transforms),
    basic shapes and clones are read, with nested group transforms. Kinds are found as
    in :func:`read_svg`. A file that draws nothing outside ``<defs>`` is a symbol
    library: every ``<symbol>`` is a shape. A file that draws something gives the shapes
    of what it draws; symbols it does not use are left out (issue 22). Each shape's
    local origin is the bounding-box centre of the kind's reference instance, unrotated
    and at unit scale; ``Shape.d`` keeps exact path data where it can be exact in local
    coordinates, and ``Shape.style`` the fill, stroke and stroke width.

    Parameters
    ----------
    source : path, or SVG text
    tolerance : float
    should_cancel : callable () -> bool, optional
        Polled after parsing and once per object; when it returns True the import stops
        with :class:`~strew._errors.Cancelled` (the studio's "stop").
    hidden : {"include", "skip"}
        Objects in hidden layers and groups, as in :func:`read_svg`.

    Returns
    -------
    dict of str to Shape

    Raises
    ------
    InputError
        When the SVG has no shapes, or cannot be read.

    Examples
    --------
    >>> shapes = read_svg_shapes('<svg xmlns="http://www.w3.org/2000/svg">'
    ...                          '<rect id="brick" x="10" y="10" width="4" height="2"/></svg>')
    >>> list(shapes), shapes["brick"].bounds
    (['brick'], (-2.0, -1.0, 2.0, 1.0))
    """
    doc = _Doc(source, tolerance, should_cancel, hidden)
    reader = _Reader(doc)
    reader.read(all_symbols=True)
    doc.warn_dangling()
    used = {id(e.kind.parts) for e in reader.elements}  # a mirrored kind shares its base's parts
    shapes = {}
    for kind in reader.kinds:
        if kind.mirrored:
            continue
        if used and id(kind.parts) not in used:
            continue  # a symbol the drawing does not use
        shape = reader.shape(kind, centred=True)
        if not shape.is_empty:
            shapes[kind.name] = shape
    if not shapes:
        raise InputError(f"{doc.name}: no shapes found (no path, basic shape, symbol or clone){doc.missing_note()}")
    return shapes


@_guarded
def read_svg_region(
    source: str | bytes | os.PathLike[str], *, tolerance: float = 0.1, should_cancel: Callable[[], bool] | None = None
) -> Region:
    """A region from the closed paths of an SVG (or ``.svgz``).

    The element with id ``region`` or ``strew-region`` (or label ``region``) when there
    is one; otherwise every closed subpath of every drawn element (hidden layers and
    groups are not drawn, so they are left out). Within an element,
    subpaths combine under the even-odd rule (a nested subpath is a hole); separate
    elements are united.

    Parameters
    ----------
    source : path, or SVG text
    tolerance : float
        Flattening tolerance for curves, in user units.
    should_cancel : callable () -> bool, optional
        Polled after parsing and once per object; when it returns True the import stops
        with :class:`~strew._errors.Cancelled` (the studio's "stop").

    Returns
    -------
    Region

    Raises
    ------
    InputError
        When there is no closed path, or the SVG cannot be read.

    Examples
    --------
    >>> r = read_svg_region('<svg xmlns="http://www.w3.org/2000/svg">'
    ...                     '<path d="M0,0 H10 V10 H0 Z M2,2 H4 V4 H2 Z"/></svg>')
    >>> r.area
    96.0
    """
    doc = _Doc(source, tolerance, should_cancel)
    # a region is what is drawn: hidden layers and groups are left out
    chosen = [(el, m) for what, el, m, _ in doc.walk("skip") if what == "region"]
    if not chosen:
        chosen = [(el, m) for what, el, m, _ in doc.walk("skip") if what in ("object", "use")]
    region = _region_of(doc, chosen)
    if region is None:
        raise InputError(f"{doc.name}: no closed path found for a region{doc.missing_note()}")
    doc.warn_dangling()
    return region


def _region_of(doc: _Doc, items: list[tuple[ET.Element, np.ndarray]]) -> Region | None:
    polys = []
    all_paths: list[Path] = []
    for el, m in items:
        doc.poll()
        parts = doc.parts(el, m, {})
        flat = doc.flatten(parts, _IDENTITY, doc.tolerance)
        closed = [p for p in flat.paths if p.closed and len(p.points) >= 3]
        area = paths_to_polygon(closed)
        if not area.is_empty:
            polys.append(area)
            all_paths.extend(closed)
    if not polys:
        return None
    if len(polys) == 1:
        return Region(polys[0], paths=all_paths)
    return Region(shapely.union_all(polys))

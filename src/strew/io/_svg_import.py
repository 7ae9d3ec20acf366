"""SVG import: exemplars, shape libraries and regions from SVG (or gzip-compressed ``.svgz``).

Three entry points share one reading of the document:

- :func:`read_svg` reads an *exemplar* as an artist draws it in Inkscape (or as
  :func:`strew.io.svg.to_svg` writes it) into an :class:`~strew.arrangement.Arrangement`;
- :func:`read_svg_shapes` reads the distinct shapes of any SVG into a shape library;
- :func:`read_svg_region` reads the closed paths of an SVG into a :class:`~strew.region.Region`.

The reading is split in three modules, each importing only the ones below it:

- :mod:`._svg_tree`: the document: parsing within the size limits, ids, transforms, the
  walk of the rendering tree into top-level objects and their drawable parts, and the
  flattening of parts into paths (by :mod:`._svg_flatten`, the lowest: path data and
  basic shapes as arrays, curves sampled in bulk);
- :mod:`._svg_match`: the geometry of kind matching: similarity invariants (complex
  moments), signatures of one or many objects, the pose of one object as another, and
  the candidate kinds an object is fully matched against;
- this module: the reader that decides each object's kind and pose, and the public
  functions.

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

import json
import math
import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import shapely

from .._errors import Cancelled, InputError
from .._limits import MAX_COORD
from ..arrangement import Arrangement
from ..region import Region
from ..shape import Path, Shape, paths_to_polygon
from ._svg_flatten import Segments, too_large
from ._svg_match import _KMAX, _Signature, _candidate_pairs, _candidates, _candidates_few, _cell, _cells_near, _control_outlines, _invariants, _invariants_many, _match, _outline_digests, control_outline_of
from ._svg_tree import HIDDEN_CHOICES, SVGImportWarning, _Doc, _Flat, _GEOMETRY_ATTRS, _IDENTITY, _Part, _SHAPE_TAGS, _apply, _bounds, _compose, _data_attrs, _det, _guarded, _invert, _key_of, _local, _name_of_target, _props, _props_no_display, _similarity, _style, _translate, _visible_parts

__all__ = ["read_svg", "read_svg_shapes", "read_svg_region", "SVGImportWarning", "HIDDEN_CHOICES"]

# Most objects whose signatures are computed in one batch (see _Reader.object_signature);
# 1 computes them one by one and prepares nothing in bulk (_Reader.prepare), as the tests compare.
_MAX_BATCH = 256
_MIRROR = np.array([[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
# Objects prepared per chunk in _Reader.prepare.
_CHUNK = 4096


# -- kinds and elements -----------------------------------------------------------------
# (slots: a large file makes one of each per object; issue 17.3)
@dataclass(slots=True)
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
    oriented: bool | None = None  # whether _match finds its rotation from its moments (None: not asked yet)


@dataclass(slots=True)
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
            tag = _local(el.tag)
            if what not in ("object", "void-object") or tag not in _SHAPE_TAGS:
                continue
            attrib = el.attrib
            plain = attrib.keys() <= _SOURCE_SETS[tag]  # type: ignore[index]
            if plain:
                # geometry attributes only (most objects of a large file): no id, name,
                # transform or style to look up; the same key and source as below
                key = doc.group_key(el)
                source = (tag, key or "", *(attrib.get(a) or "" for a in _SOURCE_ATTRS[tag]))  # type: ignore[index]
            else:
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
                t = _IDENTITY if plain else doc.transform(el)
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
        # (in chunks: one chunk's arrays stay small)
        drop: set[int] = set()
        for lo in range(0, len(todo), _CHUNK):
            chunk = todo[lo : lo + _CHUNK]
            counts = np.array([len(t[3].code) for t in chunk])
            if not counts.any():
                continue
            has = counts > 0
            top = np.zeros(len(chunk))
            mags = np.abs(np.concatenate([t[3].pts for t in chunk])).reshape(-1, 8).max(axis=1)
            top[has] = np.maximum.reduceat(mags, (np.cumsum(counts) - counts)[has])
            drop.update(lo + i for i in np.flatnonzero(~(top <= MAX_COORD)).tolist() if too_large(chunk[i][3], MAX_COORD))
        if drop:
            todo = [t for i, t in enumerate(todo) if i not in drop]
        # An object whose outline digest no other prepared object shares is a moved copy
        # of none of them: its hash is not made (None: moved_copy neither looks it up
        # nor lists it). Objects read later that are not prepared repeat a prepared
        # object's geometry text (copy_of places them) or fail.
        state, digest = _outline_digests([(t[2], t[3], t[4]) for t in todo])
        shared = state == 2
        digested = np.flatnonzero(state == 1)
        if len(digested):
            _, inverse, count = np.unique(digest[digested], return_inverse=True, return_counts=True)
            shared[digested] = count[inverse] > 1
        want = shared.tolist()
        seen_outline: set[tuple[Any, ...]] = set()
        rows: list[np.ndarray] = []
        valid: list[bool] = []
        # in chunks, so that the arrays of one chunk stay small (fresh large arrays cost
        # more in page faults than in arithmetic: 10 MB in one batch read 1.3x slower per MB)
        for lo in range(0, len(todo), _CHUNK):
            chunk = todo[lo : lo + _CHUNK]
            items: list[tuple[ET.Element, list[_Part]]] = []
            wanted = want[lo : lo + _CHUNK]
            made = iter(_control_outlines([(t[2], t[3], t[4]) for t, w in zip(chunk, wanted) if w]))
            for (el, void, key, segs, own), w in zip(chunk, wanted):
                outline = next(made) if w else None
                self._outline_of[id(el)] = outline
                if outline is not None:
                    if outline[0] in seen_outline:
                        continue  # a moved copy: moved_copy places it
                    seen_outline.add(outline[0])
                props = doc.inherited_props(el)
                mine = None if el.attrib.keys() <= _SOURCE_SETS[_local(el.tag)] else _props(el)  # type: ignore[index]
                if mine:
                    props.update((k, v) for k, v in mine.items() if k != "display")
                items.append((el, [_Part(el, own, props)]))
            if not items:
                continue
            doc.poll()
            flats = doc.flatten_all([(parts, doc.tolerance) for _, parts in items], checked=True)  # too_large above
            have = [f for f in flats if f.paths]
            if have:  # bounds for new_kind, all at once (min and max are exact)
                pts = np.concatenate([p.points for f in have for p in f.paths])
                count = np.array([len(f.paths[0].points) if len(f.paths) == 1 else sum(len(p.points) for p in f.paths) for f in have])
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
        return control_outline_of(key, self.doc.segments(el), _compose(m, self.doc.transform(el)))

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

    def shapes(self, kinds: list[_Kind]) -> list[Shape]:
        """``[self.shape(k, centred=False) for k in kinds]``, the kinds drawn by straight
        lines made at once (issue 17.3: one Shape's own checks cost more than its making).

        Their points are moved into the kinds' frames in one subtraction (the same as each
        alone) and checked in one pass as :class:`~strew.shape.Shape` checks them (finite,
        within ``MAX_COORD``, a closed path not repeating its first point); a kind that
        fails goes through :meth:`shape`, which raises or repairs as before.
        """
        out: list[Shape | None] = [None] * len(kinds)
        fast = [i for i, k in enumerate(kinds) if self._straight(k, centred=False)]
        if fast:
            paths = [p for i in fast for p in kinds[i].flat.paths]  # type: ignore[union-attr]
            counts = np.fromiter((len(p.points) for p in paths), dtype=np.intp, count=len(paths))
            per_kind = np.fromiter((len(kinds[i].flat.paths) for i in fast), dtype=np.intp, count=len(fast))  # type: ignore[union-attr]
            origins = np.array([kinds[i].origin for i in fast]).reshape(len(fast), 2)
            moved = np.concatenate([p.points for p in paths]) - np.repeat(np.repeat(origins, per_kind, axis=0), counts, axis=0)
            moved.setflags(write=False)
            end = np.cumsum(counts)
            start = end - counts
            with np.errstate(invalid="ignore"):
                fine = np.abs(moved) <= MAX_COORD
                row_ok = fine[:, 0] & fine[:, 1]
            bad_rows = np.r_[0, np.cumsum(~row_ok)]
            closed = np.fromiter((p.closed for p in paths), dtype=bool, count=len(paths))
            last = np.maximum(end - 1, 0)
            repeats = closed & (counts > 1) & (moved[np.minimum(start, last)] == moved[last]).all(axis=1)
            path_ok = (bad_rows[end] == bad_rows[start]) & (counts > 0) & ~repeats
            kind_end = np.cumsum(per_kind)
            kind_ok = np.logical_and.reduceat(path_ok, kind_end - per_kind) if len(path_ok) else np.zeros(0, bool)
            pieces = [moved[a:b] for a, b in zip(start.tolist(), end.tolist())]
            checked = Shape._checked
            for i, ok, hi, n in zip(fast, kind_ok.tolist(), kind_end.tolist(), per_kind.tolist()):
                if ok:
                    own = (Path(pieces[hi - 1], paths[hi - 1].closed),) if n == 1 else tuple([Path(pieces[q], paths[q].closed) for q in range(hi - n, hi)])
                    out[i] = checked(own, None, kinds[i].style, {})
        return [s if s is not None else self.shape(k, centred=False) for s, k in zip(out, kinds)]

    @staticmethod
    def _straight(kind: _Kind, *, centred: bool) -> bool:
        """Whether :meth:`shape` moves the kind's own flattening into its frame (straight lines)."""
        known = kind.flat
        return known is not None and bool(known.paths) and not known.curves and not known.labels and not kind.mirrored and not centred

    def shape(self, kind: _Kind, *, centred: bool) -> Shape:
        """The kind's shape in its local frame (flattened finely enough for its largest copy)."""
        doc = self.doc
        origin = kind.origin
        known = kind.flat
        if known is not None and self._straight(kind, centred=centred):
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


_SOURCE_ATTRS = {
    "path": ("d",),
    "rect": ("x", "y", "width", "height", "rx", "ry"),
    "circle": ("cx", "cy", "r"),
    "ellipse": ("cx", "cy", "rx", "ry"),
    "line": ("x1", "y1", "x2", "y2"),
    "polyline": ("points",),
    "polygon": ("points",),
}


_SOURCE_SETS = _GEOMETRY_ATTRS  # the same attributes as _SOURCE_ATTRS, as sets


def _source_key(el: ET.Element, key: str | None) -> tuple[str, ...] | None:
    """The text that defines a basic shape's or path's geometry (with its kind name), or None."""
    tag = _local(el.tag)
    attrs = _SOURCE_ATTRS.get(tag or "")
    if attrs is None:
        return None
    return (tag, key or "", *(el.get(a) or "" for a in attrs))  # type: ignore[return-value]


def _has_orientation(kind: _Kind) -> bool:
    """Whether :func:`_match` finds ``kind``'s rotation from its moments (it is not nearly round)."""
    cached = kind.oriented
    if cached is None:
        sig = kind.signature
        cached = False
        if sig is not None and sig.size > 0 and sig.gyration > 0:
            norm = sig.size * sig.gyration
            cached = any(abs(sig.moments[k]) / (norm * sig.gyration ** (k - 1)) > 0.02 for k in range(2, _KMAX + 1))
        kind.oriented = cached
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
    shapes = {k.name: shape for k, shape in zip(kinds, reader.shapes(kinds))}
    index = [e.attrs.get("index") for e in elements]
    if elements and all(i is not None for i in index):
        try:
            idx = np.array([int(i) for i in index])  # type: ignore[arg-type]
        except ValueError:
            idx = None
        if idx is not None and np.array_equal(np.sort(idx), np.arange(len(idx))):
            elements = [elements[i] for i in np.argsort(idx, kind="stable").tolist()]
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

"""Rendering the grown geometry (Wong et al. 1998, §4, Fig. 15e-g, Fig. 17).

The paper generates an ornament in two steps: first the geometry (elements and their
proxies), then a rendering of it "in any number of styles". The default rendering draws
every proxy in outline (§4). A pattern may attach a render function to an element type
for a named style; it returns :class:`Mark` objects (SVG paths with fill and stroke).
:func:`tapered_stroke` and :func:`skeletal_stroke` give strokes whose width varies along a
curve, a simple form of the skeletal strokes [Hsu and Lee 1994] the paper renders with.

Generic styles, available for every pattern:

``outline``
    every proxy in outline (the paper's default rendering);
``tapered``
    curves as filled strokes thinning from start to end; circles and polygons filled;
``filigree``
    curves thickening from start to end (the reversed width variation of Fig. 13), closed
    proxies in outline.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from .._errors import InputError
from ..arrangement import Arrangement
from ..shape import Path, Shape
from ._pattern import Element
from ._proxies import Arc, Bezier, Point, Proxy, Segment

if TYPE_CHECKING:  # what a renderer reads of a grown ornament; _engine.Ornament has it
    from typing import Protocol

    from ..region import Region
    from ._pattern import Pattern

    class Ornament(Protocol):  # no import of ._engine: the engine imports this module (issue 15.7)
        pattern: Pattern
        region: Region
        elements: list[Element]
        stats: dict[str, Any]
        params: dict[str, Any]

__all__ = [
    "Mark",
    "RenderContext",
    "GENERIC_STYLES",
    "tapered_stroke",
    "skeletal_stroke",
    "render_ornament",
    "available_styles",
]

INK = "#2b2f36"


@dataclass
class Mark:
    """One drawn path of an element: polylines in world coordinates with fill and stroke.

    Parameters
    ----------
    paths : sequence of (n, 2) float
        Polylines in document units.
    closed : bool
        Whether the paths are closed (filled under the even-odd rule when ``fill`` is set).
    fill, stroke : str
        SVG paints (``"none"`` for none).
    stroke_width : float
        In document units.
    """

    paths: Sequence[np.ndarray]
    closed: bool = False
    fill: str = "none"
    stroke: str = INK
    stroke_width: float = 0.25
    extra: dict[str, Any] = field(default_factory=dict)

    @classmethod
    def circle(cls, center: Any, radius: float, segments: int = 48, **kwargs: Any) -> Mark:
        """A circle as a closed polyline."""
        t = np.linspace(0, 2 * np.pi, segments, endpoint=False)
        c = np.asarray(center, dtype=float)
        return cls([c + radius * np.c_[np.cos(t), np.sin(t)]], closed=True, **kwargs)

    @classmethod
    def polygon(cls, points: Any, **kwargs: Any) -> Mark:
        """A closed polygon, filled by default."""
        kwargs.setdefault("fill", INK)
        kwargs.setdefault("stroke", "none")
        return cls([np.asarray(points, dtype=float)], closed=True, **kwargs)


@dataclass
class RenderContext:
    """What a render function sees besides its element.

    Attributes
    ----------
    ornament : Ornament
    style : str
    line_width : float
        Base line width in document units.
    cache : dict
        Shared by the render functions of one rendering, for what they compute once
        (the flowers pattern keeps an index of its petal outlines here).
    """

    ornament: Ornament
    style: str
    line_width: float
    _counts: dict[str, int] = field(default_factory=dict)
    #: per-rendering memo for render functions (an index of what other elements draw)
    cache: dict[str, Any] = field(default_factory=dict)
    _groups: dict[tuple[str, Any], list[Element]] | None = None

    def group(self, el: Element) -> list[Element]:
        """The elements drawn as one with ``el`` (see :meth:`Pattern.group`), in growth
        order; ``[el]`` for a type that is not grouped."""
        groups = self.ornament.pattern.groups
        if el.type not in groups:
            return [el]
        if self._groups is None:
            self._groups = {}
            for e in self.ornament.elements:
                if e.type in groups:
                    self._groups.setdefault((e.type, getattr(e, groups[e.type][0])), []).append(e)
        return self._groups[(el.type, getattr(el, groups[el.type][0]))]

    def count(self, type_name: str) -> int:
        """Number of placed elements of a type."""
        if not self._counts:
            for e in self.ornament.elements:
                self._counts[e.type] = self._counts.get(e.type, 0) + 1
        return self._counts.get(type_name, 0)


def _arclength(points: np.ndarray) -> np.ndarray:
    seg = np.hypot(*np.diff(points, axis=0).T)
    s = np.r_[0.0, np.cumsum(seg)]
    return s / s[-1] if s[-1] > 0 else np.linspace(0, 1, len(points))


def _normals(points: np.ndarray) -> np.ndarray:
    d = np.gradient(points, axis=0) if len(points) > 2 else np.repeat(points[-1:] - points[:1], len(points), axis=0)
    n = np.c_[-d[:, 1], d[:, 0]]
    ln = np.hypot(n[:, 0], n[:, 1])
    ln[ln == 0] = 1.0
    return n / ln[:, None]


def tapered_stroke(points: np.ndarray, widths: Any) -> np.ndarray:
    """Outline of a stroke whose width varies along a polyline.

    Parameters
    ----------
    points : (n, 2) float
        The centre line, n >= 2.
    widths : float, (w0, w1) or (n,) float, or callable
        Width at every point; a pair interpolates linearly by arc length from start to
        end; a callable maps arc-length fraction t in [0, 1] to width.

    Returns
    -------
    (2n, 2) float
        Closed outline: one side forward, the other back.

    Examples
    --------
    >>> out = tapered_stroke(np.array([[0.0, 0.0], [10.0, 0.0]]), (2.0, 0.0))
    >>> out.shape, float(out[:, 1].max())
    ((4, 2), 1.0)
    """
    pts = np.asarray(points, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 2:
        raise InputError("tapered_stroke: points must have shape (n, 2) with n >= 2")
    t = _arclength(pts)
    if callable(widths):
        w = np.asarray([float(widths(x)) for x in t])
    else:
        w = np.asarray(widths, dtype=float)
        if w.ndim == 0:
            w = np.full(len(pts), float(w))
        elif w.shape == (2,) and len(pts) != 2:
            w = w[0] + (w[1] - w[0]) * t
        elif w.shape != (len(pts),):
            raise InputError(f"tapered_stroke: widths must be a number, a pair or ({len(pts)},), got {w.shape}")
    nrm = _normals(pts) * (np.maximum(w, 0) / 2)[:, None]
    return np.vstack([pts + nrm, (pts - nrm)[::-1]])


def skeletal_stroke(points: np.ndarray, art: np.ndarray, width: float) -> np.ndarray:
    """Bend a piece of flat art along a path (a simple skeletal stroke, Hsu and Lee 1994).

    Parameters
    ----------
    points : (n, 2) float
        The path (skeleton).
    art : (m, 2) float
        The art in the stroke's frame: ``u`` in [0, 1] along the path, ``v`` in [-1, 1]
        across it (v = +-1 is the stroke's edge).
    width : float
        Width of the stroke (distance between v = -1 and v = +1).

    Returns
    -------
    (m, 2) float
        The art in world coordinates.
    """
    pts = np.asarray(points, dtype=float)
    art = np.asarray(art, dtype=float)
    t = _arclength(pts)
    nrm = _normals(pts)
    u = np.clip(art[:, 0], 0, 1)
    base = np.c_[np.interp(u, t, pts[:, 0]), np.interp(u, t, pts[:, 1])]
    n = np.c_[np.interp(u, t, nrm[:, 0]), np.interp(u, t, nrm[:, 1])]
    n /= np.maximum(np.hypot(n[:, 0], n[:, 1]), 1e-12)[:, None]
    return base + n * (art[:, 1] * width / 2)[:, None]


# -- generic styles -------------------------------------------------------------------------
def _curve_points(pr: Proxy) -> np.ndarray | None:
    if isinstance(pr, (Segment, Bezier, Arc)):
        pts = pr.polyline()
        if isinstance(pr, Segment):
            pts = np.linspace(pts[0], pts[1], 8)
        return pts
    return None


def _outline(el: Element, rc: RenderContext) -> list[Mark]:
    marks = []
    for pr in el.proxies:
        if isinstance(pr, Point):
            continue
        marks.append(Mark([pr.polyline()], closed=pr.closed, stroke_width=rc.line_width))
    return marks


def _taper(el: Element, rc: RenderContext, reverse: bool) -> list[Mark]:
    marks = []
    for pr in el.proxies:
        if isinstance(pr, Point):
            continue
        pts = _curve_points(pr)
        if pts is None:
            if reverse:
                marks.append(Mark([pr.polyline()], closed=True, stroke_width=rc.line_width))
            else:
                marks.append(Mark([pr.polyline()], closed=True, fill=INK, stroke="none"))
            continue
        length = float(np.hypot(*np.diff(pts, axis=0).T).sum())
        w = min(4 * rc.line_width, max(1.5 * rc.line_width, 0.06 * length))
        ws = (0.15 * w, w) if reverse else (w, 0.15 * w)
        marks.append(Mark.polygon(tapered_stroke(pts, ws)))
    return marks


def _stroke_art(kind: str, n: int = 48) -> list[np.ndarray]:
    """Flat art of a skeletal stroke, in the stroke's frame (u along, v across in
    [-1, 1]): closed outlines, drawn filled. Four strokes, as the four of Fig. 17."""
    u = np.linspace(0.0, 1.0, n)
    if kind == "brush":  # a calligraphic brush: swelling, slightly asymmetric
        top = np.sin(np.pi * u) ** 0.7
        bottom = -0.55 * np.sin(np.pi * u) ** 1.2
        return [np.r_[np.c_[u, top], np.c_[u[::-1], bottom[::-1]]]]
    if kind == "leafy":  # a thin vine with leaves alternating from side to side
        art = [np.r_[np.c_[u, np.full(n, 0.12)], np.c_[u[::-1], np.full(n, -0.12)]]]
        t = np.linspace(0.0, 1.0, 16)
        for k, c in enumerate(np.linspace(0.12, 0.88, 5)):
            side = 1.0 if k % 2 == 0 else -1.0
            along = c + 0.16 * t
            top = side * (0.1 + 0.9 * np.sin(np.pi * t) ** 0.8 * (1 - 0.3 * t))
            art.append(np.r_[np.c_[along, top], np.c_[along[::-1], np.full(16, side * 0.1)]])
        return art
    if kind == "beads":  # a string of beads shrinking along the path
        art = []
        t = np.linspace(0.0, 2 * np.pi, 20, endpoint=False)
        for k, c in enumerate(np.linspace(0.08, 0.92, 6)):
            r = 0.9 * (1 - 0.11 * k)
            art.append(np.c_[c + 0.07 * r * np.cos(t), r * np.sin(t)])
        return art
    if kind == "ribbon":  # a twisting ribbon: width follows |cos|, two lobes per length
        w = 0.15 + 0.85 * np.abs(np.cos(2 * np.pi * u))
        return [np.r_[np.c_[u, w], np.c_[u[::-1], -w[::-1]]]]
    raise InputError(f"unknown stroke {kind!r}")


SKELETAL_STROKES = ("brush", "leafy", "beads", "ribbon")


def _skeletal(el: Element, rc: RenderContext, kind: str) -> list[Mark]:
    """Every curve proxy drawn with a skeletal stroke (Fig. 17; Hsu and Lee 1994): flat
    art bent along it. Closed proxies (circles, polygons) carry the art along their
    outline, filled as a band (even-odd)."""
    marks = []
    for pr in el.proxies:
        if isinstance(pr, Point):
            continue
        pts = _curve_points(pr)
        closed = pts is None
        if closed:
            pts = pr.polyline()
            pts = np.vstack([pts, pts[:1]])
        length = float(np.hypot(*np.diff(pts, axis=0).T).sum())
        if not length > 0:
            continue
        w = min(5 * rc.line_width, max(2 * rc.line_width, 0.12 * length))
        if closed:
            w = min(w, 0.8 * rc.line_width * 4)
        art = [skeletal_stroke(pts, a, w) for a in _stroke_art(kind)]
        marks.append(Mark(art, closed=True, fill=INK, stroke="none"))
    return marks


GENERIC_STYLES: dict[str, Any] = {
    "outline": lambda el, rc: _outline(el, rc),
    "tapered": lambda el, rc: _taper(el, rc, False),
    "filigree": lambda el, rc: _taper(el, rc, True),
    "skeletal": lambda el, rc: _skeletal(el, rc, "brush"),
    **{f"skeletal-{k}": (lambda el, rc, k=k: _skeletal(el, rc, k)) for k in SKELETAL_STROKES[1:]},
}
GENERIC_HELP = {
    "outline": "every proxy in outline (the paper's default rendering)",
    "tapered": "curves as strokes thinning from start to end, closed proxies filled",
    "filigree": "curves thickening from start to end, closed proxies in outline",
    "skeletal": "every curve as a skeletal stroke, a brush bent along it (Fig. 17)",
    "skeletal-leafy": "skeletal strokes of a vine with alternating leaves (Fig. 17)",
    "skeletal-beads": "skeletal strokes of shrinking beads (Fig. 17)",
    "skeletal-ribbon": "skeletal strokes of a twisting ribbon (Fig. 17)",
}


def available_styles(pattern: Any) -> dict[str, str]:
    """Style names usable with a pattern, with one line of help each."""
    out = dict(GENERIC_HELP)
    for s in pattern.styles:
        out[s] = pattern.style_help.get(s, "defined by the pattern")
    return out


def _clip_to_panel(paths: list[np.ndarray], closed: bool, panel: Any, cover: Any) -> list[np.ndarray]:
    """Paths of a mark clipped to the panel (``(n, 2)`` arrays in, the same out).

    Growth keeps every proxy inside the panel (§3.1), but a mark drawn around a proxy
    (a stem's width, a leaf's outline) can stand out of it by half a line width; like a
    frame over the panel, the drawing is cut at the panel's edge. Marks wholly inside
    (``cover``: the panel grown by a rounding tolerance) come back unchanged.
    """
    import shapely

    from ..shape import paths_to_polygon

    # a mark lies within the convex hull of its vertices, so a covered bounding box covers
    # it: the same answer as below without the even-odd polygon (most marks, in a gallery
    # about half of the ornament section's render time)
    allp = np.vstack(paths)
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    if (hi > lo).all() and shapely.covers(cover, shapely.box(lo[0], lo[1], hi[0], hi[1])):
        return paths
    if closed:
        geom = paths_to_polygon(Path(q, True) for q in paths)
        if geom.is_empty or shapely.covers(cover, geom):
            return paths
        out = []
        for part in shapely.get_parts(shapely.intersection(geom, panel)):
            if isinstance(part, shapely.Polygon) and part.area > 0:
                out += [np.asarray(r.coords)[:-1] for r in (part.exterior, *part.interiors)]
        return out
    geom = shapely.MultiLineString([q for q in paths if len(q) >= 2])
    if geom.is_empty or shapely.covers(cover, geom):
        return paths
    cut = shapely.line_merge(shapely.intersection(geom, panel))
    return [np.asarray(g.coords) for g in shapely.get_parts(cut) if isinstance(g, shapely.LineString) and g.length > 0]


def render_ornament(ornament: Ornament, style: str = "outline", *, line_width: float | None = None, seeds: bool = False,
                    _proxies: bool = False) -> Arrangement:
    """Draw the grown ornament in a named style.

    Parameters
    ----------
    ornament : Ornament
    style : str
        A generic style (``outline``, ``tapered``, ``filigree``) or one the pattern
        defines; types without a function for a pattern style are drawn in outline.
    line_width : float, optional
        Base line width (default: a fifth of the pattern's minimum radius).
    seeds : bool
        Also draw the seed points (as small circles).
    _proxies : bool
        A tiled world's tile (issue 19.4): also the private column
        ``ornament_proxies`` (:mod:`strew.ornament._context`), from which later tiles
        grow on. Context elements (placed from a finished tile) are never drawn.

    Returns
    -------
    Arrangement
        One row per drawn element, of kind ``type`` (one kind per element type), with
        columns ``element`` (placement index), ``type``, ``parent`` (placement index of
        the parent, -1 for none), ``phase`` and ``parts``: the element's marks, one
        shape each, in its own frame (origin at the mean of its vertices). The library
        holds each type's first element as its representative.
    """
    pat = ornament.pattern
    styles = available_styles(pat)
    if style not in styles:
        raise InputError(f"style: unknown style {style!r} for pattern {pat.name!r} (have: {', '.join(styles)})")
    lw = float(line_width) if line_width is not None else 0.2 * float(ornament.params.get("min_radius", pat.min_radius))
    rc = RenderContext(ornament, style, lw)
    shapes: dict[str, Shape] = {}
    kind, xs, ys, rots = [], [], [], []
    col_el, col_type, col_parent, col_phase = [], [], [], []
    col_parts: list[list[Shape]] = []
    col_groups: list[list[Element]] = []
    col_commit: list[int] = []
    col_goal: list[tuple[float, float, float]] = []
    col_parent_el: list[int] = []  # the parent's placement index, context parents aside
    rank = {t: k for k, t in enumerate(dict.fromkeys([*pat.draw_order, *pat.types]))}
    panel = cover = None
    # a periodic tile's elements are drawn whole: those crossing its edge wrap in at the
    # opposite one (strew._periodic.images), they are not clipped
    if ornament.region is not None and not ornament.params.get("periodic"):
        import shapely

        panel = ornament.region.geometry
        cover = shapely.buffer(panel, 1e-7 * max(1.0, *np.abs(ornament.region.bounds)))
        shapely.prepare(cover)
    # elements drawn as one (Pattern.group: the segments of a spiral): the first of each
    # group stands for it, with the marks of all
    members: dict[int, list[Element]] = {}
    grouped: set[int] = set()
    for el in ornament.elements:
        if el.type in pat.groups and not getattr(el, "context", False):
            group = [g for g in rc.group(el) if not getattr(g, "context", False)]
            members[group[0].index] = group
            grouped.add(el.index)
    order: dict[str, int] = {}
    for el in sorted(ornament.elements, key=lambda e: (rank.get(e.type, len(rank)), e.index)):
        if el.index in grouped and el.index not in members:
            continue
        if getattr(el, "context", False):
            continue  # a finished tile's element, drawn there (issue 19.4)
        if el.type == "seed":
            if not seeds:
                continue
            marks = [Mark.circle(el.proxy.center, 2 * lw, fill="#c33", stroke="none")]  # type: ignore[attr-defined]
        else:
            fn = pat.renderers.get((el.type, style)) or GENERIC_STYLES.get(style) or GENERIC_STYLES["outline"]
            marks = [m for member in members.get(el.index, [el]) for m in fn(member, rc)]
        drawn: list[tuple[list[np.ndarray], bool, dict[str, Any]]] = []
        for m in marks:
            paths = [np.asarray(p, dtype=float) for p in m.paths if len(p)]
            if not paths:
                continue
            if not np.all(np.isfinite(np.vstack(paths))):
                raise InputError(f"render {pat.name!r}/{style!r}: NaN in a mark of element {el.index} ({el.type})")
            if panel is not None:
                paths = _clip_to_panel(paths, m.closed, panel, cover)
                if not paths:
                    continue
            st = {"fill": m.fill, "stroke": m.stroke, "stroke_width": float(m.stroke_width), **m.extra}
            drawn.append((paths, m.closed, st))
        if not drawn:
            continue
        # One row per element, its marks grouped (issue 21: kinds per type, counts per
        # element), in a frame of its own: origin at the mean of its vertices, x axis
        # towards its first vertex, so that x, y and rotation say where it is and which
        # way it faces. Its geometry goes in the `parts` column (each element of a type is
        # curved its own way); the type's first element stands for the kind in the library.
        allp = np.vstack([p for paths, _, _ in drawn for p in paths])
        anchor = allp.mean(axis=0)
        v0 = drawn[0][0][0][0] - anchor
        theta = math.atan2(v0[1], v0[0]) if math.hypot(v0[0], v0[1]) > 1e-9 * (1.0 + float(np.abs(allp).max())) else 0.0
        c, sn = math.cos(theta), math.sin(theta)
        unrot = np.array([[c, sn], [-sn, c]])  # R(-theta)
        parts = [Shape(tuple(Path((p - anchor) @ unrot.T, closed) for p in paths), style=st) for paths, closed, st in drawn]
        name = pat.groups[el.type][1] if el.type in pat.groups else el.type
        if name not in shapes:
            shapes[name] = parts[0]
            order[name] = rank.get(el.type, len(rank))
        kind.append(name)
        col_parts.append(parts)
        xs.append(anchor[0])
        ys.append(anchor[1])
        rots.append(theta)
        col_el.append(el.index)
        col_type.append(name)
        col_parent.append(el.parent.index if el.parent is not None and not getattr(el.parent, "context", False) else -1)
        if _proxies:
            col_groups.append(members.get(el.index, [el]))
            col_commit.append(int(getattr(el, "group", el.index)))
            col_goal.append(getattr(el, "goal_circle", (math.nan, math.nan, math.nan)))
            col_parent_el.append(col_parent[-1])
        col_phase.append(el.phase or "")
    # SVG draws one layer per kind, in library order: order the library by draw order
    shapes = {name: shapes[name] for name in sorted(shapes, key=lambda t: (order[t], t))}
    if not shapes:
        shapes = {"empty": Shape(())}
    meta = {
        "method": "ornament",
        "ornament": {
            "pattern": pat.name,
            "style": style,
            "elements": sum(1 for e in ornament.elements if e.type != "seed" and not getattr(e, "context", False)),
            # the run's wall time stays out, so that outputs are byte-for-byte repeatable
            **{k: (float(v) if isinstance(v, (np.floating, float)) else v) for k, v in ornament.stats.items() if k != "seconds"},
        },
        "params": {**ornament.params, "style": style},
    }
    extra = {}
    if _proxies:
        from ._context import (
            GOAL_COLUMN,
            GROUP_COLUMN,
            PARENT_COLUMN,
            PROXIES_COLUMN,
            records_column,
        )

        extra[PROXIES_COLUMN] = records_column(col_groups, pat)
        extra[GROUP_COLUMN] = np.asarray(col_commit, dtype=np.int64)
        goals = np.empty(len(col_goal), dtype=object)
        for i, g in enumerate(col_goal):
            goals[i] = g
        extra[GOAL_COLUMN] = goals
        # the row that draws each row's parent (PARENT_COLUMN): a group's member stands
        # for its group's first element (a spiral branches from any of its parent's arms)
        row_el = {m.index: e for e, c in zip(col_el, col_groups) for m in c}
        extra[PARENT_COLUMN] = np.asarray([row_el.get(p, -1) for p in col_parent_el], dtype=np.int64)
    return Arrangement(
        shapes,
        np.asarray(kind, dtype=object) if kind else np.zeros(0, int),
        np.asarray(xs, dtype=float),
        np.asarray(ys, dtype=float),
        np.asarray(rots, dtype=float),
        columns={
            "element": np.asarray(col_el, dtype=np.int64),
            "type": np.asarray(col_type, dtype=object),
            "parent": np.asarray(col_parent, dtype=np.int64),
            "phase": np.asarray(col_phase, dtype=object),
            "parts": col_parts,
            **extra,
        },
        region=ornament.region,
        meta=meta,
    )

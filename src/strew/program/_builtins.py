"""Mappers' built-in operators (Table 3) and the script utilities (Table 5).

§6.1: a mapper sees its cell only through these built-ins. None of them gives a cell's
index, the region's origin or any other global information, and the random values are
deterministic functions of the seed and of the cell (see :mod:`._context`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from .._errors import InputError
from ._context import current, top, unit_random
from ._curves import EMPTY, Curve, Curves, as_point
from ._operators import edge_curve
from ._planar_map import Edge, Face, Vertex, _Cell

__all__ = [
    "incident_faces",
    "incident_edges",
    "incident_vertices",
    "source_vertex",
    "target_vertex",
    "left_face",
    "right_face",
    "match_point",
    "match_points",
    "match_face",
    "location",
    "location_at",
    "centroid",
    "contour",
    "append",
    "to_curve",
    "has_label",
    "is_boundary",
    "point_labeled",
    "curve_labeled",
    "random",
    "bbox_width",
    "bbox_height",
    "bbox_center",
    "scale",
    "rotate",
    "translate",
    "nothing",
]


def _need(obj: Any, types: tuple[type, ...], fn: str, what: str) -> None:
    if not isinstance(obj, types):
        raise InputError(f"{fn}: expected {what}, got {type(obj).__name__}")


def _curves_arg(c: Any, fn: str) -> Curves:
    from ._planar_map import PlanarMap

    if isinstance(c, PlanarMap):  # e.g. the result of arrangement(face)
        return c.curves
    _need(c, (Curves,), fn, "curves")
    return c


# -- incidence ------------------------------------------------------------------------------
def incident_faces(v: Vertex) -> list[Face]:
    """IncidentFaces(Vertex v): faces connected to ``v``, in turn around it."""
    _need(v, (Vertex,), "incident_faces", "a vertex")
    t = v._map._t
    out: list[Face] = []
    for e in v._map._vertex_edges[v._i]:
        for f in (int(t.edge_left[e]), int(t.edge_right[e])):
            face = Face(v._map, f)
            if face not in out:
                out.append(face)
    return out


def incident_edges(c: Vertex | Face) -> list[Edge]:
    """IncidentEdges(Vertex | Face c): edges connected to ``c``.

    Around a vertex, in turn by direction; around a face, in turn about its centroid.
    """
    _need(c, (Vertex, Face), "incident_edges", "a vertex or a face")
    if isinstance(c, Vertex):
        return [Edge(c._map, e) for e in c._map._vertex_edges[c._i]]
    return [Edge(c._map, e) for e in c._map._face_edges[c._i]]


def incident_vertices(f: Face) -> list[Vertex]:
    """IncidentVertices(Face f): vertices connected to ``f``."""
    _need(f, (Face,), "incident_vertices", "a face")
    t = f._map._t
    out: list[int] = []
    for e in f._map._face_edges[f._i]:
        for v in (int(t.edge_source[e]), int(t.edge_target[e])):
            if v not in out:
                out.append(v)
    return [Vertex(f._map, v) for v in out]


def source_vertex(e: Edge) -> Vertex:
    """SourceVertex(Edge e): the source vertex of ``e`` (edges follow their curve)."""
    _need(e, (Edge,), "source_vertex", "an edge")
    return Vertex(e._map, int(e._map._t.edge_source[e._i]))


def target_vertex(e: Edge) -> Vertex:
    """TargetVertex(Edge e): the target vertex of ``e``."""
    _need(e, (Edge,), "target_vertex", "an edge")
    return Vertex(e._map, int(e._map._t.edge_target[e._i]))


def left_face(e: Edge) -> Face:
    """LeftFace(Edge e): the face on the left of ``e`` (as seen on screen, y down)."""
    _need(e, (Edge,), "left_face", "an edge")
    return Face(e._map, int(e._map._t.edge_left[e._i]))


def right_face(e: Edge) -> Face:
    """RightFace(Edge e): the face on the right of ``e`` (as seen on screen, y down)."""
    _need(e, (Edge,), "right_face", "an edge")
    return Face(e._map, int(e._map._t.edge_right[e._i]))


# -- adjacency ------------------------------------------------------------------------------
def _affine(c: Curves, m: np.ndarray) -> Curves:
    return c.transformed(m)


def match_point(c: Curves, s: Any, t: Any) -> Curves:
    """MatchPoint(Curves c, Point s, Point t): translates ``c`` by ``t - s``."""
    c = _curves_arg(c, "match_point")
    d = as_point(t, "match_point: t") - as_point(s, "match_point: s")
    return _affine(c, np.array([[1.0, 0.0, d[0]], [0.0, 1.0, d[1]]]))


def match_points(c: Curves, s1: Any, s2: Any, t1: Any, t2: Any) -> Curves:
    """MatchPoints(Curves c, Point s1, Point s2, Point t1, Point t2).

    Applies the transformation (s1, s2) -> (t1, t2) to ``c``: rotation, uniform scale
    and translation, so that ``s1`` lands on ``t1`` and ``s2`` on ``t2``. (The paper says
    "rigid"; a scale is needed whenever |t2 - t1| differs from |s2 - s1|, e.g. to lay a
    stroke along an edge of any length.)
    """
    c = _curves_arg(c, "match_points")
    a, b = as_point(s1, "match_points: s1"), as_point(s2, "match_points: s2")
    p, q = as_point(t1, "match_points: t1"), as_point(t2, "match_points: t2")
    u, v = b - a, q - p
    nu = float(u @ u)
    if nu == 0:
        raise InputError("match_points: s1 and s2 are the same point")
    # complex ratio v / u gives the rotation and scale
    re = (u[0] * v[0] + u[1] * v[1]) / nu
    im = (u[0] * v[1] - u[1] * v[0]) / nu
    A = np.array([[re, -im], [im, re]])
    tr = p - A @ a
    return _affine(c, np.c_[A, tr])


def match_face(c: Curves, f: Face) -> Curves:
    """MatchFace(Curves c, Face f): scales and translates ``c`` into ``f``.

    ``c``'s bounding box is scaled uniformly to fit the face's bounding box and centred
    on it.
    """
    c = _curves_arg(c, "match_face")
    _need(f, (Face,), "match_face", "a face")
    if f.is_unbounded:
        raise InputError("match_face: the unbounded face has no extent")
    x0, y0, x1, y1 = c.bbox
    fx0, fy0, fx1, fy1 = f.polygon.bounds
    w, h = x1 - x0, y1 - y0
    sx = (fx1 - fx0) / w if w > 0 else math.inf
    sy = (fy1 - fy0) / h if h > 0 else math.inf
    s = min(sx, sy)
    if not math.isfinite(s):
        s = 1.0
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    tx, ty = (fx0 + fx1) / 2 - s * cx, (fy0 + fy1) / 2 - s * cy
    return _affine(c, np.array([[s, 0.0, tx], [0.0, s, ty]]))


# -- geometry -------------------------------------------------------------------------------
def location(v: Vertex) -> np.ndarray:
    """Location(Vertex v): the position of ``v``, a (2,) array."""
    _need(v, (Vertex,), "location", "a vertex")
    return v.xy.astype(float)


def location_at(e: Edge, s: float) -> np.ndarray:
    """LocationAt(Edge e, Scalar s): the point at fraction ``s`` in [0, 1] of ``e``'s length."""
    _need(e, (Edge,), "location_at", "an edge")
    s = float(s)
    if not (0.0 <= s <= 1.0):
        raise InputError(f"location_at: s must be in [0, 1], got {s!r}")
    pts = e.points
    seg = np.sqrt((np.diff(pts, axis=0) ** 2).sum(axis=1))
    cum = np.r_[0.0, np.cumsum(seg)]
    target = s * cum[-1]
    k = int(np.clip(np.searchsorted(cum, target, side="right") - 1, 0, len(seg) - 1))
    frac = (target - cum[k]) / seg[k] if seg[k] > 0 else 0.0
    return pts[k] + frac * (pts[k + 1] - pts[k])


def centroid(f: Face) -> np.ndarray:
    """Centroid(Face f): the centroid of ``f``, a (2,) array."""
    _need(f, (Face,), "centroid", "a face")
    if f.is_unbounded:
        raise InputError("centroid: the unbounded face has no centroid")
    return np.asarray(f.polygon.centroid.coords[0], dtype=float)


def contour(f: Face) -> Curves:
    """Contour(Face f): the boundary of ``f``, one curve per boundary edge.

    Each ring of the face is cut at the map's vertices, so the contour keeps the face's
    edge structure (a shrunk contour still has one edge per side, Fig. 7); a ring with no
    vertex is one closed curve. The face's labels ride on the inner side of every curve.
    """
    _need(f, (Face,), "contour", "a face")
    if f.is_unbounded:
        raise InputError("contour: the unbounded face has no contour")
    t = f._map._t
    vindex = f._map.vertex_index
    labs = f.labels
    out = []
    poly = f.polygon
    for k, ring in enumerate([poly.exterior, *poly.interiors]):
        pts = np.asarray(ring.coords)[:-1]
        x, y = pts[:, 0], pts[:, 1]
        area2 = float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
        # the face is on the math-left (screen right) of a positive exterior ring
        face_on_right = (area2 > 0) == (k == 0)
        left, right = (EMPTY, labs) if face_on_right else (labs, EMPTY)
        ij = np.rint(pts / t.grid).astype(np.int64)
        cut = np.array([k for k, (a, b) in enumerate(ij.tolist()) if (a, b) in vindex], dtype=np.int64)
        if len(cut) == 0:
            out.append(Curve(pts, True, EMPTY, left, right))
            continue
        rolled = np.roll(pts, -int(cut[0]), axis=0)
        marks = (cut - cut[0]).tolist() + [len(pts)]
        closed_pts = np.vstack([rolled, rolled[:1]])
        for a, b in zip(marks[:-1], marks[1:]):
            out.append(Curve(closed_pts[a : b + 1], False, EMPTY, left, right))
    return Curves(tuple(out))


def append(c1: Curves, c2: Curves) -> Curves:
    """Append(Curves c1, Curves c2): appends ``c2`` to ``c1`` and returns the new set."""
    c1 = _curves_arg(c1, "append")
    c2 = _curves_arg(c2, "append")
    return c1 + c2


def to_curve(e: Edge) -> Curves:
    """ToCurve(Edge e): edge ``e`` as a curve (with its labels and its faces' labels)."""
    _need(e, (Edge,), "to_curve", "an edge")
    return Curves((edge_curve(e),))


# -- labels ---------------------------------------------------------------------------------
def has_label(c: Any, label: str) -> bool:
    """HasLabel(Cell | Cells c, String l): whether cell ``c`` (or any of cells ``c``) has ``l``.

    Also accepts Curves (any of their curves).
    """
    if not isinstance(label, str):
        raise InputError(f"has_label: the label must be a string, got {type(label).__name__}")
    if isinstance(c, _Cell):
        return label in c.labels  # type: ignore[attr-defined]
    if isinstance(c, Curves):
        return any(label in k.labels for k in c.curves)
    if isinstance(c, Sequence) and not isinstance(c, str):
        for k in c:
            _need(k, (_Cell,), "has_label", "a cell or a list of cells")
        return any(label in k.labels for k in c)  # type: ignore[attr-defined]
    raise InputError(f"has_label: expected a cell or a list of cells, got {type(c).__name__}")


def is_boundary(c: _Cell) -> bool:
    """IsBoundary(Cell c): whether ``c`` is adjacent to the unbounded face."""
    _need(c, (Vertex, Edge, Face), "is_boundary", "a cell")
    t = c._map._t
    if isinstance(c, Edge):
        return int(t.edge_left[c._i]) == 0 or int(t.edge_right[c._i]) == 0
    if isinstance(c, Vertex):
        return any(f.is_unbounded for f in incident_faces(c))
    if c._i == 0:
        return True
    return any(int(t.edge_left[e]) == 0 or int(t.edge_right[e]) == 0 for e in c._map._face_edges[c._i])


def point_labeled(c: Curves, label: str) -> np.ndarray:
    """PointLabeled(Curves c, String l): the location in ``c`` labelled ``l``, a (2,) array."""
    c = _curves_arg(c, "point_labeled")
    if label not in c.points:
        have = ", ".join(sorted(c.points)) or "none"
        raise InputError(f"point_labeled: no point labelled {label!r} (have: {have})")
    return np.asarray(c.points[label], dtype=float)


def curve_labeled(c: Curves, label: str) -> Curves:
    """CurveLabeled(Curves c, String l): the curve(s) of ``c`` labelled ``l``."""
    c = _curves_arg(c, "curve_labeled")
    sel = [label in k.labels for k in c.curves]
    if not any(sel):
        have = ", ".join(sorted(set().union(*[k.labels for k in c.curves]))) or "none"
        raise InputError(f"curve_labeled: no curve labelled {label!r} (have: {have})")
    return c.select(sel)


# -- random values --------------------------------------------------------------------------
def random(*args: Any) -> float:
    """Random(min, max) or Random(Cell c, min, max, n).

    ``random(lo, hi)``: a value in [lo, hi] drawn from the stream of the current level
    (the script, or the cell a mapper is running on), so it is repeatable for a seed.

    ``random(cell, lo, hi, n)``: a deterministic value that is always the same for a
    given cell and ``n`` (and seed): a hash of the seed, the cell's own geometry and
    ``n``, independent of execution order (§6.1).
    """
    if len(args) == 2:
        lo, hi = _bounds(args[0], args[1])
        ctx = current() or top()
        return lo + (hi - lo) * float(ctx.stream.random())
    if len(args) == 4:
        cell, lo, hi, n = args
        _need(cell, (Vertex, Edge, Face), "random", "a cell as first argument of random(cell, min, max, n)")
        lo, hi = _bounds(lo, hi)
        ctx = current() or top()
        return lo + (hi - lo) * unit_random(ctx.root, "cell", cell.key, repr(float(n)) if isinstance(n, (int, float)) else repr(n))
    raise InputError(f"random: expected random(min, max) or random(cell, min, max, n), got {len(args)} arguments")


def _bounds(lo: Any, hi: Any) -> tuple[float, float]:
    try:
        a, b = float(lo), float(hi)
    except (TypeError, ValueError):
        raise InputError(f"random: min and max must be numbers, got {lo!r}, {hi!r}") from None
    if not (math.isfinite(a) and math.isfinite(b)):
        raise InputError("random: min and max must be finite")
    return a, b


# -- Table 5 ----------------------------------------------------------------------------------
def _bbox(c: Any, fn: str) -> tuple[float, float, float, float]:
    if isinstance(c, Curves):
        return c.bbox
    if isinstance(c, Vertex):
        x, y = c.xy
        return (float(x), float(y), float(x), float(y))
    if isinstance(c, Edge):
        p = c.points
        return (float(p[:, 0].min()), float(p[:, 1].min()), float(p[:, 0].max()), float(p[:, 1].max()))
    if isinstance(c, Face):
        if c.is_unbounded:
            raise InputError(f"{fn}: the unbounded face has no bounding box")
        return tuple(float(v) for v in c.polygon.bounds)  # type: ignore[return-value]
    raise InputError(f"{fn}: expected a cell or curves, got {type(c).__name__}")


def bbox_width(c: Any) -> float:
    """BBoxWidth(Cell | Curves c): bounding box width of ``c``."""
    x0, _, x1, _ = _bbox(c, "bbox_width")
    return x1 - x0


def bbox_height(c: Any) -> float:
    """BBoxHeight(Cell | Curves c): bounding box height of ``c``."""
    _, y0, _, y1 = _bbox(c, "bbox_height")
    return y1 - y0


def bbox_center(c: Any) -> np.ndarray:
    """BBoxCenter(Cell | Curves c): bounding box centre of ``c``, a (2,) array."""
    x0, y0, x1, y1 = _bbox(c, "bbox_center")
    return np.array([(x0 + x1) / 2, (y0 + y1) / 2])


def _about_center(c: Curves, a: np.ndarray) -> Curves:
    ctr = bbox_center(c)
    return c.transformed(np.c_[a, ctr - a @ ctr])


def scale(c: Curves, s: float) -> Curves:
    """Scale(Curves c, Scalar s): scales ``c`` by ``s`` about its bounding-box centre.

    Scaling about a fixed point of the plane would depend on global coordinates (§6.1),
    so the centre of ``c`` is used.
    """
    c = _curves_arg(c, "scale")
    s = float(s)
    if not math.isfinite(s):
        raise InputError(f"scale: factor must be finite, got {s!r}")
    return _about_center(c, np.array([[s, 0.0], [0.0, s]]))


def rotate(c: Curves, s: float) -> Curves:
    """Rotate(Curves c, Scalar s): rotates ``c`` by ``s`` radians about its bounding-box centre."""
    c = _curves_arg(c, "rotate")
    a = float(s)
    if not math.isfinite(a):
        raise InputError(f"rotate: angle must be finite, got {s!r}")
    co, si = math.cos(a), math.sin(a)
    return _about_center(c, np.array([[co, -si], [si, co]]))


def translate(c: Curves, v: Any) -> Curves:
    """Translate(Curves c, Vector v): translates ``c`` by ``v``."""
    c = _curves_arg(c, "translate")
    d = as_point(v, "translate: v")
    return c.transformed(np.array([[1.0, 0.0, d[0]], [0.0, 1.0, d[1]]]))


def nothing() -> Curves:
    """Nothing(): an empty set of curves."""
    return Curves()


"""Proxies (Wong et al. 1998, §3.2, §4.2) and the small geometry library for rule bodies.

A proxy is a simple geometric shape standing for an element, or part of one, when the
framework looks for empty space and tests intersections. Available proxies, as in §4.2:
:class:`Point`, :class:`Circle`, :class:`Arc`, :class:`Segment` (``linesegment``),
:class:`Bezier` (cubic) and :class:`Polygon`. Each has a ``set(...)`` method, the
``$k.set(...)`` of the paper's rule bodies.

Points are ``(2,)`` float arrays in document units (y down). Directions are given either
as an angle in radians (measured from +x towards +y) or as a vector; the helpers
:func:`offset`, :func:`polar`, :func:`angle_of`, :func:`distance` and :func:`unit` cover
what the paper's support library offers (``p.offset(dir, d)``, ``~(a - b)``, ``dir + pi/2``).
"""

from __future__ import annotations

import abc
import math
from typing import Any

import numpy as np
import shapely

from .._errors import InputError

__all__ = [
    "Proxy",
    "Point",
    "Circle",
    "Arc",
    "Segment",
    "LineSegment",
    "Bezier",
    "Polygon",
    "PROXY_TYPES",
    "vec",
    "angle_of",
    "polar",
    "offset",
    "distance",
    "unit",
]


# -- vector helpers ---------------------------------------------------------------------
def vec(x: Any, y: float | None = None) -> np.ndarray:
    """A point or vector as a ``(2,)`` float array: ``vec(x, y)`` or ``vec(pair)``."""
    if y is None:
        a = np.asarray(x, dtype=float).reshape(-1)
        if a.shape != (2,):
            raise InputError(f"expected a point (x, y), got {x!r}")
        return a.copy()
    return np.array([float(x), float(y)])


def angle_of(direction: Any) -> float:
    """Angle in radians of a direction given as an angle or a vector."""
    if np.ndim(direction) == 0:
        return float(direction)
    d = vec(direction)
    return math.atan2(d[1], d[0])


def polar(angle: float, length: float = 1.0) -> np.ndarray:
    """The vector of ``length`` at ``angle`` radians."""
    return np.array([length * math.cos(angle), length * math.sin(angle)])


def offset(point: Any, direction: Any, dist: float) -> np.ndarray:
    """``point`` moved ``dist`` along ``direction`` (an angle or a vector), the paper's ``p.offset``."""
    return vec(point) + polar(angle_of(direction), dist)


def distance(a: Any, b: Any) -> float:
    """Euclidean distance between two points (the paper's ``~(a - b)``)."""
    d = vec(a) - vec(b)
    return math.hypot(d[0], d[1])


def unit(v: Any) -> np.ndarray:
    """``v`` scaled to length 1 (``(1, 0)`` for a zero vector)."""
    v = vec(v)
    n = math.hypot(v[0], v[1])
    return v / n if n > 0 else np.array([1.0, 0.0])


def _finite_point(p: Any, what: str) -> np.ndarray:
    a = vec(p)
    if not np.all(np.isfinite(a)):
        raise InputError(f"{what}: NaN or inf coordinate {a.tolist()}")
    return a


# -- proxies ------------------------------------------------------------------------------
class Proxy(abc.ABC):
    """Base class of proxies. ``is_set`` is False until ``set`` has been called."""

    kind = "proxy"
    __slots__ = ("_geom",)

    def __init__(self) -> None:
        self._geom = None

    @property
    @abc.abstractmethod
    def is_set(self) -> bool:
        """True once ``set`` has been called."""

    def _need(self) -> None:
        if not self.is_set:
            raise InputError(f"{self.kind} proxy used before set()")

    @property
    def geometry(self) -> shapely.Geometry:
        """Exact shapely geometry (curves flattened finely) used for intersection tests."""
        if self._geom is None:
            self._need()
            self._geom = self._make_geometry()
        return self._geom

    @abc.abstractmethod
    def _make_geometry(self) -> shapely.Geometry:
        """The shapely geometry of a set proxy."""

    @abc.abstractmethod
    def polyline(self) -> np.ndarray:
        """(n, 2) points of the proxy's outline (closed outlines do not repeat the first point)."""

    @property
    def closed(self) -> bool:
        """True when :meth:`polyline` is a closed outline."""
        return False

    def bounding_circle(self) -> tuple[float, float, float]:
        """``(cx, cy, r)``: a circle enclosing the proxy."""
        pts = self.polyline()
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        c = (lo + hi) / 2
        r = float(np.sqrt(((pts - c) ** 2).sum(axis=1)).max())
        return float(c[0]), float(c[1]), r

    def __repr__(self) -> str:
        return f"{type(self).__name__}(unset)" if not self.is_set else f"{type(self).__name__}({self._fields()})"

    def _fields(self) -> str:  # pragma: no cover - cosmetic
        return ""


class Point(Proxy):
    """A point proxy; the required ``seed`` type has one (§4.2). Field: ``center``."""

    kind = "point"
    __slots__ = ("center",)

    def __init__(self) -> None:
        super().__init__()
        self.center: np.ndarray | None = None

    @property
    def is_set(self) -> bool:
        return self.center is not None

    def set(self, point: Any) -> Point:
        self.center = _finite_point(point, "point.set")
        self._geom = None
        return self

    @property
    def position(self) -> np.ndarray:
        self._need()
        return self.center  # type: ignore[return-value]

    def _make_geometry(self) -> shapely.Geometry:
        return shapely.Point(self.center)

    def polyline(self) -> np.ndarray:
        self._need()
        return self.center.reshape(1, 2)  # type: ignore[union-attr]

    def bounding_circle(self) -> tuple[float, float, float]:
        self._need()
        return float(self.center[0]), float(self.center[1]), 0.0  # type: ignore[index]

    def _fields(self) -> str:
        return f"center={self.center.tolist()}"  # type: ignore[union-attr]


class Circle(Proxy):
    """A circle proxy. Fields: ``center`` (2,), ``radius``."""

    kind = "circle"
    __slots__ = ("center", "radius")

    def __init__(self) -> None:
        super().__init__()
        self.center: np.ndarray | None = None
        self.radius: float = 0.0

    @property
    def is_set(self) -> bool:
        return self.center is not None

    def set(self, center: Any, radius: float) -> Circle:
        """Place the circle, the paper's ``$k.set(center, radius)``."""
        r = float(radius)
        if not (math.isfinite(r) and r >= 0):
            raise InputError(f"circle.set: radius must be finite and >= 0, got {radius!r}")
        self.center = _finite_point(center, "circle.set")
        self.radius = r
        self._geom = None
        return self

    def _make_geometry(self) -> shapely.Geometry:
        return shapely.Point(self.center).buffer(self.radius, quad_segs=32)

    def polyline(self, segments: int = 64) -> np.ndarray:
        self._need()
        t = np.linspace(0, 2 * np.pi, segments, endpoint=False)
        return self.center + self.radius * np.c_[np.cos(t), np.sin(t)]

    @property
    def closed(self) -> bool:
        return True

    def bounding_circle(self) -> tuple[float, float, float]:
        self._need()
        return float(self.center[0]), float(self.center[1]), self.radius  # type: ignore[index]

    def _fields(self) -> str:
        return f"center={self.center.tolist()}, radius={self.radius:g}"  # type: ignore[union-attr]


class Arc(Proxy):
    """A circular arc. Fields: ``center``, ``radius``, ``start``, ``end`` (radians; from start to end)."""

    kind = "arc"
    __slots__ = ("center", "radius", "start", "end")

    def __init__(self) -> None:
        super().__init__()
        self.center: np.ndarray | None = None
        self.radius = 0.0
        self.start = 0.0
        self.end = 0.0

    @property
    def is_set(self) -> bool:
        return self.center is not None

    def set(self, center: Any, radius: float, start: float, end: float) -> Arc:
        r = float(radius)
        if not (math.isfinite(r) and r > 0):
            raise InputError(f"arc.set: radius must be finite and > 0, got {radius!r}")
        self.center = _finite_point(center, "arc.set")
        self.radius, self.start, self.end = r, float(start), float(end)
        self._geom = None
        return self

    def polyline(self) -> np.ndarray:
        self._need()
        n = max(2, int(np.ceil(abs(self.end - self.start) / (np.pi / 32))) + 1)
        t = np.linspace(self.start, self.end, n)
        return self.center + self.radius * np.c_[np.cos(t), np.sin(t)]

    def _make_geometry(self) -> shapely.Geometry:
        return shapely.LineString(self.polyline())


class Segment(Proxy):
    """A line segment (the paper's ``linesegment``). Fields: ``start``, ``end``."""

    kind = "linesegment"
    __slots__ = ("start", "end")

    def __init__(self) -> None:
        super().__init__()
        self.start: np.ndarray | None = None
        self.end: np.ndarray | None = None

    @property
    def is_set(self) -> bool:
        return self.start is not None

    def set(self, start: Any, end: Any) -> Segment:
        """Place the segment from ``start`` to ``end``, the paper's ``$0.set($.center, $1.center)``."""
        self.start = _finite_point(start, "linesegment.set")
        self.end = _finite_point(end, "linesegment.set")
        self._geom = None
        return self

    @property
    def length(self) -> float:
        self._need()
        return distance(self.start, self.end)

    def polyline(self) -> np.ndarray:
        self._need()
        return np.array([self.start, self.end])

    def _make_geometry(self) -> shapely.Geometry:
        return shapely.LineString(self.polyline())


LineSegment = Segment


class Bezier(Proxy):
    """A cubic Bézier segment. Field: ``points`` (4, 2) control points."""

    kind = "bezier"
    __slots__ = ("points",)

    def __init__(self) -> None:
        super().__init__()
        self.points: np.ndarray | None = None

    @property
    def is_set(self) -> bool:
        return self.points is not None

    def set(self, p0: Any, dir0: Any, mag0: float, p3: Any, dir3: Any, mag3: float) -> Bezier:
        """Place by end points, tangent directions and magnitudes (Appendix A, ``$x(0).set``).

        The curve leaves ``p0`` heading along ``dir0`` and arrives at ``p3`` heading along
        ``dir3``. The magnitudes are fractions of the chord ``|p3 - p0|`` (the paper leaves
        their unit implicit; with its leaf values 0.6 and 0.4 this gives its leaf shape).
        """
        a = _finite_point(p0, "bezier.set")
        d = _finite_point(p3, "bezier.set")
        chord = distance(a, d)
        b = a + polar(angle_of(dir0), float(mag0) * chord)
        c = d - polar(angle_of(dir3), float(mag3) * chord)
        return self.set_points(a, b, c, d)

    def set_points(self, p0: Any, p1: Any, p2: Any, p3: Any) -> Bezier:
        """Place by the four control points."""
        pts = np.array([_finite_point(p, "bezier.set_points") for p in (p0, p1, p2, p3)])
        self.points = pts
        self._geom = None
        return self

    def point_at(self, t: float | np.ndarray) -> np.ndarray:
        """Point(s) at parameter ``t`` in [0, 1]: (2,) or (n, 2)."""
        self._need()
        t = np.asarray(t, dtype=float)
        tt = t[..., None]
        p = self.points
        return (
            (1 - tt) ** 3 * p[0] + 3 * (1 - tt) ** 2 * tt * p[1] + 3 * (1 - tt) * tt**2 * p[2] + tt**3 * p[3]  # type: ignore[index]
        )

    def tangent_at(self, t: float) -> np.ndarray:
        """Unit tangent at ``t``."""
        self._need()
        p = self.points
        d = 3 * (1 - t) ** 2 * (p[1] - p[0]) + 6 * (1 - t) * t * (p[2] - p[1]) + 3 * t**2 * (p[3] - p[2])  # type: ignore[index]
        if np.hypot(*d) < 1e-12:
            d = p[3] - p[0]  # type: ignore[index]
        return unit(d)

    @property
    def start(self) -> np.ndarray:
        self._need()
        return self.points[0]  # type: ignore[index]

    @property
    def end(self) -> np.ndarray:
        self._need()
        return self.points[3]  # type: ignore[index]

    def polyline(self, segments: int = 24) -> np.ndarray:
        return self.point_at(np.linspace(0.0, 1.0, segments + 1))

    def _make_geometry(self) -> shapely.Geometry:
        return shapely.LineString(self.polyline(48))


class Polygon(Proxy):
    """A closed polygon. Field: ``points`` (n, 2), n >= 3."""

    kind = "polygon"
    __slots__ = ("points",)

    def __init__(self) -> None:
        super().__init__()
        self.points: np.ndarray | None = None

    @property
    def is_set(self) -> bool:
        return self.points is not None

    def set(self, points: Any) -> Polygon:
        pts = np.asarray(points, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 3 or not np.all(np.isfinite(pts)):
            raise InputError("polygon.set: need at least three finite points (n, 2)")
        self.points = pts.copy()
        self._geom = None
        return self

    @property
    def closed(self) -> bool:
        return True

    def polyline(self) -> np.ndarray:
        self._need()
        return self.points  # type: ignore[return-value]

    def _make_geometry(self) -> shapely.Geometry:
        g = shapely.Polygon(self.points)
        if not g.is_valid:
            g = shapely.make_valid(g)
        return g


PROXY_TYPES: dict[str, type[Proxy]] = {
    "point": Point,
    "circle": Circle,
    "arc": Arc,
    "linesegment": Segment,
    "segment": Segment,
    "bezier": Bezier,
    "polygon": Polygon,
}

"""Shape: the geometry of one element kind, in local coordinates.

A shape is a list of polyline paths (curves are flattened when imported; the exact SVG
path data may be kept in ``d``), a style, and named points (``labels``) such as
``"start"`` and ``"end"``. Closed paths bound the filled area under the even-odd rule;
open paths are strokes.

The element's local origin ``(0, 0)`` is its position: an element placed at ``(x, y)``
with rotation ``t`` and scale ``s`` maps a local point ``p`` to
``(x, y) + s * R(t) @ p`` (see :mod:`strew.arrangement`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, NamedTuple

import numpy as np
import shapely

from ._errors import InputError
from ._limits import MAX_COORD

__all__ = ["Path", "Shape", "paths_to_polygon"]


class Path(NamedTuple):
    """One polyline of a shape or region.

    Attributes
    ----------
    points : (n, 2) float ndarray
        Vertices. A closed path does not repeat its first vertex at the end.
    closed : bool
        Whether the last vertex joins the first.
    """

    points: np.ndarray
    closed: bool = True


def _as_points(points: Any, where: str) -> np.ndarray:
    try:
        arr = np.asarray(points, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{where}: points must be numbers ({exc})") from None
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise InputError(f"{where}: points must have shape (n, 2), got {arr.shape}")
    # one pass for both checks (NaN fails the comparison too): shapes are made by the
    # thousand when an SVG of many kinds is read (issue 17.3)
    if arr.size and not float(np.abs(arr).max()) <= MAX_COORD:
        if not np.isfinite(arr).all():
            raise InputError(f"{where}: NaN or inf coordinate")
        # beyond this, squared distances and areas overflow (issue 17)
        raise InputError(f"{where}: coordinate magnitude over {MAX_COORD:.0e}")
    return arr


def _normalise_path(p: Any, where: str) -> Path:
    if isinstance(p, Path):
        pts, closed = p.points, p.closed
    elif isinstance(p, Mapping):
        if "points" not in p:
            raise InputError(f"{where}: missing 'points'")
        pts, closed = p["points"], bool(p.get("closed", True))
    else:
        pts, closed = p, True
    arr = _as_points(pts, f"{where}.points")
    if closed and len(arr) > 1 and arr[0, 0] == arr[-1, 0] and arr[0, 1] == arr[-1, 1]:
        arr = arr[:-1]
    arr = np.ascontiguousarray(arr)
    arr.setflags(write=False)
    return Path(arr, closed)


def _polygonal(geom: shapely.Geometry) -> shapely.Geometry:
    """The polygonal parts of ``geom`` as one geometry."""
    parts = [g for g in shapely.get_parts(geom) if isinstance(g, (shapely.Polygon, shapely.MultiPolygon))]
    return shapely.union_all(parts) if parts else shapely.Polygon()


def paths_to_polygon(paths: Iterable[Path]) -> shapely.Geometry:
    """Filled area of closed paths under the even-odd rule.

    Parameters
    ----------
    paths : iterable of Path
        Open paths and closed paths with fewer than three vertices are ignored.

    Returns
    -------
    shapely Polygon or MultiPolygon (possibly empty)
    """
    result = shapely.Polygon()
    for p in paths:
        if not p.closed or len(p.points) < 3:
            continue
        ring = shapely.Polygon(p.points)
        if not ring.is_valid:
            ring = _polygonal(shapely.make_valid(ring))
        if ring.is_empty or ring.area == 0:
            continue
        result = shapely.symmetric_difference(result, ring) if not result.is_empty else ring
    if result.is_empty:
        return shapely.Polygon()
    polys = [g for g in shapely.get_parts(result) if isinstance(g, shapely.Polygon) and g.area > 0]
    if not polys:
        return shapely.Polygon()
    return polys[0] if len(polys) == 1 else shapely.MultiPolygon(polys)


@dataclass(frozen=True, eq=False)
class Shape:
    """Geometry of one element kind in local coordinates.

    Parameters
    ----------
    paths : sequence of Path, (n, 2) arrays or ``{"points": ..., "closed": ...}`` dicts
        Polylines. Closed paths bound the area (even-odd rule); open paths are strokes.
    d : str, optional
        Exact SVG path data, kept for curves; ``paths`` is its flattening.
    style : mapping, optional
        Presentation: ``fill``, ``stroke``, ``stroke_width``, ``opacity`` ...
    labels : mapping of str to (2,) points, optional
        Named points, e.g. ``{"start": (0, 0), "end": (10, 0)}``.

    Examples
    --------
    >>> sq = Shape.rectangle(2, 1)
    >>> round(sq.area, 6)
    2.0
    >>> sq.bounds
    (-1.0, -0.5, 1.0, 0.5)
    """

    paths: tuple[Path, ...]
    d: str | None = None
    style: Mapping[str, Any] = field(default_factory=dict)
    labels: Mapping[str, tuple[float, float]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        paths = self.paths
        if isinstance(paths, (Path, np.ndarray)):
            paths = [paths]
        norm = tuple(_normalise_path(p, f"paths[{i}]") for i, p in enumerate(paths))
        object.__setattr__(self, "paths", norm)
        object.__setattr__(self, "style", dict(self.style or {}))
        labels = {}
        for name, pt in dict(self.labels or {}).items():
            arr = np.asarray(pt, dtype=float)
            if arr.shape != (2,) or not np.all(np.isfinite(arr)):
                raise InputError(f"labels.{name}: must be a finite point [x, y]")
            labels[str(name)] = (float(arr[0]), float(arr[1]))
        object.__setattr__(self, "labels", labels)

    # -- constructors -----------------------------------------------------------------
    @classmethod
    def _checked(cls, paths: tuple[Path, ...], d: str | None, style: Mapping[str, Any], labels: dict[str, tuple[float, float]]) -> Shape:
        """A shape whose caller has checked what ``__post_init__`` checks and makes: every
        path's points a read-only, C-contiguous float (n, 2) array, finite and within
        ``MAX_COORD``, a closed path not repeating its first point at the end, labels
        ``(float, float)``. Nothing is copied or checked again (a reader that makes
        thousands of shapes checks them all at once, issue 17.3)."""
        shape = object.__new__(cls)
        shape.__dict__.update(paths=paths, d=d, style=dict(style), labels=labels)  # frozen: no __setattr__
        return shape

    @classmethod
    def from_geometry(cls, geom: shapely.Geometry, **kwargs: Any) -> Shape:
        """Shape from a shapely geometry (polygons with holes, lines, or collections)."""
        paths: list[Path] = []
        for part in shapely.get_parts(geom):
            if isinstance(part, shapely.Polygon):
                for ring in [part.exterior, *part.interiors]:
                    paths.append(Path(np.asarray(ring.coords)[:-1], True))
            elif isinstance(part, shapely.LineString):
                paths.append(Path(np.asarray(part.coords), False))
            elif isinstance(part, shapely.LinearRing):
                paths.append(Path(np.asarray(part.coords)[:-1], True))
            elif isinstance(part, shapely.GeometryCollection):
                paths.extend(cls.from_geometry(part).paths)
        return cls(tuple(paths), **kwargs)

    @classmethod
    def polygon(cls, points: Sequence[Sequence[float]] | np.ndarray, **kwargs: Any) -> Shape:
        """Shape of one closed polygon."""
        return cls((Path(np.asarray(points, dtype=float), True),), **kwargs)

    @classmethod
    def rectangle(cls, width: float, height: float, **kwargs: Any) -> Shape:
        """Axis-aligned rectangle centred on the origin."""
        w, h = width / 2, height / 2
        return cls.polygon([(-w, -h), (w, -h), (w, h), (-w, h)], **kwargs)

    @classmethod
    def circle(cls, radius: float, segments: int = 32, **kwargs: Any) -> Shape:
        """Regular polygon approximating a circle centred on the origin."""
        t = np.linspace(0, 2 * np.pi, segments, endpoint=False)
        return cls.polygon(np.c_[radius * np.cos(t), radius * np.sin(t)], **kwargs)

    # -- geometry ---------------------------------------------------------------------
    @cached_property
    def area_geometry(self) -> shapely.Geometry:
        """Filled area (even-odd rule over closed paths); empty if there is none."""
        return paths_to_polygon(self.paths)

    @cached_property
    def has_area(self) -> bool:
        """True when :attr:`area_geometry` is not empty, mostly without building it.

        One valid ring of positive area, or one whose area exceeds the others' together
        (the even-odd area is then at least the difference), settles it; anything else
        (invalid rings, rings that might cancel) asks :attr:`area_geometry` itself.
        """
        if "area_geometry" in self.__dict__:
            return not self.area_geometry.is_empty
        rings = [p.points for p in self.paths if p.closed and len(p.points) >= 3]
        if not rings:
            return False
        polys = shapely.polygons([shapely.linearrings(r) for r in rings])
        if not shapely.is_valid(polys).all():
            return not self.area_geometry.is_empty
        area = shapely.area(polys)
        if area.max() > 0 and area.max() > area.sum() - area.max():
            return True
        return not self.area_geometry.is_empty

    @cached_property
    def line_geometry(self) -> shapely.Geometry:
        """Open paths as a (Multi)LineString; empty if there is none."""
        lines = [shapely.LineString(p.points) for p in self.paths if not p.closed and len(p.points) >= 2]
        if not lines:
            return shapely.LineString()
        return lines[0] if len(lines) == 1 else shapely.MultiLineString(lines)

    @cached_property
    def geometry(self) -> shapely.Geometry:
        """The geometry used for collisions and metrics.

        The filled area when there is one, else the strokes as lines.
        """
        area = self.area_geometry
        return area if not area.is_empty else self.line_geometry

    @property
    def is_empty(self) -> bool:
        """True when the shape has no drawable geometry."""
        return self.geometry.is_empty

    @property
    def area(self) -> float:
        """Area of the filled part."""
        return float(self.area_geometry.area)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """``(minx, miny, maxx, maxy)`` of all path points (zeros when there is none)."""
        pts = self.points
        if len(pts) == 0:  # no path, or only empty ones
            return (0.0, 0.0, 0.0, 0.0)
        return (float(pts[:, 0].min()), float(pts[:, 1].min()), float(pts[:, 0].max()), float(pts[:, 1].max()))

    @property
    def radius(self) -> float:
        """Bounding radius about the local origin: the largest distance of a path point."""
        pts = self.points
        if len(pts) == 0:
            return 0.0
        return float(np.sqrt((pts**2).sum(axis=1)).max())

    @property
    def points(self) -> np.ndarray:
        """(n, 2) all path vertices concatenated."""
        if not self.paths:
            return np.zeros((0, 2))
        return np.concatenate([p.points for p in self.paths])

    # -- transforms -------------------------------------------------------------------
    def transformed(self, matrix: np.ndarray | Sequence[Sequence[float]]) -> Shape:
        """Shape with every point and label mapped by a 2x3 affine ``matrix``.

        The exact path data ``d`` is dropped, since it is no longer valid.
        """
        m = np.asarray(matrix, dtype=float)
        a, t = m[:, :2], m[:, 2]
        paths = tuple(Path(p.points @ a.T + t, p.closed) for p in self.paths)
        labels = {k: tuple(np.asarray(v) @ a.T + t) for k, v in self.labels.items()}
        return Shape(paths, None, self.style, labels)

    def translated(self, dx: float, dy: float) -> Shape:
        """Shape moved by ``(dx, dy)``."""
        return self.transformed([[1, 0, dx], [0, 1, dy]])

    def centered(self) -> Shape:
        """Shape moved so that its bounding-box centre is the local origin."""
        x0, y0, x1, y1 = self.bounds
        return self.translated(-(x0 + x1) / 2, -(y0 + y1) / 2)

    def with_style(self, **style: Any) -> Shape:
        """Copy with style entries replaced."""
        return Shape(self.paths, self.d, {**self.style, **style}, self.labels)

    # -- serialisation ----------------------------------------------------------------
    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict, as in the strew document's ``shapes`` entries."""
        out: dict[str, Any] = {
            "paths": [{"points": p.points.tolist(), "closed": bool(p.closed)} for p in self.paths]
        }
        if self.d is not None:
            out["d"] = self.d
        if self.style:
            out["style"] = dict(self.style)
        if self.labels:
            out["labels"] = {k: [v[0], v[1]] for k, v in self.labels.items()}
        return out

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], where: str = "shape") -> Shape:
        """Inverse of :meth:`to_dict`; raises :class:`InputError` naming the field."""
        if not isinstance(data, Mapping):
            raise InputError(f"{where}: must be an object")
        if "paths" not in data:
            raise InputError(f"{where}.paths: missing")
        paths = data["paths"]
        if not isinstance(paths, list):
            raise InputError(f"{where}.paths: must be a list")
        norm = [_normalise_path(p, f"{where}.paths[{i}]") for i, p in enumerate(paths)]
        d = data.get("d")
        if d is not None and not isinstance(d, str):
            raise InputError(f"{where}.d: must be a string")
        style = data.get("style") or {}
        if not isinstance(style, Mapping):
            raise InputError(f"{where}.style: must be an object")
        labels = data.get("labels") or {}
        if not isinstance(labels, Mapping):
            raise InputError(f"{where}.labels: must be an object")
        try:
            return cls(tuple(norm), d, style, labels)
        except InputError as exc:
            raise InputError(f"{where}.{exc}") from None

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Shape):
            return NotImplemented
        return (
            len(self.paths) == len(other.paths)
            and all(a.closed == b.closed and np.array_equal(a.points, b.points) for a, b in zip(self.paths, other.paths))
            and self.d == other.d
            and dict(self.style) == dict(other.style)
            and dict(self.labels) == dict(other.labels)
        )

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        n = sum(len(p.points) for p in self.paths)
        return f"Shape({len(self.paths)} paths, {n} points, bounds={tuple(round(b, 3) for b in self.bounds)})"

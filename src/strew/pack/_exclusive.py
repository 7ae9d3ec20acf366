"""Exclusive regions (Sakurai & Miyata §3.1).

An exclusive region is the area an element claims: two placed exclusive regions never
overlap. It is independent of the element's drawing: by default it is the element's own
filled area, grown by a margin (a buffer), or the user gives one shape per kind.

Transformation (§3.1, Eq. 1): ``x = (R S + T) x0`` about the centre of the exclusive
region's bounding box. In strew's convention an element maps a local point ``p`` to
``(x, y) + s R(t) p``; placing the bounding-box centre ``c`` at ``T`` therefore means
``(x, y) = T - s R(t) c`` (see :func:`element_origin`).
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import shapely

from .._errors import InputError
from ..shape import Shape

__all__ = ["ExclusiveRegion", "PackWarning", "build_exclusive_regions", "transform_many", "element_origin"]


class PackWarning(UserWarning):
    """A shape was usable only after a repair (e.g. a self-intersecting outline)."""


@dataclass(frozen=True)
class ExclusiveRegion:
    """One kind's exclusive region, centred on its bounding-box centre.

    Attributes
    ----------
    name : str
        Kind name.
    body : shapely Polygon or MultiPolygon
        Exclusive region in centred local coordinates (collisions use it).
    hull : shapely geometry
        What must lie inside the domain: the exclusive region and the element itself.
    centre : (2,) float
        Bounding-box centre of the exclusive region in the shape's own coordinates.
    radius : float
        Radius of the circumscribed circle O about the centre (§4.1, Fig. 9).
    area : float
        Area of ``body``.
    rotation : (lo, hi) float
        Rotation range in radians.
    scale : (lo, hi) float
        Scale range (positive).
    """

    name: str
    body: shapely.Geometry
    hull: shapely.Geometry
    centre: np.ndarray
    radius: float
    area: float
    rotation: tuple[float, float]
    scale: tuple[float, float]


def _self_intersecting_paths(shape: Shape) -> list[int]:
    bad = []
    for i, p in enumerate(shape.paths):
        if p.closed and len(p.points) >= 3:
            ring = shapely.LinearRing(p.points)
            if not ring.is_simple:
                bad.append(i)
    return bad


def _check_range(value: object, name: str, *, positive: bool = False) -> tuple[float, float]:
    try:
        lo, hi = (float(v) for v in value)  # type: ignore[union-attr]
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected a (low, high) pair of numbers, got {value!r}") from None
    if not (np.isfinite(lo) and np.isfinite(hi)):
        raise InputError(f"{name}: must be finite, got ({lo}, {hi})")
    if lo > hi:
        raise InputError(f"{name}: inverted range ({lo:g}, {hi:g}); low must not exceed high")
    if positive and lo <= 0:
        raise InputError(f"{name}: scales must be positive, got ({lo:g}, {hi:g})")
    return lo, hi


def _per_kind(value: object, kinds: list[str], name: str, default: object) -> dict[str, object]:
    """Resolve a value given once for all kinds, or per kind as a mapping."""
    if isinstance(value, Mapping):
        unknown = [k for k in value if k not in kinds and k != "*"]
        if unknown:
            raise InputError(f"{name}: unknown kind {unknown[0]!r} (kinds: {', '.join(kinds)})")
        base = value.get("*", default)
        return {k: value.get(k, base) for k in kinds}
    return {k: (default if value is None else value) for k in kinds}


def build_exclusive_regions(
    shapes: Mapping[str, Shape],
    *,
    rotation: object = (0.0, 2 * np.pi),
    scale: object = (1.0, 1.0),
    margin: object = 0.0,
    exclusive: Mapping[str, Shape] | None = None,
) -> list[ExclusiveRegion]:
    """Exclusive regions of every kind, validated.

    Parameters
    ----------
    shapes : mapping of str to Shape
    rotation, scale : (lo, hi) or mapping of kind -> (lo, hi)
        Ranges; a mapping may hold ``"*"`` for the kinds it does not name.
    margin : float or mapping of kind -> float
        Buffer distance added around the exclusive region (may be negative to shrink).
    exclusive : mapping of kind -> Shape, optional
        Exclusive shapes in the element's local coordinates; default: the element.

    Returns
    -------
    list of ExclusiveRegion, in the order of ``shapes``

    Raises
    ------
    InputError
        Zero-area exclusive regions, inverted or non-finite ranges, unknown kinds.
    """
    kinds = list(shapes)
    if not kinds:
        raise InputError("shapes: no shape given")
    exclusive = dict(exclusive or {})
    unknown = [k for k in exclusive if k not in shapes]
    if unknown:
        raise InputError(f"exclusive: unknown kind {unknown[0]!r} (kinds: {', '.join(kinds)})")
    rot = _per_kind(rotation, kinds, "rotation", (0.0, 2 * np.pi))
    sca = _per_kind(scale, kinds, "scale", (1.0, 1.0))
    mar = _per_kind(margin, kinds, "margin", 0.0)
    out = []
    for name in kinds:
        shape = shapes[name]
        if not isinstance(shape, Shape):
            raise InputError(f"shapes.{name}: must be a Shape, got {type(shape).__name__}")
        r = _check_range(rot[name], f"rotation[{name}]")
        s = _check_range(sca[name], f"scale[{name}]", positive=True)
        try:
            m = float(mar[name])  # type: ignore[arg-type]
        except (TypeError, ValueError):
            raise InputError(f"margin[{name}]: must be a number, got {mar[name]!r}") from None
        if not np.isfinite(m):
            raise InputError(f"margin[{name}]: must be finite, got {m}")
        source = exclusive.get(name, shape)
        which = "exclusive shape" if name in exclusive else "shape"
        body = source.geometry
        if not body.is_empty and not body.is_valid:
            body = shapely.make_valid(body)
        if m != 0 and not body.is_empty:
            body = shapely.buffer(body, m)
        polys = [g for g in shapely.get_parts(body) if isinstance(g, shapely.Polygon) and g.area > 0]
        body = shapely.union_all(polys) if polys else shapely.Polygon()
        if body.is_empty or body.area <= 0:
            hint = " (it has only open strokes; give a margin > 0)" if not source.line_geometry.is_empty else ""
            raise InputError(f"{which} {name!r}: exclusive region has zero area{hint}")
        bad = _self_intersecting_paths(source)
        if bad:
            warnings.warn(
                f"{which} {name!r}: path {bad[0]} intersects itself; repaired under the even-odd rule",
                PackWarning,
                stacklevel=3,
            )
        x0, y0, x1, y1 = body.bounds
        c = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
        body = shapely.transform(body, lambda p, c=c: p - c)
        elem = shape.geometry
        if not elem.is_empty:
            elem = shapely.transform(elem, lambda p, c=c: p - c)
            if not elem.is_valid:
                elem = shapely.make_valid(elem)
        hull = body if elem.is_empty or shapely.covers(body, elem) else shapely.union(body, elem)
        radius = float(np.sqrt((shapely.get_coordinates(body) ** 2).sum(axis=1)).max())
        shapely.prepare(body)
        out.append(ExclusiveRegion(name, body, hull, c, radius, float(body.area), r, s))
    return out


def transform_many(geom: shapely.Geometry, xy: np.ndarray, rotation: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """World copies of one centred local geometry: ``T + s R(t) p`` (Eq. 1).

    Parameters
    ----------
    geom : shapely geometry
        In centred local coordinates.
    xy : (m, 2) float
        Translations T (where the bounding-box centre goes).
    rotation, scale : (m,) float

    Returns
    -------
    (m,) object ndarray of shapely geometries
    """
    m = len(xy)
    if m == 0:
        return np.empty(0, dtype=object)
    nc = int(shapely.get_num_coordinates(geom))
    c = np.repeat(np.cos(rotation) * scale, nc)
    s = np.repeat(np.sin(rotation) * scale, nc)
    tx = np.repeat(xy[:, 0], nc)
    ty = np.repeat(xy[:, 1], nc)

    def f(p: np.ndarray) -> np.ndarray:
        return np.c_[tx + c * p[:, 0] - s * p[:, 1], ty + s * p[:, 0] + c * p[:, 1]]

    return shapely.transform(np.full(m, geom, dtype=object), f)


def element_origin(centre: np.ndarray, xy: np.ndarray, rotation: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """(m, 2) positions ``T - s R(t) c`` that put the local point ``c`` at ``T``.

    Parameters
    ----------
    centre : (2,) or (m, 2) float
    xy : (m, 2) float
    rotation, scale : (m,) float
    """
    cr, sr = np.cos(rotation), np.sin(rotation)
    cx, cy = centre[..., 0], centre[..., 1]
    return np.c_[xy[:, 0] - scale * (cr * cx - sr * cy), xy[:, 1] - scale * (sr * cx + cr * cy)]

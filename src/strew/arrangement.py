"""Arrangement: the one core data type of strew.

A set of placed elements stored column-wise. Each element has a ``kind`` (index into the
shape library), a position ``x, y``, a ``rotation`` (radians) and a uniform ``scale``, and
may carry optional columns (``color``, ``sub_id``, ``radius``, ``neighborhood_radius``,
``void``, ``layer`` ...). The arrangement also carries its shape library (kind name ->
:class:`~strew.shape.Shape`), an optional :class:`~strew.region.Region` and ``meta``.

Transform convention (DESIGN.md): element ``i`` maps a local point ``p`` to::

    p_world = (x_i, y_i) + scale_i * R(rotation_i) @ p,   R(t) = [[cos t, -sin t],
                                                                   [sin t,  cos t]]

in SVG's y-down coordinates; this is exactly ``translate(x y) rotate(deg(t)) scale(s)``.

Arrangements are immutable: every operation returns a new one.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from functools import cached_property
from typing import Any

import numpy as np
import shapely

from ._display import hook
from ._errors import InputError
from ._limits import check_coordinates
from .region import Region
from .shape import Shape

__all__ = ["Arrangement", "concat", "transform_points", "CORE_COLUMNS", "PARTS_COLUMN"]

CORE_COLUMNS = ("kind", "x", "y", "rotation", "scale")
# optional per-element geometry: elements of one kind whose curves differ (ornament stems,
# spirals); see the Arrangement docstring
PARTS_COLUMN = "parts"
# characters that XML 1.0 cannot hold, so an SVG could not carry such a kind name
_CONTROL = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def transform_points(points: np.ndarray, x: float, y: float, rotation: float, scale: float) -> np.ndarray:
    """Map local points to world space with the strew convention.

    Parameters
    ----------
    points : (n, 2) float
    x, y, rotation, scale : float

    Returns
    -------
    (n, 2) float

    Examples
    --------
    >>> transform_points(np.array([[1.0, 0.0]]), 10, 20, np.pi / 2, 2).round(9).tolist()
    [[10.0, 22.0]]
    """
    c, s = np.cos(rotation), np.sin(rotation)
    p = np.asarray(points, dtype=float)
    return np.c_[x + scale * (c * p[:, 0] - s * p[:, 1]), y + scale * (s * p[:, 0] + c * p[:, 1])]


def _readonly(a: np.ndarray) -> np.ndarray:
    a = np.array(a, copy=True)
    a.setflags(write=False)
    return a


def _column_array(name: str, values: Any, n: int) -> np.ndarray:
    if isinstance(values, np.ndarray):
        arr = values
    else:
        values = list(values)
        try:
            arr = np.asarray(values)
        except ValueError:  # ragged
            arr = np.empty(len(values), dtype=object)
            arr[:] = values
        if arr.dtype.kind == "U":
            obj = np.empty(len(values), dtype=object)
            obj[:] = values
            arr = obj
    if arr.ndim == 0 or len(arr) != n:
        got = "a scalar" if arr.ndim == 0 else f"length {len(arr)}"
        raise InputError(f"elements.{name}: {got} does not match elements.kind length {n}")
    return _readonly(arr)


def _parts_column(values: Any, n: int) -> tuple[np.ndarray, tuple[tuple[Shape, ...] | None, ...]]:
    """The ``parts`` column, normalised to JSON-ready dicts, and its shapes."""
    vals = list(values)
    if len(vals) != n:
        raise InputError(f"elements.{PARTS_COLUMN}: length {len(vals)} does not match elements.kind length {n}")
    arr = np.empty(n, dtype=object)
    shapes: list[tuple[Shape, ...] | None] = []
    for i, v in enumerate(vals):
        if isinstance(v, np.ndarray):
            v = v.tolist()
        if v is None:
            shapes.append(None)
            continue
        if not isinstance(v, (list, tuple)) or not v:
            raise InputError(f"elements.{PARTS_COLUMN}[{i}]: must be null or a non-empty list of shapes ({{'paths': [...], 'style': {{...}}}})")
        sh = tuple(p if isinstance(p, Shape) else Shape.from_dict(p, f"elements.{PARTS_COLUMN}[{i}][{j}]") for j, p in enumerate(v))
        shapes.append(sh)
        arr[i] = [s.to_dict() for s in sh]
    arr.setflags(write=False)
    return arr, tuple(shapes)


def _union_parts(geoms: list[shapely.Geometry], area: bool) -> shapely.Geometry:
    geoms = [g for g in geoms if not g.is_empty]
    if not geoms:
        return shapely.Polygon() if area else shapely.LineString()
    if len(geoms) == 1:
        return geoms[0]
    if area:
        return shapely.union_all(geoms)
    lines = [g for part in geoms for g in shapely.get_parts(part)]
    return shapely.MultiLineString(lines)


class Arrangement:
    """Placed elements, column-wise, with their shape library.

    Parameters
    ----------
    shapes : mapping of str to Shape
        The shape library; its order fixes kind indices.
    kind : (n,) int or str
        Kind of each element: an index into ``shapes`` or a kind name.
    x, y : (n,) float
        Positions.
    rotation : (n,) float, optional
        Radians (default 0).
    scale : (n,) float, optional
        Uniform scale (default 1).
    columns : mapping of str to (n, ...) array, optional
        Extra per-element columns; they travel through every operation and round-trip.
    region : Region, optional
        The domain the elements fill.
    meta : mapping, optional
        How the arrangement was made (generator, method, seed, params, command).
    extra : mapping, optional
        Other top-level document entries (e.g. connectivity), kept for the round trip.

    Notes
    -----
    Per-element geometry: the optional column ``parts`` gives an element its own
    geometry, for kinds whose elements share a role but not a shape (an ornament's
    stems, each curved its own way). Each entry is ``None`` (draw the kind's shape) or a
    list of shape dicts ``{"paths": [...], "style": {...}}`` in the element's local
    frame, drawn in order over one another; x, y, rotation and scale place it as usual,
    and the kind's shape in the library is then a representative. :attr:`geometry` (so
    metrics and ``strew info``), the JSON document and SVG export honour it.

    Examples
    --------
    >>> from strew import Shape
    >>> a = Arrangement({"dot": Shape.circle(1)}, ["dot", "dot"], [0, 5], [0, 0])
    >>> len(a), a.kinds
    (2, ('dot',))
    >>> a.select(a.x > 1).x.tolist()
    [5.0]
    """

    def __init__(
        self,
        shapes: Mapping[str, Shape],
        kind: Sequence[int] | Sequence[str] | np.ndarray,
        x: Sequence[float] | np.ndarray,
        y: Sequence[float] | np.ndarray,
        rotation: Sequence[float] | np.ndarray | None = None,
        scale: Sequence[float] | np.ndarray | None = None,
        *,
        columns: Mapping[str, Any] | None = None,
        region: Region | None = None,
        meta: Mapping[str, Any] | None = None,
        extra: Mapping[str, Any] | None = None,
    ) -> None:
        shapes = dict(shapes)
        for name, sh in shapes.items():
            if not isinstance(name, str) or not name:
                raise InputError(f"shapes: kind names must be non-empty strings, got {name!r}")
            if _CONTROL.search(name):
                raise InputError(f"shapes: kind name {name!r} contains control characters")
            if not isinstance(sh, Shape):
                raise InputError(f"shapes.{name}: must be a Shape, got {type(sh).__name__}")
        self._shapes = shapes
        self._kinds = tuple(shapes)
        kind_arr = np.asarray(kind)
        n = len(kind_arr) if kind_arr.ndim else 0
        if kind_arr.ndim != 1 and not (kind_arr.ndim == 0 or kind_arr.size == 0):
            raise InputError("elements.kind: must be a list")
        if kind_arr.size == 0:
            n = 0
            kind_idx = np.zeros(0, dtype=np.int32)
        elif kind_arr.dtype.kind in "iu":
            kind_idx = kind_arr.astype(np.int32)
            bad = np.flatnonzero((kind_idx < 0) | (kind_idx >= len(self._kinds)))
            if len(bad):
                raise InputError(
                    f"elements.kind[{bad[0]}]: unknown kind index {kind_arr[bad[0]]} (library has {len(self._kinds)} kinds)"
                )
        else:
            lookup = {k: i for i, k in enumerate(self._kinds)}
            kind_idx = np.empty(n, dtype=np.int32)
            for i, k in enumerate(kind_arr.tolist()):
                j = lookup.get(k) if isinstance(k, str) else None
                if j is None:
                    known = ", ".join(self._kinds) or "none"
                    raise InputError(f"elements.kind[{i}]: unknown kind {k!r} (known: {known})")
                kind_idx[i] = j
        self._kind = _readonly(kind_idx)

        def core(name: str, values: Any, default: float) -> np.ndarray:
            if values is None:
                return _readonly(np.full(n, default, dtype=float))
            try:
                arr = np.asarray(values, dtype=float)
            except (TypeError, ValueError):
                raise InputError(f"elements.{name}: must be numbers") from None
            if arr.ndim != 1 or len(arr) != n:
                got = f"length {len(arr)}" if arr.ndim == 1 else f"shape {arr.shape}"
                raise InputError(f"elements.{name}: {got} does not match elements.kind length {n}")
            bad = np.flatnonzero(~np.isfinite(arr))
            if len(bad):
                raise InputError(f"elements.{name}[{bad[0]}]: NaN or inf coordinate")
            # Magnitudes beyond MAX_COORD overflow the methods' squared distances and areas;
            # a scale must be positive (mirror images are kinds of their own).
            check_coordinates(arr, f"elements.{name}", positive=name == "scale", index=True)
            return _readonly(arr)

        self._x = core("x", x, 0.0)
        self._y = core("y", y, 0.0)
        self._rotation = core("rotation", rotation, 0.0)
        self._scale = core("scale", scale, 1.0)
        cols: dict[str, np.ndarray] = {}
        self._parts: tuple[tuple[Shape, ...] | None, ...] | None = None
        for name, values in dict(columns or {}).items():
            if name in CORE_COLUMNS:
                raise InputError(f"columns: {name!r} is a core column, pass it directly")
            if name == PARTS_COLUMN:
                cols[name], self._parts = _parts_column(values, n)
                continue
            cols[str(name)] = _column_array(name, values, n)
        self._columns = cols
        if region is not None and not isinstance(region, Region):
            raise InputError(f"region: must be a Region, got {type(region).__name__}")
        self._region = region
        self._meta = dict(meta or {})
        self._extra = dict(extra or {})

    # -- columns ----------------------------------------------------------------------
    @property
    def shapes(self) -> dict[str, Shape]:
        """Shape library, kind name -> Shape (a copy)."""
        return dict(self._shapes)

    @property
    def kinds(self) -> tuple[str, ...]:
        """Kind names in index order."""
        return self._kinds

    @property
    def kind(self) -> np.ndarray:
        """(n,) int32 kind indices into :attr:`kinds`."""
        return self._kind

    @property
    def kind_names(self) -> np.ndarray:
        """(n,) object array of kind names."""
        names = np.empty(len(self._kinds), dtype=object)
        names[:] = self._kinds
        return names[self._kind] if len(self._kinds) else np.zeros(0, dtype=object)

    @property
    def x(self) -> np.ndarray:
        """(n,) float positions."""
        return self._x

    @property
    def y(self) -> np.ndarray:
        """(n,) float positions."""
        return self._y

    @property
    def xy(self) -> np.ndarray:
        """(n, 2) float positions."""
        return np.c_[self._x, self._y]

    @property
    def rotation(self) -> np.ndarray:
        """(n,) float rotations in radians."""
        return self._rotation

    @property
    def scale(self) -> np.ndarray:
        """(n,) float uniform scales."""
        return self._scale

    @property
    def columns(self) -> dict[str, np.ndarray]:
        """Extra columns (name -> read-only array)."""
        return dict(self._columns)

    @property
    def region(self) -> Region | None:
        return self._region

    @property
    def meta(self) -> dict[str, Any]:
        """Metadata (a copy)."""
        return dict(self._meta)

    @property
    def extra(self) -> dict[str, Any]:
        """Other top-level document entries (a copy)."""
        return dict(self._extra)

    def __len__(self) -> int:
        return len(self._kind)

    def __getitem__(self, name: str) -> np.ndarray:
        """Column by name: a core column or an extra one."""
        if name in CORE_COLUMNS:
            return getattr(self, name)
        try:
            return self._columns[name]
        except KeyError:
            raise KeyError(f"no column {name!r}; have {', '.join(CORE_COLUMNS + tuple(self._columns))}") from None

    def __contains__(self, name: object) -> bool:
        return name in CORE_COLUMNS or name in self._columns

    @property
    def element_parts(self) -> tuple[tuple[Shape, ...] | None, ...] | None:
        """(n,) per-element geometry from the ``parts`` column (None where an element draws
        its kind's shape), or None without that column (see Notes)."""
        return self._parts

    # -- derived ----------------------------------------------------------------------
    @cached_property
    def geometry(self) -> np.ndarray:
        """(n,) shapely geometries in world space (see the module's transform convention)."""
        return self.geometry_of("geometry")

    def geometry_of(self, which: str = "geometry") -> np.ndarray:
        """(n,) world-space geometries of a shape attribute.

        Parameters
        ----------
        which : {"geometry", "area_geometry", "line_geometry"}
        """
        out = np.empty(len(self), dtype=object)
        for k, name in enumerate(self._kinds):
            idx = np.flatnonzero(self._kind == k)
            if len(idx) == 0:
                continue
            local = getattr(self._shapes[name], which)
            if local.is_empty:
                out[idx] = local
                continue
            ncoords = int(shapely.get_num_coordinates(local))
            c = np.repeat(np.cos(self._rotation[idx]) * self._scale[idx], ncoords)
            s = np.repeat(np.sin(self._rotation[idx]) * self._scale[idx], ncoords)
            tx = np.repeat(self._x[idx], ncoords)
            ty = np.repeat(self._y[idx], ncoords)

            def f(p: np.ndarray, c=c, s=s, tx=tx, ty=ty) -> np.ndarray:
                return np.c_[tx + c * p[:, 0] - s * p[:, 1], ty + s * p[:, 0] + c * p[:, 1]]

            out[idx] = shapely.transform(np.full(len(idx), local, dtype=object), f)
        if self._parts is not None:
            area = which == "area_geometry"
            for i, parts in enumerate(self._parts):
                if parts is None:
                    continue
                if which == "geometry":
                    local = _union_parts([p.area_geometry for p in parts], True)
                    if local.is_empty:
                        local = _union_parts([p.line_geometry for p in parts], False)
                else:
                    local = _union_parts([getattr(p, which) for p in parts], area)
                xi, yi, ri, si = self._x[i], self._y[i], self._rotation[i], self._scale[i]
                out[i] = shapely.transform(local, lambda p, xi=xi, yi=yi, ri=ri, si=si: transform_points(p, xi, yi, ri, si))
        return out

    @cached_property
    def radii(self) -> np.ndarray:
        """(n,) float bounding radii in world units: the largest distance of an element's
        outline from its position (its shape's :attr:`~strew.shape.Shape.radius`, or the
        largest of its ``parts``' radii, times ``|scale|``).

        A disc of this radius about ``(x, y)`` holds the element, whatever its rotation;
        spatial queries use it to find the elements that may touch.
        """
        if len(self) == 0:
            return np.zeros(0)
        per_kind = np.array([self._shapes[k].radius for k in self._kinds], dtype=float)
        r = per_kind[self._kind]
        if self._parts is not None:
            r = r.copy()
            for i, parts in enumerate(self._parts):
                if parts is not None:
                    r[i] = max((p.radius for p in parts), default=0.0)
        return r * np.abs(self._scale)

    @cached_property
    def sindex(self) -> shapely.STRtree:
        """STRtree over :attr:`geometry` (indices are element indices)."""
        return shapely.STRtree(self.geometry)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """World bounds of all elements; the region's when empty."""
        if len(self) == 0:
            if self._region is not None:
                return self._region.bounds
            return (0.0, 0.0, 0.0, 0.0)
        b = shapely.total_bounds(self.geometry)
        if not np.all(np.isfinite(b)):  # only empty shapes
            return (float(self._x.min()), float(self._y.min()), float(self._x.max()), float(self._y.max()))
        return tuple(float(v) for v in b)  # type: ignore[return-value]

    def counts(self) -> dict[str, int]:
        """Number of elements per kind name."""
        c = np.bincount(self._kind, minlength=len(self._kinds))
        return {k: int(c[i]) for i, k in enumerate(self._kinds)}

    # -- operations -------------------------------------------------------------------
    def replace(self, **changes: Any) -> Arrangement:
        """Copy with some of ``shapes, kind, x, y, rotation, scale, columns, region, meta, extra`` replaced."""
        args: dict[str, Any] = dict(
            shapes=self._shapes,
            kind=self._kind,
            x=self._x,
            y=self._y,
            rotation=self._rotation,
            scale=self._scale,
            columns=self._columns,
            region=self._region,
            meta=self._meta,
            extra=self._extra,
        )
        unknown = set(changes) - set(args)
        if unknown:
            raise TypeError(f"replace: unknown field(s) {', '.join(sorted(unknown))}")
        args.update(changes)
        return Arrangement(**args)

    def with_columns(self, **columns: Any) -> Arrangement:
        """Copy with extra columns added or replaced (core columns too)."""
        core = {k: v for k, v in columns.items() if k in CORE_COLUMNS}
        extra = {k: v for k, v in columns.items() if k not in CORE_COLUMNS}
        return self.replace(columns={**self._columns, **extra}, **core)

    def without_columns(self, *names: str) -> Arrangement:
        """Copy without the named extra columns."""
        return self.replace(columns={k: v for k, v in self._columns.items() if k not in names})

    def with_meta(self, **meta: Any) -> Arrangement:
        """Copy with metadata entries added or replaced."""
        return self.replace(meta={**self._meta, **meta})

    def select(self, which: np.ndarray | Sequence[int] | Sequence[bool] | slice) -> Arrangement:
        """Subset of elements by boolean mask, indices or slice (shape library kept)."""
        if isinstance(which, slice):
            idx = np.arange(len(self))[which]
        else:
            w = np.asarray(which)
            if w.dtype == bool:
                if w.shape != (len(self),):
                    raise InputError(f"select: mask has shape {w.shape}, expected ({len(self)},)")
                idx = np.flatnonzero(w)
            else:
                idx = w.astype(np.intp).ravel()
        return Arrangement(
            self._shapes,
            self._kind[idx],
            self._x[idx],
            self._y[idx],
            self._rotation[idx],
            self._scale[idx],
            columns={k: v[idx] for k, v in self._columns.items()},
            region=self._region,
            meta=self._meta,
            extra=self._extra,
        )

    def concat(self, *others: Arrangement) -> Arrangement:
        """This arrangement followed by ``others``; see :func:`concat`."""
        return concat([self, *others])

    # -- display ----------------------------------------------------------------------
    # The writers live in strew.io, a layer above: they reach this type through the
    # hooks of strew._display, which io fills when it is imported (issue 15 point 7).
    def to_svg(self, **kwargs: Any) -> str:
        """SVG text; see :func:`strew.io.svg.to_svg`."""
        return hook("svg")(self, **kwargs)

    # Notebooks show small arrangements as SVG; above this many elements the SVG would be
    # megabytes (about 165 bytes per element), so they show a PNG with a note instead.
    REPR_SVG_MAX_ELEMENTS = 20_000

    def _repr_svg_(self) -> str | None:
        if len(self) > self.REPR_SVG_MAX_ELEMENTS:
            return None
        return self.to_svg(width=480)

    def _repr_png_(self) -> bytes | None:
        if len(self) <= self.REPR_SVG_MAX_ELEMENTS:
            return None
        return hook("png")(self, width=720)

    def _repr_html_(self) -> str | None:
        png = self._repr_png_()
        if png is None:
            return None
        import base64
        import html

        note = f"{html.escape(repr(self))}: shown as a PNG (over {self.REPR_SVG_MAX_ELEMENTS:,} elements); use .to_svg() for vectors"
        return f'<img src="data:image/png;base64,{base64.b64encode(png).decode()}"><br><small>{note}</small>'

    # -- data frames ------------------------------------------------------------------
    def to_pandas(self) -> Any:
        """A pandas DataFrame, one row per element; see :func:`strew.io.to_pandas`."""
        return hook("to_pandas")(self)

    def to_geopandas(self) -> Any:
        """A GeoDataFrame with each element's world geometry; see :func:`strew.io.to_geopandas`."""
        return hook("to_geopandas")(self)

    @classmethod
    def from_pandas(cls, df: Any, shapes: Mapping[str, Shape] | None = None, **kwargs: Any) -> Arrangement:
        """An arrangement from a data frame; see :func:`strew.io.from_pandas`."""
        return hook("from_pandas")(df, shapes, **kwargs)

    def __repr__(self) -> str:
        counts = ", ".join(f"{k}: {v}" for k, v in self.counts().items())
        cols = f", columns={list(self._columns)}" if self._columns else ""
        return f"Arrangement({len(self)} elements {{{counts}}}{cols})"

    def equals(self, other: Arrangement) -> bool:
        """Exact equality of shapes, columns, region, meta and extra."""
        if not isinstance(other, Arrangement) or len(self) != len(other):
            return False
        if self._kinds != other._kinds or any(self._shapes[k] != other._shapes[k] for k in self._kinds):
            return False
        for name in CORE_COLUMNS:
            if not np.array_equal(getattr(self, name), getattr(other, name)):
                return False
        if self._columns.keys() != other._columns.keys():
            return False
        for k, v in self._columns.items():
            w = other._columns[k]
            if v.shape != w.shape:
                return False
            if v.dtype.kind == "f" and w.dtype.kind == "f":
                if not np.array_equal(v, w, equal_nan=True):
                    return False
            elif v.tolist() != w.tolist():
                return False
        if (self._region is None) != (other._region is None):
            return False
        if self._region is not None and self._region != other._region:
            return False
        return self._meta == other._meta and self._extra == other._extra


def _column_concat(name: str, parts: list[np.ndarray | None], lengths: list[int]) -> np.ndarray:
    present = [p for p in parts if p is not None]
    ref = present[0]
    filled = []
    for p, n in zip(parts, lengths):
        if p is None:
            if ref.dtype.kind == "f":
                p = np.full((n, *ref.shape[1:]), np.nan)
            elif ref.dtype.kind == "b":
                p = np.zeros((n, *ref.shape[1:]), dtype=bool)
            elif ref.dtype.kind in "iu":
                p = np.zeros((n, *ref.shape[1:]), dtype=ref.dtype)
            else:
                p = np.empty((n, *ref.shape[1:]), dtype=object)
        filled.append(p)
    try:
        return np.concatenate(filled)
    except ValueError as exc:
        raise InputError(f"concat: column {name!r} has incompatible shapes ({exc})") from None


def concat(arrangements: Iterable[Arrangement]) -> Arrangement:
    """Join arrangements into one.

    Shape libraries are merged by kind name; the same name must denote the same shape.
    A column missing from some inputs is filled with NaN (floats), False (bools), 0
    (ints) or None. The region and meta of the first input are kept.
    """
    arrs = list(arrangements)
    if not arrs:
        raise InputError("concat: nothing to concatenate")
    shapes: dict[str, Shape] = {}
    for a in arrs:
        for name, sh in a._shapes.items():
            if name in shapes and shapes[name] != sh:
                raise InputError(f"concat: kind {name!r} names different shapes in the inputs")
            shapes.setdefault(name, sh)
    index = {k: i for i, k in enumerate(shapes)}
    kind = np.concatenate([np.array([index[k] for k in a._kinds], dtype=np.int32)[a._kind] if len(a) else np.zeros(0, np.int32) for a in arrs])
    lengths = [len(a) for a in arrs]
    names: list[str] = []
    for a in arrs:
        names.extend(k for k in a._columns if k not in names)
    columns = {k: _column_concat(k, [a._columns.get(k) for a in arrs], lengths) for k in names}
    return Arrangement(
        shapes,
        kind,
        np.concatenate([a._x for a in arrs]),
        np.concatenate([a._y for a in arrs]),
        np.concatenate([a._rotation for a in arrs]),
        np.concatenate([a._scale for a in arrs]),
        columns=columns,
        region=arrs[0]._region,
        meta=arrs[0]._meta,
        extra=arrs[0]._extra,
    )

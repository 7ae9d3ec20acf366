"""Curves: what mappers return and what arrangements evaluate to (Loi et al. §3, §4).

A :class:`Curves` value is an immutable collection of polylines with labels, plus named
points (``"start"``, ``"end"`` ...). Following §4 ("Face labels reconstruction", after
Asente et al. [3]) labels live only on curves: each curve carries its own (edge) labels
and the labels of the faces on its left and on its right. Face labels are rebuilt from
these side labels every time a planar map is induced.

Left and right are as seen on the screen, in strew's y-down coordinates: walking along a
curve from its first point to its last, the left face is on the walker's left in the
picture (for a direction ``d`` and a point ``p`` off the curve at ``a``,
``cross(d, p - a) < 0`` means "left").
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._errors import InputError

__all__ = ["Curve", "Curves", "as_labels", "as_point", "concat_curves"]

EMPTY: frozenset[str] = frozenset()


def as_labels(labels: Any, where: str = "labels") -> frozenset[str]:
    """A frozenset of label strings from a string, an iterable of strings or None."""
    if labels is None:
        return EMPTY
    if isinstance(labels, str):
        return frozenset([labels]) if labels else EMPTY
    try:
        out = frozenset(labels)
    except TypeError:
        raise InputError(f"{where}: expected a string or a list of strings, got {type(labels).__name__}") from None
    for lab in out:
        if not isinstance(lab, str) or not lab:
            raise InputError(f"{where}: labels must be non-empty strings, got {lab!r}")
    return out


def as_point(p: Any, where: str = "point") -> np.ndarray:
    """A finite point as a (2,) float array."""
    try:
        arr = np.asarray(p, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise InputError(f"{where}: expected a point (x, y), got {type(p).__name__}") from None
    if arr.shape != (2,) or not np.all(np.isfinite(arr)):
        raise InputError(f"{where}: expected a finite point (x, y), got {p!r}")
    return arr


@dataclass(frozen=True, eq=False)
class Curve:
    """One labelled polyline.

    Parameters
    ----------
    points : (n, 2) float
        Vertices; a closed curve does not repeat its first vertex.
    closed : bool
        Whether the last vertex joins the first.
    labels : frozenset of str
        Edge labels, given to every edge of a planar map induced from this curve.
    left, right : frozenset of str
        Labels of the faces on the curve's left and right (as seen on screen, y down).
    """

    points: np.ndarray
    closed: bool = False
    labels: frozenset[str] = EMPTY
    left: frozenset[str] = EMPTY
    right: frozenset[str] = EMPTY

    def __post_init__(self) -> None:
        pts = np.asarray(self.points, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 2:
            raise InputError(f"curve: points must have shape (n, 2), got {pts.shape}")
        if not np.all(np.isfinite(pts)):
            raise InputError("curve: NaN or inf coordinate")
        if self.closed and len(pts) > 1 and np.array_equal(pts[0], pts[-1]):
            pts = pts[:-1]
        pts = np.array(pts, copy=True)
        pts.setflags(write=False)
        object.__setattr__(self, "points", pts)
        object.__setattr__(self, "labels", as_labels(self.labels, "curve labels"))
        object.__setattr__(self, "left", as_labels(self.left, "curve left labels"))
        object.__setattr__(self, "right", as_labels(self.right, "curve right labels"))

    @property
    def polyline(self) -> np.ndarray:
        """(m, 2) the points, with the first repeated at the end when closed."""
        if self.closed and len(self.points) > 1:
            return np.vstack([self.points, self.points[:1]])
        return self.points

    def transformed(self, matrix: np.ndarray) -> Curve:
        """The curve mapped by a 2x3 affine matrix; a reflection swaps left and right."""
        a, t = matrix[:, :2], matrix[:, 2]
        flip = np.linalg.det(a) < 0
        left, right = (self.right, self.left) if flip else (self.left, self.right)
        return Curve(self.points @ a.T + t, self.closed, self.labels, left, right)

    def reversed(self) -> Curve:
        """The same curve walked backwards (left and right swap)."""
        return Curve(self.points[::-1], self.closed, self.labels, self.right, self.left)

    def with_labels(self, labels: Any = None, left: Any = None, right: Any = None) -> Curve:
        """Copy with labels added (edge labels, left-face and right-face labels)."""
        return Curve(
            self.points,
            self.closed,
            self.labels | as_labels(labels),
            self.left | as_labels(left),
            self.right | as_labels(right),
        )


@dataclass(frozen=True, eq=False)
class Curves:
    """An immutable collection of labelled curves and named points.

    This is the paper's "Curves" type (Tables 3 and 5): what :func:`import_svg` reads,
    what mappers return, and what arrangements produce before a planar map is induced.

    Parameters
    ----------
    curves : sequence of Curve
    points : mapping of str to (2,) point
        Named points, e.g. ``{"start": (0, 0), "end": (10, 0)}``. When a planar map is
        induced, a named point that falls on a vertex gives that vertex its name as a label.
    marks : sequence of (x, y, labels)
        Vertex labels stored on the curves (partitions' weighted vertex labels): when a
        planar map is induced, the vertex at ``(x, y)`` receives ``labels``.

    Examples
    --------
    >>> c = Curves.polyline([(0, 0), (10, 0)], named={"start": (0, 0), "end": (10, 0)})
    >>> len(c), c.bbox
    (1, (0.0, 0.0, 10.0, 0.0))
    """

    curves: tuple[Curve, ...] = ()
    points: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    marks: tuple[tuple[float, float, frozenset[str]], ...] = ()

    def __post_init__(self) -> None:
        curves = tuple(self.curves)
        for c in curves:
            if not isinstance(c, Curve):
                raise InputError(f"curves: expected Curve items, got {type(c).__name__}")
        object.__setattr__(self, "curves", curves)
        pts = {}
        for name, p in dict(self.points or {}).items():
            xy = as_point(p, f"point {name!r}")
            pts[str(name)] = (float(xy[0]), float(xy[1]))
        object.__setattr__(self, "points", pts)
        marks = []
        for m in self.marks:
            x, y, labs = m
            marks.append((float(x), float(y), as_labels(labs, "vertex labels")))
        object.__setattr__(self, "marks", tuple(marks))

    # -- constructors -------------------------------------------------------------------
    @classmethod
    def polyline(cls, xy: Any, closed: bool = False, labels: Any = None, *, named: Any = None) -> Curves:
        """One curve through ``xy`` ((n, 2)), with optional named points."""
        return cls((Curve(np.asarray(xy, dtype=float), closed, as_labels(labels)),), named or {})

    @classmethod
    def polygon(cls, points: Any, labels: Any = None) -> Curves:
        """One closed curve through ``points`` ((n, 2))."""
        return cls((Curve(np.asarray(points, dtype=float), True, as_labels(labels)),))

    # -- container ----------------------------------------------------------------------
    def __len__(self) -> int:
        return len(self.curves)

    def __iter__(self) -> Iterator[Curve]:
        return iter(self.curves)

    def __add__(self, other: Curves) -> Curves:
        if not isinstance(other, Curves):
            return NotImplemented
        return Curves(self.curves + other.curves, {**self.points, **other.points}, self.marks + other.marks)

    @property
    def is_empty(self) -> bool:
        return not self.curves

    @property
    def all_points(self) -> np.ndarray:
        """(n, 2) every curve vertex (and no named point)."""
        if not self.curves:
            return np.zeros((0, 2))
        return np.concatenate([c.points for c in self.curves])

    @property
    def bbox(self) -> tuple[float, float, float, float]:
        """``(minx, miny, maxx, maxy)`` of the curve vertices (of the named points if none)."""
        pts = self.all_points
        if len(pts) == 0:
            pts = np.asarray(list(self.points.values()), dtype=float).reshape(-1, 2)
        if len(pts) == 0:
            return (0.0, 0.0, 0.0, 0.0)
        return (float(pts[:, 0].min()), float(pts[:, 1].min()), float(pts[:, 0].max()), float(pts[:, 1].max()))

    def transformed(self, matrix: Any) -> Curves:
        """Curves and named points mapped by a 2x3 affine matrix."""
        m = np.asarray(matrix, dtype=float)
        if m.shape != (2, 3) or not np.all(np.isfinite(m)):
            raise InputError(f"transform: expected a finite 2x3 matrix, got shape {m.shape}")
        a, t = m[:, :2], m[:, 2]
        pts = {k: tuple(np.asarray(v) @ a.T + t) for k, v in self.points.items()}
        marks = []
        for x, y, labs in self.marks:
            p = np.array([x, y]) @ a.T + t
            marks.append((p[0], p[1], labs))
        return Curves(tuple(c.transformed(m) for c in self.curves), pts, tuple(marks))

    def select(self, keep: Iterable[bool]) -> Curves:
        """The curves for which ``keep`` is true (named points are kept)."""
        return Curves(tuple(c for c, k in zip(self.curves, keep) if k), self.points, self.marks)

    def with_labels(self, labels: Any = None, left: Any = None, right: Any = None) -> Curves:
        """Copy with labels added to every curve."""
        return Curves(tuple(c.with_labels(labels, left, right) for c in self.curves), self.points, self.marks)

    def __repr__(self) -> str:
        n = sum(len(c.points) for c in self.curves)
        names = f", points={sorted(self.points)}" if self.points else ""
        return f"Curves({len(self.curves)} curves, {n} vertices{names})"


def concat_curves(parts: Sequence[Curves]) -> Curves:
    """All curves of ``parts`` in order; named points of later parts win."""
    curves: list[Curve] = []
    points: dict[str, tuple[float, float]] = {}
    marks: list[tuple[float, float, frozenset[str]]] = []
    for p in parts:
        curves.extend(p.curves)
        points.update(p.points)
        marks.extend(p.marks)
    return Curves(tuple(curves), points, tuple(marks))

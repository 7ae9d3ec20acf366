"""Arrangements as functions, and the partition, mapping and merging operators.

§3 "Functional programming": an arrangement is a function that takes a region and
returns a collection of curves; every operator (partition, mapping, merging) returns an
arrangement; evaluating an arrangement on a region gives a planar map (§4).
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from ..region import Region
from ._context import Context, Field, Periodic, current, derive_seed, evaluation, field, periodic, top, unit_random
from ._curves import EMPTY, Curve, Curves, concat_curves
from ._planar_map import DEFAULT_GRID, Face, PlanarMap, Vertex, Edge, _Cell
from ._sampling import periodic_poisson, periodic_poisson_disk, poisson, poisson_disk

__all__ = [
    "ArrangementFunction",
    "Border",
    "CROP",
    "CROP_ADD_BOUNDARY",
    "KEEP_INSIDE",
    "KEEP_OUTSIDE",
    "StripesProperties",
    "IrregularProperties",
    "MapperError",
    "as_arrangement",
    "as_region_geometry",
    "stripes_properties",
    "set_edge_labels",
    "set_face_labels",
    "stripes_partition",
    "grid_partition",
    "irregular_properties",
    "set_weighted_vertex_labels",
    "set_weighted_edge_labels",
    "set_weighted_face_labels",
    "uniform_partition",
    "random_partition",
    "map_to_vertices",
    "map_to_edges",
    "map_to_faces",
    "union",
    "inside",
    "outside",
    "edge_curve",
]


class MapperError(InputError):
    """An exception raised inside a mapper, or a mapper that returned a wrong type.

    The message names the mapper, its file and line.
    """


class Border(enum.Enum):
    """Border management options (§5.2, Fig. 6)."""

    CROP = "crop"
    CROP_ADD_BOUNDARY = "crop_add_boundary"
    KEEP_INSIDE = "keep_inside"
    KEEP_OUTSIDE = "keep_outside"

    def __repr__(self) -> str:
        return self.name


CROP = Border.CROP
CROP_ADD_BOUNDARY = Border.CROP_ADD_BOUNDARY
KEEP_INSIDE = Border.KEEP_INSIDE
KEEP_OUTSIDE = Border.KEEP_OUTSIDE


def _check_border(b: Any, where: str) -> Border:
    if isinstance(b, Border):
        return b
    if isinstance(b, str) and b.upper() in Border.__members__:
        return Border[b.upper()]
    raise InputError(f"{where}: border must be CROP, CROP_ADD_BOUNDARY, KEEP_INSIDE or KEEP_OUTSIDE, got {b!r}")


# -- regions ------------------------------------------------------------------------------
def as_region_geometry(region: Any) -> shapely.Geometry:
    """The polygonal region an arrangement is evaluated on.

    Accepts a size ``N`` (the square [0, N]^2), a :class:`strew.Region`, a shapely
    (Multi)Polygon, a bounded :class:`Face` (``arrangement(face)`` inside a mapper), or
    closed curves (the faces they enclose).
    """
    if isinstance(region, Face):
        if region.is_unbounded:
            raise InputError("region: the unbounded face cannot be partitioned")
        return region.polygon
    if isinstance(region, Region):
        return region.geometry
    if isinstance(region, (Curves, PlanarMap)):
        # the bounded faces of the curves' planar map (e.g. a blob placed by a mapper)
        pm = region if isinstance(region, PlanarMap) else PlanarMap(region)
        polys = [p for p in pm._t.face_polygons[1:]]
        if not polys:
            raise InputError("region: these curves enclose no face")
        return shapely.union_all(polys)
    if isinstance(region, (shapely.Polygon, shapely.MultiPolygon)):
        if region.is_empty or region.area <= 0:
            raise InputError("region: empty polygon")
        return region
    if isinstance(region, (int, float, np.integer, np.floating)) and not isinstance(region, bool):
        n = float(region)
        if not (math.isfinite(n) and n > 0):
            raise InputError(f"region: size must be a positive number, got {region!r}")
        return shapely.box(0.0, 0.0, n, n)
    raise InputError(
        f"region: expected a size, a Region, a shapely polygon, a face or closed curves, got {type(region).__name__}"
    )


# -- arrangements -------------------------------------------------------------------------
class ArrangementFunction:
    """An arrangement: a function of a region that returns curves (§3).

    Calling it on a region gives a :class:`PlanarMap`::

        pm = arrangement(2000)           # the square [0, 2000]^2
        pm = arrangement(face)           # inside a mapper: a sub-scale arrangement

    Parameters
    ----------
    fn : callable
        ``fn(region_geometry, context) -> Curves``.
    name : str
        The operator that made it (for messages).
    """

    def __init__(self, fn: Callable[[shapely.Geometry, Context], Curves], name: str) -> None:
        self._fn = fn
        self.name = name

    def _eval(self, geom: shapely.Geometry, ctx: Context) -> Curves:
        out = self._fn(geom, ctx)
        if not isinstance(out, Curves):  # pragma: no cover - internal invariant
            raise TypeError(f"{self.name} produced {type(out).__name__}")
        return out

    def curves(self, region: Any, *, seed: int | None = None) -> Curves:
        """The curves of this arrangement on ``region`` (no planar map is induced)."""
        geom = as_region_geometry(region)
        ctx = current()
        if ctx is not None and seed is None:
            return self._eval(geom, ctx)
        root = int(seed) if seed is not None else top().root
        ctx = Context(root, root)
        with evaluation(ctx):
            return self._eval(geom, ctx)

    def __call__(self, region: Any, *, seed: int | None = None, grid: float = DEFAULT_GRID) -> PlanarMap:
        """Evaluate on ``region``; returns the induced planar map."""
        return PlanarMap(self.curves(region, seed=seed), grid)

    def __repr__(self) -> str:
        return f"<arrangement {self.name}>"


def as_arrangement(a: Any, where: str) -> ArrangementFunction:
    """An arrangement from an arrangement, or a constant one from Curves or a PlanarMap."""
    if isinstance(a, ArrangementFunction):
        return a
    if isinstance(a, PlanarMap):
        a = a.curves
    if isinstance(a, Curves):
        const = a
        return ArrangementFunction(lambda geom, ctx: const, "curves")
    raise InputError(f"{where}: expected an arrangement (or curves), got {type(a).__name__}")


# -- curve helpers ------------------------------------------------------------------------
def edge_curve(edge: Edge, *, sides: tuple[bool, bool] = (True, True)) -> Curve:
    """An edge as a curve carrying its labels and its faces' labels (§4)."""
    t = edge._map._t
    i = edge._i
    lf, rf = int(t.edge_left[i]), int(t.edge_right[i])
    left = t.face_labels[lf] if sides[0] else EMPTY
    right = t.face_labels[rf] if sides[1] else EMPTY
    return Curve(t.edge_points[i], False, t.edge_labels[i], left, right)


def _map_curves(pm: PlanarMap) -> Curves:
    """Every edge of a planar map as a curve (with the map's vertex labels as marks)."""
    t = pm._t
    curves = tuple(edge_curve(Edge(pm, i)) for i in range(pm.n_edges))
    marks = tuple((float(x), float(y), labs) for (x, y), labs in zip(pm.vertex_xy.tolist(), t.vertex_labels) if labs)
    return Curves(curves, {}, marks)


def _crop(curves: Curves, area: shapely.Geometry, keep_inside: bool) -> Curves:
    """Curves cut along the boundary of ``area``; the part inside (or outside) is kept."""
    if not curves.curves:
        return curves
    lines = np.array([shapely.LineString(c.polyline) if len(c.polyline) >= 2 else shapely.LineString() for c in curves.curves], dtype=object)
    prepared = area
    shapely.prepare(prepared)
    inside = shapely.covered_by(lines, prepared)
    disjoint = ~shapely.intersects(lines, prepared)
    out: list[Curve] = []
    for c, line, ins, dis in zip(curves.curves, lines, inside.tolist(), disjoint.tolist()):
        if line.is_empty:
            continue
        if (ins and keep_inside) or (dis and not keep_inside):
            out.append(c)
            continue
        if (dis and keep_inside) or (ins and not keep_inside):
            continue
        cut = shapely.intersection(line, area) if keep_inside else shapely.difference(line, area)
        # GEOS keeps the direction of the input line; pieces of a closed curve are open
        for part in shapely.get_parts(shapely.line_merge(cut) if cut.geom_type == "MultiLineString" else cut):
            if isinstance(part, shapely.LineString) and not part.is_empty and part.length > 0:
                out.append(Curve(np.asarray(part.coords), False, c.labels, c.left, c.right))
    return Curves(tuple(out), curves.points, curves.marks)


def _boundary_curves(geom: shapely.Geometry) -> list[Curve]:
    out = []
    for poly in shapely.get_parts(geom):
        if isinstance(poly, shapely.Polygon):
            for ring in [poly.exterior, *poly.interiors]:
                out.append(Curve(np.asarray(ring.coords), True))
    return out


def _keep_faces(curves: Curves, geom: shapely.Geometry, keep_inside: bool) -> Curves:
    """The edges of the faces of ``curves``' planar map inside (or meeting) ``geom``."""
    pm = PlanarMap(curves)
    t = pm._t
    polys = np.array(t.face_polygons[1:], dtype=object)
    if len(polys) == 0:
        return Curves()
    if keep_inside:
        area = geom.buffer(10 * pm.grid)
        sel = shapely.covered_by(polys, area)
        if field() is not None:  # a world's tile: a dropped cell may be the world's (issue 19.1)
            from ._world import check_dropped_faces

            check_dropped_faces(polys[~sel], "a cell dropped by KEEP_INSIDE")
    else:
        sel = shapely.relate_pattern(polys, geom, "T********")
    selected = np.r_[False, sel]
    out = []
    for e in range(pm.n_edges):
        ls, rs = bool(selected[t.edge_left[e]]), bool(selected[t.edge_right[e]])
        if ls or rs:
            out.append(edge_curve(Edge(pm, e), sides=(ls, rs)))
    return Curves(tuple(out), curves.points, curves.marks)


def _apply_border(curves: Curves, geom: shapely.Geometry, border: Border) -> Curves:
    """§5.2: crop the partition at the region's boundary, add it, or keep whole cells."""
    if border is Border.CROP:
        return _crop(curves, geom, True)
    if border is Border.CROP_ADD_BOUNDARY:
        c = _crop(curves, geom, True)
        return Curves(c.curves + tuple(_boundary_curves(geom)), c.points, c.marks)
    return _keep_faces(curves, geom, border is Border.KEEP_INSIDE)


def _padded_bounds(geom: shapely.Geometry, pad: float) -> tuple[float, float, float, float]:
    x0, y0, x1, y1 = geom.bounds
    return (x0 - pad, y0 - pad, x1 + pad, y1 + pad)


# -- periodic tiles (issue 18) ------------------------------------------------------------
_ODD = 0.3183098861837907  # 1/pi: offsets the window that picks a cell's period shift


def _periodic_top(geom: shapely.Geometry) -> Periodic | None:
    """The periodic evaluation when ``geom`` is its top-level domain, else None."""
    per = periodic()
    return per if per is not None and geom is per.domain else None


def _equivariant(fn: Callable[[shapely.Geometry, Context], Curves]) -> Callable[[shapely.Geometry, Context], Curves]:
    """A partition that commutes with the tile's periods on a periodic evaluation.

    Not in the paper (its partitions are fixed in the plane): inside a mapper, on a
    periodic tile, a partition of a face is computed on the face's translate into the
    tile and moved back, so that a face and its translates by whole periods get the same
    sub-arrangement and the pieces of a face cut by the tile's edge match up.
    """

    def g(geom: shapely.Geometry, ctx: Context) -> Curves:
        per = periodic()
        if per is None or geom is per.domain:
            return fn(geom, ctx)
        x0, y0, x1, y1 = geom.bounds
        sx, sy = per.shift(0.5 * (x0 + x1) - _ODD * per.tile[2], 0.5 * (y0 + y1) - _ODD * per.tile[3])
        if sx == 0.0 and sy == 0.0:
            return fn(geom, ctx)
        out = fn(shapely.transform(geom, lambda p: p - np.array([sx, sy])), ctx)
        return out.transformed(np.array([[1.0, 0.0, sx], [0.0, 1.0, sy]]))

    return g


# -- label groups -------------------------------------------------------------------------
def _label_list(labels: tuple[Any, ...], where: str) -> tuple[str, ...]:
    if not labels:
        raise InputError(f"{where}: give at least one label")
    out = []
    for lab in labels:
        if not isinstance(lab, str) or not lab:
            raise InputError(f"{where}: labels must be non-empty strings, got {lab!r}")
        out.append(lab)
    return tuple(out)


def _weighted_list(args: tuple[Any, ...], where: str) -> tuple[tuple[str, float], ...]:
    if not args or len(args) % 2:
        raise InputError(f"{where}: expected pairs label, weight (label1, w1, label2, w2, ...)")
    out = []
    for lab, w in zip(args[::2], args[1::2]):
        if not isinstance(lab, str) or not lab:
            raise InputError(f"{where}: labels must be non-empty strings, got {lab!r}")
        try:
            wf = float(w)
        except (TypeError, ValueError):
            raise InputError(f"{where}: weight of {lab!r} must be a number, got {w!r}") from None
        if not (math.isfinite(wf) and wf >= 0):
            raise InputError(f"{where}: weight of {lab!r} must be finite and >= 0, got {w!r}")
        out.append((lab, wf))
    return tuple(out)


def _draw_labels(groups: tuple[tuple[tuple[str, float], ...], ...], n: int, rng: np.random.Generator) -> list[frozenset[str]]:
    """One label per group per cell, drawn with the group's apparition probabilities.

    Weights are probabilities; when they sum to less than 1 the rest is "no label", and
    when they sum to more they are normalised.
    """
    out: list[set[str]] = [set() for _ in range(n)]
    for group in groups:
        labs = [g[0] for g in group]
        w = np.array([g[1] for g in group], dtype=float)
        cum = np.cumsum(w) / max(1.0, float(w.sum()))
        u = rng.random(n)
        idx = np.searchsorted(cum, u, side="right")
        for i, k in enumerate(idx.tolist()):
            if k < len(labs):
                out[i].add(labs[k])
    return [frozenset(s) for s in out]


# -- regular partitions (Table 1) ---------------------------------------------------------
@dataclass(frozen=True)
class StripesProperties:
    """Stripes properties: angle, cycle of widths, and cycles of edge and face labels."""

    angle: float
    widths: tuple[float, ...]
    edge_labels: tuple[tuple[str, ...], ...] = ()
    face_labels: tuple[tuple[str, ...], ...] = ()


def stripes_properties(a: float, w1: float, *widths: float) -> StripesProperties:
    """StripesProperties(Scalar a, Scalar w1 [, Scalar w2, ...]): sets stripes properties.

    Parameters
    ----------
    a : float
        Angle of the lines, in radians (0: horizontal lines).
    w1, *widths : float
        Widths between successive lines, repeated as a cycle (§5.1).
    """
    try:
        angle = float(a)
        ws = tuple(float(w) for w in (w1, *widths))
    except (TypeError, ValueError):
        raise InputError("stripes_properties: angle and widths must be numbers") from None
    if not math.isfinite(angle):
        raise InputError(f"stripes_properties: angle must be finite, got {a!r}")
    for w in ws:
        if not (math.isfinite(w) and w > 0):
            raise InputError(f"stripes_properties: widths must be positive, got {w!r}")
    return StripesProperties(angle, ws)


def set_edge_labels(p: StripesProperties, l1: str, *labels: str) -> StripesProperties:
    """SetEdgeLabels(Properties p, String l1 [, String l2, ...]): adds edge labels to ``p``.

    Lines take the labels in turn, as a cycle (§5.1). Each call adds one cycle, so a line
    may carry several labels.
    """
    if not isinstance(p, StripesProperties):
        raise InputError(f"set_edge_labels: expected stripes properties, got {type(p).__name__} (use set_weighted_edge_labels for irregular properties)")
    return replace(p, edge_labels=p.edge_labels + (_label_list((l1, *labels), "set_edge_labels"),))


def set_face_labels(p: StripesProperties, l1: str, *labels: str) -> StripesProperties:
    """SetFaceLabels(Properties p, String l1 [, String l2, ...]): adds face labels to ``p``.

    Stripes (the faces between two successive lines) take the labels in turn. In a grid
    each face gets one label per stripes set (§5.1: "each single face receives a total of
    two labels").
    """
    if not isinstance(p, StripesProperties):
        raise InputError(f"set_face_labels: expected stripes properties, got {type(p).__name__} (use set_weighted_face_labels for irregular properties)")
    return replace(p, face_labels=p.face_labels + (_label_list((l1, *labels), "set_face_labels"),))


#: Bounds on how far :func:`_snap_stripes` may move a stripes set to make it repeat with a
#: tile (issue 18): the lines turn by at most this angle (radians) ...
_SNAP_MAX_TURN = math.radians(15.0)
#: ... and the widths change by at most this factor (either way).
_SNAP_MAX_WIDTH_RATIO = 2.0


def _stripes_repeat(p: StripesProperties) -> float:
    """The repeat of a stripes set along its normal: the widths' cycle, extended to a whole
    number of every label cycle."""
    m = len(p.widths)
    cycle = m
    for g in (*p.edge_labels, *p.face_labels):
        cycle = cycle * len(g) // math.gcd(cycle, len(g))
    return float(sum(p.widths)) * cycle / m


def _snap_reach(turn: float, ratio: float) -> float:
    """How far (in units of the asked frequency's length) a frequency vector that turns by
    at most ``turn`` and scales the widths by a factor within ``ratio`` either way can be
    from the asked one: ``|r e^{i d} - 1| <= (ratio - 1) + ratio * 2 sin(turn / 2)`` for
    ``1 / ratio <= r <= ratio`` and ``|d| <= turn``."""
    return (ratio - 1.0) + ratio * 2.0 * math.sin(min(turn, math.pi) / 2.0)


def _snap_window(n0: np.ndarray, period: float, w: float, h: float, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Every lattice vector ``(k, l)`` but ``(0, 0)`` in the box around the asked frequency
    ``n0 / period`` that holds the disc of radius ``reach / period`` about it (the
    frequency of ``(k, l)`` is ``(k / w, l / h)``)."""
    kc, lc = w * n0[0] / period, h * n0[1] / period
    rk, rl = reach * w / period + 1.0, reach * h / period + 1.0
    ks = np.arange(math.ceil(kc - rk), math.floor(kc + rk) + 1, dtype=float)
    ls = np.arange(math.ceil(lc - rl), math.floor(lc + rl) + 1, dtype=float)
    k, l = (x.ravel() for x in np.meshgrid(ks, ls, indexing="ij"))
    keep = (k != 0) | (l != 0)
    return k[keep], l[keep]


def _snap_measures(k: np.ndarray, l: np.ndarray, n0: np.ndarray, period: float, w: float, h: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """For lattice vectors ``(k, l)``: the signed turn (radians, from ``n0`` to the
    snapped normal), the snapped widths' ratio to the asked ones, and the cost
    ``|period (k / w, l / h) - n0|**2``."""
    vx, vy = k / w, l / h
    turn = np.arctan2(n0[0] * vy - n0[1] * vx, n0[0] * vx + n0[1] * vy)
    ratio = 1.0 / (period * np.hypot(vx, vy))
    cost = (period * vx - n0[0]) ** 2 + (period * vy - n0[1]) ** 2
    return turn, ratio, cost


def _snap_stripes(p: StripesProperties, tile: tuple[float, float, float, float]) -> StripesProperties:
    """The stripes set nearest ``p`` that repeats with the tile's periods (issue 18).

    A stripes set of unit normal ``n`` and repeat ``P`` (the widths' cycle, extended to a
    whole number of every label cycle) is invariant under the translation ``t`` when
    ``t . n`` is a multiple of ``P``. Both tile periods are when ``n / P = (k / W, l / H)``
    for integers ``k`` and ``l``. The angle and the widths change (the widths all by one
    factor ``s``), which the paper's fixed stripes do not need (Loi §5.1 has no tile).

    Of the lattice vectors ``(k, l)`` that turn the lines by at most ``_SNAP_MAX_TURN``
    (15 degrees; never flipping the normal, which would reverse the label order) and keep
    ``s`` within a factor ``_SNAP_MAX_WIDTH_RATIO`` (2) either way, the one of least cost
    ``|P (k / W, l / H) - n0|**2`` is taken: the squared distance to the asked frequency
    vector ``n0 / P``, relative to its length (to first order ``turn**2 + (1 - 1 / s)**2``).
    Its unbounded minimum is ``k`` and ``l`` rounded (the rule before), which is kept
    whenever it is within bounds, so those tiles are unchanged. Rounding alone turned the
    lines by up to 90 degrees when the tile holds about one repeat (65 degrees for angle
    2, widths 21 and 40 with three labels, tile 100 x 220). Otherwise the search is
    bounded: the box of lattice vectors that can meet the bounds (rounding misses them only
    when ``P > 0.36 min(W, H)``, so the box spans at most 11 vectors across the tile's
    shorter side and about ``3 max(W, H) / P + 3`` along the longer one). When none does, an
    :class:`InputError` names the angle, the tile and the nearest reachable angle, rather
    than turning the stripes silently.
    """
    _, _, w, h = (float(x) for x in tile)
    period = _stripes_repeat(p)
    n0 = np.array([-math.sin(p.angle), math.cos(p.angle)])
    k0, l0 = round(w * n0[0] / period), round(h * n0[1] / period)
    if k0 == 0 and l0 == 0:
        raise InputError(
            f"periodic: the tile ({w:g} x {h:g}) is smaller than two stripes of this set "
            f"(it repeats every {period:g} units); use a larger tile or narrower stripes"
        )
    max_turn, max_log = _SNAP_MAX_TURN + 1e-12, math.log(_SNAP_MAX_WIDTH_RATIO) + 1e-12
    k, l = np.array([k0], dtype=float), np.array([l0], dtype=float)
    turn, ratio, cost = _snap_measures(k, l, n0, period, w, h)
    ok = (np.abs(turn) <= max_turn) & (np.abs(np.log(ratio)) <= max_log)
    if not ok[0]:
        nearest = (float(turn[0]), float(ratio[0]))
        k, l = _snap_window(n0, period, w, h, _snap_reach(max_turn, _SNAP_MAX_WIDTH_RATIO))
        turn, ratio, cost = _snap_measures(k, l, n0, period, w, h)
        ok = (np.abs(turn) <= max_turn) & (np.abs(np.log(ratio)) <= max_log)
        if not ok.any():
            raise InputError(_snap_refusal(p, period, n0, w, h, nearest))
    i = int(np.argmin(np.where(ok, cost, np.inf)))
    v = np.array([k[i] / w, l[i] / h])
    p_new = 1.0 / float(np.hypot(v[0], v[1]))
    n = v * p_new
    angle = math.atan2(-n[0], n[1])
    f = p_new / period
    return replace(p, angle=angle, widths=tuple(x * f for x in p.widths))


def _snap_refusal(p: StripesProperties, period: float, n0: np.ndarray, w: float, h: float, nearest: tuple[float, float]) -> str:
    """The message of :func:`_snap_stripes` when no lattice direction is within bounds:
    the asked angle, the tile, and the nearest reachable angle: the least turn among the
    lattice vectors whose widths are within bounds, else (none is) the turn and widths'
    ratio ``nearest`` of the nearest lattice vector."""
    k, l = _snap_window(n0, period, w, h, _snap_reach(math.pi, _SNAP_MAX_WIDTH_RATIO))
    turn, ratio, _ = _snap_measures(k, l, n0, period, w, h)
    fits = np.abs(np.log(ratio)) <= math.log(_SNAP_MAX_WIDTH_RATIO)
    if fits.any():
        i = int(np.argmin(np.where(fits, np.abs(turn), np.inf)))
        t, s = float(turn[i]), float(ratio[i])
    else:
        t, s = nearest
    near = round(p.angle + t, 4) + 0.0  # + 0.0: no "-0"
    return (
        f"periodic: stripes at angle {p.angle:g} rad ({math.degrees(p.angle):.1f} deg), repeating every "
        f"{period:g} units, cannot repeat on the {w:g} x {h:g} tile within {math.degrees(_SNAP_MAX_TURN):g} deg "
        f"of that angle and a factor {_SNAP_MAX_WIDTH_RATIO:g} on the widths; the nearest reachable angle is "
        f"{near:.4f} rad ({math.degrees(near):.1f} deg, a turn of {math.degrees(t):+.1f} deg, widths x {s:.3g}); "
        f"use a larger tile, narrower stripes or that angle"
    )


def _stripe_lines(p: StripesProperties, bounds: tuple[float, float, float, float], fixed: bool = False) -> list[Curve]:
    """Lines of a stripes set covering ``bounds``; line 0 passes through the origin.

    The phase is fixed in the plane (not by the region), so a stripes set is the same
    wherever it is evaluated. With ``fixed`` (a world's tiles, issue 19.1) each line is a
    polyline whose vertices are fixed in the plane too (every narrowest width along it,
    from its foot on the normal through the origin), so that two tiles crop it to pieces
    that share their inner segments and node them to the same bits.
    """
    if fixed:
        return _fixed_stripe_lines(p, bounds)
    x0, y0, x1, y1 = bounds
    d = np.array([math.cos(p.angle), math.sin(p.angle)])
    nrm = np.array([-d[1], d[0]])
    corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    proj = corners @ nrm
    tmin, tmax = float(proj.min()), float(proj.max())
    c = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    half = 0.5 * math.hypot(x1 - x0, y1 - y0) + 1.0
    lines = []
    for tk, labs, left, right in _stripe_offsets(p, tmin, tmax):
        base = c + (tk - float(c @ nrm)) * nrm
        pts = np.round(np.array([base - half * d, base + half * d]), 9)
        lines.append(Curve(pts, False, labs, left, right))
    return lines


def _stripe_offsets(p: StripesProperties, tmin: float, tmax: float) -> Iterator[tuple[float, frozenset, frozenset, frozenset]]:
    """Each line of a stripes set whose offset along the normal is within a period of
    ``[tmin, tmax]``: its offset ``t_k``, edge labels, and the face labels on its left
    and right."""
    m = len(p.widths)
    cum = np.r_[0.0, np.cumsum(p.widths)]
    period = float(cum[-1])
    q0, q1 = math.floor(tmin / period) - 1, math.ceil(tmax / period) + 1
    for q in range(q0, q1 + 1):
        for r in range(m):
            tk = q * period + cum[r]
            if tk < tmin - period or tk > tmax + period:
                continue
            k = q * m + r
            labs = frozenset(g[k % len(g)] for g in p.edge_labels)
            # stripe k lies between line k and line k + 1, on the +normal side of line k;
            # +normal is the math-left of d, i.e. the right as seen in y-down coordinates
            right = frozenset(g[k % len(g)] for g in p.face_labels)
            left = frozenset(g[(k - 1) % len(g)] for g in p.face_labels)
            yield tk, labs, left, right


def _fixed_stripe_lines(p: StripesProperties, bounds: tuple[float, float, float, float]) -> list[Curve]:
    """:func:`_stripe_lines` with vertices fixed in the plane (issue 19.1; not in the paper,
    whose partitions are evaluated once): line ``k``'s vertices are ``t_k n + (m + 1/pi) w d``
    for integers ``m`` (``n`` the normal, ``d`` the direction, ``w`` the narrowest width)."""
    x0, y0, x1, y1 = bounds
    d = np.array([math.cos(p.angle), math.sin(p.angle)])
    nrm = np.array([-d[1], d[0]])
    corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    proj = corners @ nrm
    along = corners @ d
    tmin, tmax = float(proj.min()), float(proj.max())
    # a vertex every narrowest width (a tile whose halo is at least that keeps whole the
    # segments that cross it), offset by an odd fraction of it: at whole widths the
    # vertices would sit on the crossings of a grid's other set (widths in proportion),
    # where a piece shorter than the attribution tolerance would carry both lines' labels
    step = float(min(p.widths))
    s0, s1 = math.floor(float(along.min()) / step) - 1, math.ceil(float(along.max()) / step) + 1
    steps = (np.arange(s0, s1 + 1, dtype=float) + _ODD) * step
    lines = []
    for tk, labs, left, right in _stripe_offsets(p, tmin, tmax):
        pts = np.round(tk * nrm[None, :] + steps[:, None] * d[None, :], 9)
        lines.append(Curve(pts, False, labs, left, right))
    return lines


def _field_top(geom: shapely.Geometry) -> Field | None:
    """The world evaluation when ``geom`` is its top-level domain, else None."""
    f = field()
    return f if f is not None and geom is f.domain else None


def stripes_partition(p: StripesProperties, *, border: Border | None = None) -> ArrangementFunction:
    """StripesPartition(Properties p): creates a stripes partition.

    Stripes partitions are always cropped, as their faces are infinite (§5.2). Cropped
    lines alone close no face, so the keyword ``border`` (an addition to the paper's
    signature) says whether the region's outline is added:

    - default (None): ``CROP_ADD_BOUNDARY`` when ``p`` carries face labels (the stripes
      become faces that carry them, as in the paper's Fig. 5a), else ``CROP`` (open
      lines, e.g. a hatching to merge with other arrangements);
    - ``CROP``: open lines only; face labels then label no face, since there is none;
    - ``CROP_ADD_BOUNDARY``: always closed by the outline.
    """
    if not isinstance(p, StripesProperties):
        raise InputError(f"stripes_partition: expected stripes properties, got {type(p).__name__}")
    if border is None:
        border = CROP_ADD_BOUNDARY if p.face_labels else CROP
    b = _check_border(border, "stripes_partition")
    if b not in (Border.CROP, Border.CROP_ADD_BOUNDARY):
        raise InputError("stripes_partition: stripes faces are infinite; border must be CROP or CROP_ADD_BOUNDARY")

    def fn(geom: shapely.Geometry, ctx: Context) -> Curves:
        per = _periodic_top(geom)
        q = p if per is None else _snap_stripes(p, per.tile)
        lines = _stripe_lines(q, _padded_bounds(geom, 1.0), _field_top(geom) is not None)
        return _apply_border(Curves(tuple(lines)), geom, b)

    return ArrangementFunction(_equivariant(fn), "stripes_partition")


def grid_partition(s1: StripesProperties, s2: StripesProperties, b: Border) -> ArrangementFunction:
    """GridPartition(Stripes S1, Stripes S2, Border b): creates a grid partition.

    The grid is the union of two stripes sets; with ``KEEP_INSIDE`` / ``KEEP_OUTSIDE``
    whole grid cells are kept (§5.2).
    """
    for name, s in (("S1", s1), ("S2", s2)):
        if not isinstance(s, StripesProperties):
            raise InputError(f"grid_partition: {name} must be stripes properties, got {type(s).__name__}")
    border = _check_border(b, "grid_partition")
    if abs(math.sin(s1.angle - s2.angle)) < 1e-9:
        raise InputError("grid_partition: the two stripes sets are parallel")

    def fn(geom: shapely.Geometry, ctx: Context) -> Curves:
        per = _periodic_top(geom)
        t1, t2 = (s1, s2) if per is None else (_snap_stripes(s1, per.tile), _snap_stripes(s2, per.tile))
        if abs(math.sin(t1.angle - t2.angle)) < 1e-9:
            raise InputError("grid_partition: on this periodic tile the two stripes sets snap to one direction; use a larger tile")
        pad = 2.0 * max(max(t1.widths), max(t2.widths)) / max(abs(math.sin(t1.angle - t2.angle)), 0.05) + 1.0
        bounds = _padded_bounds(geom, pad)
        fixed = _field_top(geom) is not None
        lines = _stripe_lines(t1, bounds, fixed) + _stripe_lines(t2, bounds, fixed)
        return _apply_border(Curves(tuple(lines)), geom, border)

    return ArrangementFunction(_equivariant(fn), "grid_partition")


# -- irregular partitions -----------------------------------------------------------------
@dataclass(frozen=True)
class IrregularProperties:
    """Irregular partition properties: density and weighted label groups."""

    density: float
    vertex_labels: tuple[tuple[tuple[str, float], ...], ...] = ()
    edge_labels: tuple[tuple[tuple[str, float], ...], ...] = ()
    face_labels: tuple[tuple[tuple[str, float], ...], ...] = ()


def irregular_properties(d: float) -> IrregularProperties:
    """IrregularProperties(Scalar d): sets the partition density (samples per unit area)."""
    try:
        dens = float(d)
    except (TypeError, ValueError):
        raise InputError(f"irregular_properties: density must be a number, got {d!r}") from None
    if not (math.isfinite(dens) and dens > 0):
        raise InputError(f"irregular_properties: density must be positive, got {d!r}")
    return IrregularProperties(dens)


def _check_irregular(p: Any, where: str) -> IrregularProperties:
    if not isinstance(p, IrregularProperties):
        raise InputError(f"{where}: expected irregular properties, got {type(p).__name__}")
    return p


def set_weighted_vertex_labels(p: IrregularProperties, l1: str, w1: float, *more: Any) -> IrregularProperties:
    """SetWeightedVertexLabels(Properties p, String l1, Scalar w1 [, String l2, Scalar w2, ...]).

    Adds vertex labels to ``p``: each vertex draws one of the labels with the given
    apparition probabilities (normalised when they sum above 1; below 1 the rest is no
    label).
    """
    p = _check_irregular(p, "set_weighted_vertex_labels")
    return replace(p, vertex_labels=p.vertex_labels + (_weighted_list((l1, w1, *more), "set_weighted_vertex_labels"),))


def set_weighted_edge_labels(p: IrregularProperties, l1: str, w1: float, *more: Any) -> IrregularProperties:
    """SetWeightedEdgeLabels(Properties p, String l1, Scalar w1 [, String l2, Scalar w2, ...]).

    Adds edge labels to ``p``, drawn per edge with the given probabilities.
    """
    p = _check_irregular(p, "set_weighted_edge_labels")
    return replace(p, edge_labels=p.edge_labels + (_weighted_list((l1, w1, *more), "set_weighted_edge_labels"),))


def set_weighted_face_labels(p: IrregularProperties, l1: str, w1: float, *more: Any) -> IrregularProperties:
    """SetWeightedFaceLabels(Properties p, String l1, Scalar w1 [, String l2, Scalar w2, ...]).

    Adds face labels to ``p``, drawn per face with the given probabilities.
    """
    p = _check_irregular(p, "set_weighted_face_labels")
    return replace(p, face_labels=p.face_labels + (_weighted_list((l1, w1, *more), "set_weighted_face_labels"),))


def _canonical_ids(keys: np.ndarray) -> np.ndarray:
    """Dense ids of the rows of an integer array (equal rows, equal ids), in sorted order."""
    if len(keys) == 0:
        return np.zeros(0, np.int64)
    _, inv = np.unique(keys, axis=0, return_inverse=True)
    return inv.reshape(-1).astype(np.int64)


def _keyed_labels(groups: tuple[tuple[tuple[str, float], ...], ...], keys: list[bytes], seed: int, kind: str) -> list[frozenset[str]]:
    """:func:`_draw_labels` with each cell's draw a function of (``seed``, its key): the
    same cell gets the same labels in every tile of a world (issue 19.1)."""
    out: list[set[str]] = [set() for _ in keys]
    for gi, group in enumerate(groups):
        labs = [g[0] for g in group]
        w = np.array([g[1] for g in group], dtype=float)
        cum = np.cumsum(w) / max(1.0, float(w.sum()))
        u = np.array([unit_random(seed, kind, gi, k) for k in keys], dtype=float)
        idx = np.searchsorted(cum, u, side="right")
        for i, k in enumerate(idx.tolist()):
            if k < len(labs):
                out[i].add(labs[k])
    return [frozenset(s) for s in out]


def _canonical_vertices(points: np.ndarray, rp: np.ndarray, rv: np.ndarray, qhull: np.ndarray) -> np.ndarray:
    """The Voronoi vertices ``qhull`` recomputed as the circumcentres of their sites, taken
    in lexicographic order (the three smallest when more are cocircular): a function of
    those sites alone, not of the rest of the diagram (qhull's own vertices are not)."""
    n_v = len(qhull)
    V = np.array(qhull, dtype=float, copy=True)
    sites: list[list[int]] = [[] for _ in range(n_v)]
    for (a, b), (va, vb) in zip(rp.tolist(), rv.tolist()):
        for v in (va, vb):
            if v >= 0:
                sites[v] += [a, b]
    for v, lst in enumerate(sites):
        ids = sorted(set(lst), key=lambda k: (points[k, 0], points[k, 1]))
        if len(ids) < 3:
            continue
        (ax, ay), (bx, by), (cx, cy) = (points[k].tolist() for k in ids[:3])
        bx, by, cx, cy = bx - ax, by - ay, cx - ax, cy - ay
        dd = 2.0 * (bx * cy - by * cx)
        if dd == 0.0:
            continue
        b2, c2 = bx * bx + by * by, cx * cx + cy * cy
        V[v] = (ax + (cy * b2 - by * c2) / dd, ay + (bx * c2 - cx * b2) / dd)
    return V


def _voronoi_curves(
    sites: np.ndarray,
    p: IrregularProperties,
    bounds: tuple[float, float, float, float],
    rng: np.random.Generator,
    *,
    periodic_tile: tuple[float, float, float, float] | None = None,
    site_ids: np.ndarray | None = None,
    keyed: int | None = None,
) -> Curves:
    """Voronoi edges of ``sites`` as labelled curves (face labels on their sides).

    With ``periodic_tile`` the sites are translates of ``site_ids.max() + 1`` canonical
    sites (``site_ids`` (n,) gives each one's), and every label is drawn once per cell of
    the torus: a face, edge or vertex and its translates carry the same labels.
    """
    from scipy.spatial import Voronoi

    n = len(sites)
    if n < 2:
        return Curves()
    x0, y0, x1, y1 = bounds
    span = max(x1 - x0, y1 - y0)
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    # four far guard sites make every real cell bounded, whatever the number of sites
    guards = np.array([[cx - 20 * span, cy], [cx + 20 * span, cy], [cx, cy - 20 * span], [cx, cy + 20 * span]])
    vor = Voronoi(np.vstack([sites, guards]), qhull_options="Qbb Qc Qz")
    rp = vor.ridge_points
    rv = np.array(vor.ridge_vertices, dtype=np.int64)
    keep = (rp.min(axis=1) < n) & (rv.min(axis=1) >= 0)
    rp, rv = rp[keep], rv[keep]
    V = vor.vertices
    if keyed is not None:
        # a world's tile (issue 19.1): every vertex is the circumcentre of its three sites
        # and every label a function of the sites (not of the order of cells), so that the
        # tiles that share a cell compute it to the same bits
        V = _canonical_vertices(vor.points, rp, rv, V)
        face_labs = _keyed_labels(p.face_labels, [vor.points[k].tobytes() for k in range(n)], keyed, "face")
        ekeys = [min(vor.points[a].tobytes(), vor.points[b].tobytes()) + max(vor.points[a].tobytes(), vor.points[b].tobytes())
                 for a, b in rp.tolist()]
        edge_labs = _keyed_labels(p.edge_labels, ekeys, keyed, "edge")
    elif periodic_tile is None or site_ids is None:
        face_labs = _draw_labels(p.face_labels, n, rng)
        edge_labs = _draw_labels(p.edge_labels, len(rp), rng)
    else:
        # one draw per torus cell: a face by its canonical site, an edge by its two
        # canonical sites and the offset between them
        ids = np.r_[site_ids, -1 - np.arange(len(guards))]
        n_canon = int(site_ids.max()) + 1
        canon = _draw_labels(p.face_labels, n_canon, rng)
        face_labs = [canon[int(k)] for k in site_ids]
        q = 1e-6 * max(periodic_tile[2], periodic_tile[3])
        a, b = ids[rp[:, 0]], ids[rp[:, 1]]
        off = np.rint((vor.points[rp[:, 1]] - vor.points[rp[:, 0]]) / q).astype(np.int64)
        swap = a > b
        a2, b2 = np.where(swap, b, a), np.where(swap, a, b)
        off = np.where(swap[:, None], -off, off)
        eid = _canonical_ids(np.c_[a2, b2, off])
        canon_e = _draw_labels(p.edge_labels, int(eid.max()) + 1 if len(eid) else 0, rng)
        edge_labs = [canon_e[int(k)] for k in eid]
    curves = []
    for (a, b), (va, vb), elab in zip(rp.tolist(), rv.tolist(), edge_labs):
        pa, pb = V[va], V[vb]
        d = pb - pa
        w = vor.points[a] - pa
        la = face_labs[a] if a < n else EMPTY
        lb = face_labs[b] if b < n else EMPTY
        # cross(d, w) < 0: site a is on the left as seen in y-down coordinates
        if d[0] * w[1] - d[1] * w[0] < 0:
            left, right = la, lb
        else:
            left, right = lb, la
        curves.append(Curve(np.array([pa, pb]), False, elab, left, right))
    marks: tuple[tuple[float, float, frozenset[str]], ...] = ()
    if p.vertex_labels:
        used = np.unique(rv)
        if keyed is not None:
            vlabs = _keyed_labels(p.vertex_labels, [V[k].tobytes() for k in used.tolist()], keyed, "vertex")
        elif periodic_tile is None:
            vlabs = _draw_labels(p.vertex_labels, len(used), rng)
        else:
            x0, y0, w, h = periodic_tile
            q = 1e-6 * max(w, h)
            cv = V[used] - np.array([x0, y0])
            cv = np.c_[np.mod(cv[:, 0], w), np.mod(cv[:, 1], h)]
            key = np.rint(cv / q).astype(np.int64)
            key[:, 0] %= int(round(w / q))
            key[:, 1] %= int(round(h / q))
            vid = _canonical_ids(key)
            canon_v = _draw_labels(p.vertex_labels, int(vid.max()) + 1, rng)
            vlabs = [canon_v[int(k)] for k in vid]
        marks = tuple((float(V[k, 0]), float(V[k, 1]), lab) for k, lab in zip(used.tolist(), vlabs) if lab)
    return Curves(tuple(curves), {}, marks)


def _irregular_partition(p: IrregularProperties, b: Border, name: str, sampler: Callable[..., np.ndarray]) -> ArrangementFunction:
    p = _check_irregular(p, name)
    border = _check_border(b, name)

    def fn(geom: shapely.Geometry, ctx: Context) -> Curves:
        rng = ctx.rng(name, p)
        spacing = 1.0 / math.sqrt(p.density)
        per = _periodic_top(geom)
        if per is not None:
            return _periodic_irregular(p, border, name, geom, per, rng, spacing)
        if _field_top(geom) is not None:
            # a world's tile (issue 19.1): the sites of a field fixed in the plane
            from ._world import field_sites

            bounds = _padded_bounds(geom, 4 * spacing)
            key = derive_seed(ctx.seed, name, p)
            sites = field_sites(name, p.density, key, bounds)
            return _apply_border(_voronoi_curves(sites, p, bounds, rng, keyed=key), geom, border)
        x0, y0, x1, y1 = geom.bounds
        expected = p.density * (x1 - x0 + 8 * spacing) * (y1 - y0 + 8 * spacing)
        if expected > 5e6:
            raise InputError(f"{name}: density {p.density:g} asks for about {expected:.3g} cells on this region; lower it")
        # sites in a margin of 4 mean spacings, so that cells near the border are exact
        bounds = _padded_bounds(geom, 4 * spacing)
        sites = sampler(bounds, p.density, rng)
        return _apply_border(_voronoi_curves(sites, p, bounds, rng), geom, border)

    return ArrangementFunction(_equivariant(fn), name)


def _periodic_irregular(
    p: IrregularProperties, border: Border, name: str, geom: shapely.Geometry, per: Periodic, rng: np.random.Generator, spacing: float
) -> Curves:
    """An irregular partition that repeats with the tile: the Voronoi diagram of the
    translates of a point set on the torus (issue 18; §5.1's sets, drawn on the torus)."""
    x0, y0, w, h = per.tile
    expected = p.density * w * h
    if expected < 2:
        raise InputError(
            f"periodic: the tile ({w:g} x {h:g}) holds about {expected:.2g} cells at density {p.density:g}; "
            "it needs at least two (use a larger tile or a higher density)"
        )
    if expected > 5e6:
        raise InputError(f"{name}: density {p.density:g} asks for about {expected:.3g} cells on this tile; lower it")
    sampler = periodic_poisson_disk if name == "uniform_partition" else periodic_poisson
    base = sampler(per.tile, p.density, rng)
    bounds = _padded_bounds(geom, 4 * spacing)
    i0, i1 = math.floor((bounds[0] - x0) / w), math.floor((bounds[2] - x0) / w)
    j0, j1 = math.floor((bounds[1] - y0) / h), math.floor((bounds[3] - y0) / h)
    pts, ids = [], []
    for j in range(j0, j1 + 1):
        for i in range(i0, i1 + 1):
            q = base + np.array([i * w, j * h])
            inside = (q[:, 0] >= bounds[0]) & (q[:, 0] <= bounds[2]) & (q[:, 1] >= bounds[1]) & (q[:, 1] <= bounds[3])
            pts.append(q[inside])
            ids.append(np.flatnonzero(inside))
    sites = np.vstack(pts)
    site_ids = np.concatenate(ids)
    curves = _voronoi_curves(sites, p, bounds, rng, periodic_tile=per.tile, site_ids=site_ids)
    return _apply_border(curves, geom, border)


def uniform_partition(p: IrregularProperties, b: Border) -> ArrangementFunction:
    """UniformPartition(Properties p, Border b): creates a uniform partition.

    The Voronoi diagram of a Poisson-disk set of the given density (§5.1).
    """
    return _irregular_partition(p, b, "uniform_partition", poisson_disk)


def random_partition(p: IrregularProperties, b: Border) -> ArrangementFunction:
    """RandomPartition(Properties p, Border b): creates a random partition.

    The Voronoi diagram of a Poisson set of the given density (§5.1).
    """
    return _irregular_partition(p, b, "random_partition", poisson)


# -- mapping operators (Table 2) ----------------------------------------------------------
def _mapper_location(mapper: Callable[..., Any], tb: Any) -> str:
    code = getattr(mapper, "__code__", None)
    fname = code.co_filename if code is not None else None
    line = code.co_firstlineno if code is not None else None
    while tb is not None:
        if fname is not None and tb.tb_frame.f_code.co_filename == fname:
            line = tb.tb_lineno
        tb = tb.tb_next
    name = getattr(mapper, "__name__", type(mapper).__name__)
    if fname is None:
        return f"mapper {name}"
    from pathlib import Path

    return f"{Path(fname).name} line {line}, in mapper {name}"


def _as_mapper_result(res: Any, mapper: Callable[..., Any]) -> Curves:
    if isinstance(res, Curves):
        return res
    if isinstance(res, PlanarMap):
        return res.curves
    code = getattr(mapper, "__code__", None)
    name = getattr(mapper, "__name__", type(mapper).__name__)
    where = f"mapper {name}"
    if code is not None:
        from pathlib import Path

        where = f"{Path(code.co_filename).name} line {code.co_firstlineno}, mapper {name}"
    if isinstance(res, ArrangementFunction):
        raise MapperError(f"{where}: returned an arrangement; evaluate it on the cell's face first: arrangement(face)")
    if res is None:
        raise MapperError(f"{where}: returned None; a mapper must return curves (use nothing() for no curves)")
    raise MapperError(f"{where}: returned {type(res).__name__}; a mapper must return curves (Curves, a planar map, or nothing())")


def _run_mapper(mapper: Callable[..., Any], cell: _Cell, ctx: Context) -> Curves:
    child = ctx.child("mapper", getattr(mapper, "__qualname__", repr(type(mapper))), cell.key)
    try:
        with evaluation(child):
            res = mapper(cell)
    except MapperError:
        raise
    except Exception as exc:
        import sys

        tb = sys.exc_info()[2]
        msg = str(exc).replace("\n", " ")
        raise MapperError(f"{_mapper_location(mapper, tb.tb_next if tb else None)}: {type(exc).__name__}: {msg}") from exc
    return _as_mapper_result(res, mapper)


def _mapping(mapper: Any, a: Any, kind: str) -> ArrangementFunction:
    name = f"map_to_{kind}"
    if not callable(mapper):
        raise InputError(f"{name}: the mapper must be a function of one cell, got {type(mapper).__name__}")
    arr = as_arrangement(a, name)

    def fn(geom: shapely.Geometry, ctx: Context) -> Curves:
        pm = PlanarMap(arr._eval(geom, ctx))
        if kind == "vertices":
            cells: list[_Cell] = [Vertex(pm, i) for i in range(pm.n_vertices)]
        elif kind == "edges":
            cells = [Edge(pm, i) for i in range(pm.n_edges)]
        else:
            cells = [Face(pm, i) for i in range(1, pm.n_faces)]
        if field() is not None:  # a world's tile: a mapper's cell must be whole there (issue 19.1)
            from ._world import check_cut_edges, check_open_faces

            if kind == "faces":
                check_open_faces(pm, geom, f"a face given to {name}")
            elif kind == "edges":
                check_cut_edges(pm, geom, f"an edge given to {name}")
        # §6: the mapper is applied homogeneously to every cell; each call gets its own
        # context, so the order of the calls does not matter
        return concat_curves([_run_mapper(mapper, c, ctx) for c in cells])

    return ArrangementFunction(fn, name)


def map_to_vertices(m: Callable[[Vertex], Any], a: Any) -> ArrangementFunction:
    """MapToVertices(Mapper m, Arrangement A): applies ``m`` to all vertices of ``A``."""
    return _mapping(m, a, "vertices")


def map_to_edges(m: Callable[[Edge], Any], a: Any) -> ArrangementFunction:
    """MapToEdges(Mapper m, Arrangement A): applies ``m`` to all edges of ``A``."""
    return _mapping(m, a, "edges")


def map_to_faces(m: Callable[[Face], Any], a: Any) -> ArrangementFunction:
    """MapToFaces(Mapper m, Arrangement A): applies ``m`` to all faces of ``A``.

    The mapper sees the bounded faces; the unbounded face has no centroid or contour
    and is left out.
    """
    return _mapping(m, a, "faces")


# -- merging operators (Table 4) ----------------------------------------------------------
def union(a1: Any, a2: Any) -> ArrangementFunction:
    """Union(Arrangement A1, Arrangement A2): all the curves from ``A1`` and ``A2`` (§7)."""
    x1, x2 = as_arrangement(a1, "union: A1"), as_arrangement(a2, "union: A2")

    def fn(geom: shapely.Geometry, ctx: Context) -> Curves:
        return concat_curves([x1._eval(geom, ctx), x2._eval(geom, ctx)])

    return ArrangementFunction(fn, "union")


def _mask(a1: Any, a2: Any, b: Any, keep_inside_faces: bool, name: str) -> ArrangementFunction:
    x1, x2 = as_arrangement(a1, f"{name}: A1"), as_arrangement(a2, f"{name}: A2")
    border = _check_border(b, name)

    def fn(geom: shapely.Geometry, ctx: Context) -> Curves:
        pm1 = PlanarMap(x1._eval(geom, ctx))
        pm2 = PlanarMap(x2._eval(geom, ctx))
        polys = [p for p in pm2._t.face_polygons[1:]]
        edges = _map_curves(pm1)
        if not polys:
            return edges if not keep_inside_faces else Curves()
        area = shapely.union_all(polys)
        if border in (Border.CROP, Border.CROP_ADD_BOUNDARY):
            out = _crop(edges, area, keep_inside_faces)
            if border is Border.CROP_ADD_BOUNDARY:
                t2 = pm2._t
                outline = tuple(
                    Curve(t2.edge_points[e])
                    for e in range(pm2.n_edges)
                    if t2.edge_left[e] != 0 or t2.edge_right[e] != 0
                )
                out = Curves(out.curves + outline, out.points, out.marks)
            return out
        lines = np.array([shapely.LineString(c.points) for c in edges.curves], dtype=object)
        if len(lines) == 0:
            return edges
        shapely.prepare(area)
        within = shapely.covered_by(lines, area.buffer(10 * pm1.grid))
        meets = shapely.relate_pattern(lines, area, "T********")
        if keep_inside_faces:
            keep = within if border is Border.KEEP_INSIDE else meets
        else:
            keep = ~meets if border is Border.KEEP_INSIDE else ~within
        return edges.select(keep.tolist())

    return ArrangementFunction(fn, name)


def inside(a1: Any, a2: Any, b: Border) -> ArrangementFunction:
    """Inside(Arrangement A1, Arrangement A2, Border b): edges of ``A1`` inside ``A2``'s faces.

    ``CROP`` cuts ``A1``'s edges at the boundary of ``A2``'s bounded faces,
    ``CROP_ADD_BOUNDARY`` also adds those faces' outlines, ``KEEP_INSIDE`` keeps only the
    edges wholly inside, ``KEEP_OUTSIDE`` every edge that enters a face (§7, Fig. 8).
    """
    return _mask(a1, a2, b, True, "inside")


def outside(a1: Any, a2: Any, b: Border) -> ArrangementFunction:
    """Outside(Arrangement A1, Arrangement A2, Border b): edges of ``A1`` outside ``A2``'s faces.

    ``CROP`` cuts ``A1``'s edges at the boundary of ``A2``'s bounded faces,
    ``CROP_ADD_BOUNDARY`` also adds those faces' outlines, ``KEEP_INSIDE`` keeps only the
    edges wholly outside, ``KEEP_OUTSIDE`` every edge that leaves the faces (§7, Fig. 8).
    """
    return _mask(a1, a2, b, False, "outside")

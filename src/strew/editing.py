"""Editing operations on arrangements, for interactive front ends and scripts.

What a painting tool needs besides a method: which new elements overlap existing ones,
which of a sequence of elements to leave out so that none overlap, which elements stick
out of a region or cross a boundary stroke, and a stroke on a repeat tile cut into runs
inside the tile. :mod:`strew.studio` is a thin layer over these; a script that edits an
arrangement by hand can use them too.

Cutting a region along boundary strokes is :func:`strew.region.cut_along`; an element's
bounding radius is :attr:`strew.Arrangement.radii`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
import shapely

from ._periodic import canonical, translations, wrap_delta
from .arrangement import Arrangement
from .region import Region, stroke_walls

__all__ = ["overlapping", "overlap_drops", "Bounds", "wrap_stroke", "near_stroke"]


def overlapping(new: Arrangement, existing: Arrangement) -> np.ndarray:
    """Elements of ``new`` whose outline intersects an element of ``existing``.

    Parameters
    ----------
    new, existing : Arrangement
        ``n`` and ``m`` elements.

    Returns
    -------
    (n,) bool
        Touching counts as intersecting (shapely ``intersects``). Only elements of
        ``existing`` whose bounding disc (:attr:`~strew.Arrangement.radii`) reaches one
        of ``new`` are tested exactly.
    """
    if len(new) == 0 or len(existing) == 0:
        return np.zeros(len(new), bool)
    from scipy.spatial import cKDTree

    near = cKDTree(new.xy).query_ball_point(existing.xy, r=existing.radii + new.radii.max(), return_length=True)
    cand = np.flatnonzero(near > 0)
    hit = np.zeros(len(new), bool)
    if len(cand) == 0:
        return hit
    ia, _ = shapely.STRtree(existing.select(cand).geometry).query(new.geometry, predicate="intersects")
    hit[np.unique(ia)] = True
    return hit


def overlap_drops(pairs: np.ndarray, n_fixed: int, new: np.ndarray, *, later: bool = True) -> np.ndarray:
    """Which elements to leave out so that nothing overlaps, given the overlapping pairs.

    The elements are ``n_fixed`` fixed ones followed by ``m`` others, in order of age.
    A new element (``new[j]``) that overlaps a fixed one goes. With ``later``, of two
    overlapping non-fixed elements the later goes, unless the earlier one went already:
    an element goes when an earlier kept element overlaps it. With ``n_fixed=0`` and every
    element new this is the rule by which :meth:`strew.synth.SynthState.to_arrangement`
    leaves overlapping output out when the exemplars' shapes do not overlap (the bounding
    discs of Davison et al. 2018, §4, do not rule overlaps out).

    Parameters
    ----------
    pairs : (p, 2) int
        Index pairs ``(i, j)``, ``i < j``, over the ``n_fixed + m`` elements (as
        :func:`strew.metrics.overlaps` returns them).
    n_fixed : int
        How many elements come first and never go.
    new : (m,) bool
        Which of the others may go for overlapping a fixed element.
    later : bool
        Also drop the later of two overlapping non-fixed elements.

    Returns
    -------
    (m,) bool
        The elements to leave out.
    """
    new = np.asarray(new, bool)
    dropped = np.zeros(len(new), bool)
    pairs = np.asarray(pairs, dtype=np.int64).reshape(-1, 2)
    for i, j in sorted(map(tuple, pairs.tolist()), key=lambda p: (p[1], p[0])):
        if j < n_fixed:
            continue
        if i < n_fixed:
            if new[j - n_fixed]:
                dropped[j - n_fixed] = True
        elif later and not dropped[i - n_fixed]:
            dropped[j - n_fixed] = True
    return dropped


class Bounds:
    """A region with boundary strokes: which elements stick out of it or cross a stroke.

    Filled elements must not overhang the region's border, nor cross a boundary stroke
    (Ijiri et al. 2008, §3, Fig. 1f). Both tests are exact on the outlines (shapely) and
    run only for elements whose bounding disc reaches the border or a stroke; the zones
    that decide this are cached per reach, so repeated calls on a growing scene are cheap.

    Parameters
    ----------
    region : Region
    strokes : sequence of (m, 2) float arrays
        Boundary strokes (polylines; those of one point are ignored).
    """

    def __init__(self, region: Region, strokes: Sequence[np.ndarray] = ()) -> None:
        self.region = region
        self.strokes = list(strokes)
        self._zones: dict[float, tuple[Any, Any]] = {}

    def zones(self, reach: float) -> tuple[Any, Any]:
        """The region eroded by ``reach`` and, with strokes, (the strokes widened by
        ``reach``, the strokes), all prepared; cached (``reach`` rounded up 5% and to
        1/64, so that a few widths share one entry)."""
        # 5% over: buffer() draws round joins and caps as inscribed chords (about 2% short
        # at its 8 segments a quarter circle)
        reach = float(np.ceil(reach * 1.05 * 64.0) / 64.0)
        if reach not in self._zones:
            inner = self.region.geometry.buffer(-reach)
            shapely.prepare(inner)
            band = None
            lines = [b for b in self.strokes if len(b) > 1]
            if lines:
                walls = stroke_walls(lines)
                near = walls.buffer(reach)
                shapely.prepare(near)
                shapely.prepare(walls)
                band = (near, walls)
            self._zones[reach] = (inner, band)
        return self._zones[reach]

    def outside(self, arr: Arrangement) -> np.ndarray:
        """(n,) bool: elements not wholly inside the region, or crossing a stroke.

        The inside test allows ``1e-9`` of the region's extent, as
        :meth:`strew.synth.SynthState.to_arrangement` clips.
        """
        n = len(arr)
        out = np.zeros(n, bool)
        if n == 0:
            return out
        x, y = arr.x, arr.y
        inner, band = self.zones(float(arr.radii.max()))
        out |= ~self.region.contains(arr.xy)
        # centres in the region eroded by the widest bounding radius are wholly inside; the
        # rest (a band along the border) get the exact test
        near = np.flatnonzero(~out & ~shapely.contains_xy(inner, x, y))
        if len(near):
            tol = 1e-9 * max(1.0, *map(abs, self.region.bounds))
            out[near[~self.region.contains_geometry(arr.select(near).geometry, tolerance=tol)]] = True
        if band is not None:
            near = np.flatnonzero(~out & shapely.contains_xy(band[0], x, y))
            if len(near):
                out[near[shapely.intersects(arr.select(near).geometry, band[1])]] = True
        return out


def near_stroke(xy: np.ndarray, points: np.ndarray, radius: float) -> np.ndarray:
    """Which points lie within ``radius`` of a stroke: the eraser's rule.

    Davison et al. 2018, §5.4: the eraser removes the elements whose centre lies within
    the brush radius of its path (as :func:`strew.synth.erase` does on a synthesis state).

    Parameters
    ----------
    xy : (n, 2) float
        Element centres.
    points : (m, 2) float
        The stroke, a polyline; one point is a disc about it.
    radius : float
        The tool's radius (the bound counts as within).

    Returns
    -------
    (n,) bool
    """
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    if len(xy) == 0 or len(points) == 0:
        return np.zeros(len(xy), bool)
    path = shapely.LineString(points) if len(points) > 1 else shapely.Point(points[0])
    return shapely.dwithin(path, shapely.points(xy), radius)


def wrap_stroke(points: np.ndarray, tile: tuple[float, float, float, float], radius: float = 0.0) -> list[np.ndarray]:
    """A stroke on the torus of a repeat tile, as runs inside the tile.

    Points are wrapped into the tile (:func:`strew._periodic.canonical`). Where the
    stroke crosses an edge it continues at the opposite edge: the run before the
    crossing ends beyond the edge, the run after it starts beyond the opposite edge, so
    that each run is continuous. With ``radius``, the runs' copies one tile away whose
    discs of that radius reach into the tile follow, so that a brush or an eraser near an
    edge also works across it.

    Parameters
    ----------
    points : (m, 2) float
        The stroke, in order.
    tile : (x0, y0, w, h)
        The repeat tile.
    radius : float
        The tool's radius (0: no copies).

    Returns
    -------
    list of (k, 2) float arrays
        The runs, then their copies.
    """
    points = np.asarray(points, dtype=float)
    if len(points) == 0:
        return [points]
    x, y = canonical(points[:, 0], points[:, 1], tile)
    pts = np.c_[x, y]
    runs: list[np.ndarray] = []
    start = 0
    for i in range(1, len(pts)):
        a, b = pts[i - 1], pts[i]
        step = np.array([wrap_delta(b[0] - a[0], tile[2]), wrap_delta(b[1] - a[1], tile[3])])
        if np.allclose(a + step, b):
            continue
        runs.append(np.vstack([pts[start:i], a + step]))  # up to the crossing, beyond the edge
        pts[i - 1] = b - step  # the next run starts beyond the opposite edge
        start = i - 1
    runs.append(pts[start:])
    if radius > 0:
        x0, y0, w, h = tile
        for run in list(runs):
            lo, hi = run.min(axis=0) - radius, run.max(axis=0) + radius
            for i, j in translations(3, 3):
                dx, dy = i * w, j * h
                if (i or j) and lo[0] + dx < x0 + w and hi[0] + dx > x0 and lo[1] + dy < y0 + h and hi[1] + dy > y0:
                    runs.append(run + [dx, dy])
    return runs

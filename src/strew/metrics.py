"""Measurements of arrangements, used by tests, benchmarks and ``strew info``.

Every function takes an :class:`~strew.Arrangement` and returns plain numbers or arrays.
:func:`fidelity` measures a result against the exemplar it continues (code in
``strew._fidelity``); :func:`pair_correlation` and :func:`nearest_neighbor_distances` are
its single-arrangement parts.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import shapely

from ._errors import InputError
from ._fidelity import FidelityReport, MetricResult, fidelity, nearest_neighbor_distances, pair_correlation
from .arrangement import Arrangement
from .region import Region

__all__ = [
    "overlaps",
    "overlap_area",
    "outside",
    "coverage",
    "density_uniformity",
    "nearest_neighbor_stats",
    "kind_fractions",
    "visible",
    "visible_count",
    "summary",
    "fidelity",
    "FidelityReport",
    "MetricResult",
    "pair_correlation",
    "nearest_neighbor_distances",
]


def overlaps(arr: Arrangement, *, tolerance: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """Pairs of elements whose geometries intersect, and their overlap areas.

    Two filled shapes overlap when their intersection has area above ``tolerance``
    (touching edges do not count). When either geometry is a stroke (no area), they
    overlap when they cross or touch, and the reported area is 0.

    Parameters
    ----------
    arr : Arrangement
    tolerance : float
        Intersection area at or below this does not count.

    Returns
    -------
    pairs : (m, 2) int
        Index pairs ``i < j``.
    areas : (m,) float
        Overlap area of each pair.

    Examples
    --------
    >>> from strew import Arrangement, Shape
    >>> a = Arrangement({"sq": Shape.rectangle(2, 2)}, [0, 0, 0], [0, 1, 10], [0, 0, 0])
    >>> pairs, areas = overlaps(a)
    >>> pairs.tolist(), areas.round(6).tolist()
    ([[0, 1]], [2.0])
    """
    n = len(arr)
    if n < 2:
        return np.zeros((0, 2), dtype=np.intp), np.zeros(0)
    geoms = arr.geometry
    left, right = arr.sindex.query(geoms, predicate="intersects")
    keep = left < right
    left, right = left[keep], right[keep]
    if len(left) == 0:
        return np.zeros((0, 2), dtype=np.intp), np.zeros(0)
    a, b = geoms[left], geoms[right]
    areal = (shapely.area(a) > 0) & (shapely.area(b) > 0)
    areas = np.zeros(len(left))
    if areal.any():
        try:
            areas[areal] = shapely.area(shapely.intersection(a[areal], b[areal]))
        except shapely.errors.GEOSException:  # a self-intersecting outline (e.g. a skeletal stroke)
            areas[areal] = shapely.area(shapely.intersection(shapely.make_valid(a[areal]), shapely.make_valid(b[areal])))
    # GEOS overlay can misjudge near-coincident edges: two adjacent strips whose shared
    # corners differ by 3e-14 intersected in one strip's whole area. Recheck every areal
    # hit on a fixed-precision grid a 1e-10 fraction of the coordinates' magnitude, which
    # merges such vertices and moves a real overlap's area by far below ``tolerance``.
    recheck = np.flatnonzero(areal & (areas > tolerance))
    if len(recheck):
        grid = 1e-10 * max(1.0, float(np.abs(shapely.bounds(geoms)).max()))
        try:
            areas[recheck] = shapely.area(shapely.intersection(a[recheck], b[recheck], grid_size=grid))
        except shapely.errors.GEOSException:
            pass  # an invalid outline: keep the unsnapped areas
    hit = np.where(areal, areas > tolerance, True)
    pairs = np.c_[left[hit], right[hit]].astype(np.intp)
    order = np.lexsort((pairs[:, 1], pairs[:, 0]))
    return pairs[order], areas[hit][order]


def overlap_area(arr: Arrangement) -> float:
    """Total pairwise overlap area."""
    return float(overlaps(arr)[1].sum())


def _region(arr: Arrangement, region: Region | None) -> Region | None:
    return region if region is not None else arr.region


def outside(arr: Arrangement, region: Region | None = None, *, tolerance: float = 1e-6) -> np.ndarray:
    """Indices of elements not wholly inside the region.

    Parameters
    ----------
    region : Region, optional
        Defaults to ``arr.region``; without one, nothing is outside.
    tolerance : float
        The region is grown by this distance first, to absorb rounding.

    Returns
    -------
    (k,) int
    """
    reg = _region(arr, region)
    if reg is None or len(arr) == 0:
        return np.zeros(0, dtype=np.intp)
    inside = reg.contains_geometry(arr.geometry, tolerance=tolerance)
    return np.flatnonzero(~inside)


def coverage(arr: Arrangement, region: Region | None = None) -> float:
    """Fraction of the region's area covered by elements (overlaps counted once).

    Without a region, the elements' bounding box is used.
    """
    reg = _region(arr, region)
    if len(arr) == 0:
        return 0.0
    geoms = arr.geometry_of("area_geometry")
    try:
        union = shapely.union_all(geoms)
    except shapely.errors.GEOSException:  # a self-intersecting outline
        union = shapely.union_all(shapely.make_valid(geoms))
    if reg is None:
        domain = shapely.box(*arr.bounds)
    else:
        domain = reg.geometry
    if domain.area <= 0:
        return 0.0
    return float(shapely.intersection(union, domain).area / domain.area)


def density_uniformity(
    arr: Arrangement,
    region: Region | None = None,
    *,
    window: float | None = None,
) -> float:
    """Coefficient of variation (std / mean) of element counts over square windows.

    Windows tile the region's bounding box; only windows wholly inside the region are
    counted. An element counts in the window holding its position. 0 means perfectly
    even; a Poisson process gives about ``1 / sqrt(mean count)``.

    Parameters
    ----------
    window : float, optional
        Window side; default: sized so that windows hold about 10 elements on average.

    Returns
    -------
    float
        NaN when fewer than two windows fit or no element lies in them.
    """
    reg = _region(arr, region)
    if len(arr) == 0:
        return float("nan")
    x0, y0, x1, y1 = reg.bounds if reg is not None else arr.bounds
    area = reg.area if reg is not None else max((x1 - x0) * (y1 - y0), 1e-12)
    if window is None:
        window = float(np.sqrt(area * 10.0 / len(arr)))
    if not window > 0:
        raise InputError(f"window: must be positive, got {window}")
    nx, ny = int((x1 - x0) // window), int((y1 - y0) // window)
    if nx * ny < 2:
        return float("nan")
    cx = ((arr.x - x0) // window).astype(np.int64)
    cy = ((arr.y - y0) // window).astype(np.int64)
    ok = (cx >= 0) & (cx < nx) & (cy >= 0) & (cy < ny)
    counts = np.bincount(cy[ok] * nx + cx[ok], minlength=nx * ny).astype(float)
    if reg is not None:
        boxes = shapely.box(
            x0 + np.tile(np.arange(nx), ny) * window,
            y0 + np.repeat(np.arange(ny), nx) * window,
            x0 + (np.tile(np.arange(nx), ny) + 1) * window,
            y0 + (np.repeat(np.arange(ny), nx) + 1) * window,
        )
        counts = counts[shapely.covers(reg.prepared, boxes)]
    if len(counts) < 2 or counts.mean() == 0:
        return float("nan")
    return float(counts.std() / counts.mean())


def nearest_neighbor_stats(arr: Arrangement) -> dict[str, float]:
    """Statistics of each element's distance to its nearest neighbour (by position).

    Returns
    -------
    dict
        ``mean``, ``std``, ``min``, ``median``, ``max`` and ``cv`` (std / mean); NaN
        with fewer than two elements.
    """
    if len(arr) < 2:
        nan = float("nan")
        return {"mean": nan, "std": nan, "min": nan, "median": nan, "max": nan, "cv": nan}
    from scipy.spatial import cKDTree

    d, _ = cKDTree(arr.xy).query(arr.xy, k=2)
    nn = d[:, 1]
    mean = float(nn.mean())
    return {
        "mean": mean,
        "std": float(nn.std()),
        "min": float(nn.min()),
        "median": float(np.median(nn)),
        "max": float(nn.max()),
        "cv": float(nn.std() / mean) if mean > 0 else float("nan"),
    }


def kind_fractions(arr: Arrangement) -> dict[str, float]:
    """Fraction of elements of each kind (kinds of the library with none give 0)."""
    n = len(arr)
    return {k: (c / n if n else 0.0) for k, c in arr.counts().items()}


def visible(arr: Arrangement) -> np.ndarray:
    """Which elements are drawn: not void (the synth ``void`` column, Davison §5.6) and
    not of an empty shape (an invisible helper).

    Returns
    -------
    (n,) bool

    Examples
    --------
    >>> from strew import Arrangement, Shape
    >>> a = Arrangement({"sq": Shape.rectangle(1, 1)}, [0, 0], [0, 5], [0, 0]).with_columns(void=[False, True])
    >>> visible(a).tolist()
    [True, False]
    """
    vis = ~shapely.is_empty(arr.geometry) if len(arr) else np.zeros(0, bool)
    if "void" in arr:
        vis &= ~np.asarray(arr["void"]).astype(bool)
    return vis


def visible_count(arr: Arrangement) -> int:
    """The one element count strew reports (gallery captions, CLI summaries, ``strew info``):
    the number of :func:`visible` elements."""
    return int(visible(arr).sum())


def _filled(arr: Arrangement) -> np.ndarray:
    """(n,) bool: elements with a filled area (the rest are open strokes or empty)."""
    return shapely.area(arr.geometry_of("area_geometry")) > 0 if len(arr) else np.zeros(0, bool)


def summary(arr: Arrangement, region: Region | None = None) -> dict[str, Any]:
    """All metrics in one JSON-ready dict (as ``strew info`` prints them).

    ``count`` is :func:`visible_count`; ``elements`` counts every row, voids and empty
    helpers included. ``overlap_pairs`` and ``overlap_area`` are :func:`overlaps` over all
    elements (strokes that touch count as pairs). They are split into
    ``filled_overlap_pairs`` / ``filled_overlap_area`` (both elements visible and filled,
    intersection area above the tolerance: shapes that run into each other) and
    ``stroke_crossings`` (visible pairs with at least one open stroke that cross or touch,
    often by design in line drawings).
    """
    pairs, areas = overlaps(arr)
    reg = _region(arr, region)
    vis = visible(arr)
    filled = _filled(arr) & vis
    if len(pairs):
        both_vis = vis[pairs[:, 0]] & vis[pairs[:, 1]]
        both_filled = filled[pairs[:, 0]] & filled[pairs[:, 1]]
    else:
        both_vis = both_filled = np.zeros(0, bool)
    out: dict[str, Any] = {
        "count": int(vis.sum()),
        "elements": len(arr),
        "counts": arr.counts(),
        "kind_fractions": kind_fractions(arr),
        "bounds": list(arr.bounds),
        "overlap_pairs": int(len(pairs)),
        "overlap_area": float(areas.sum()),
        "filled_overlap_pairs": int(both_filled.sum()),
        "filled_overlap_area": float(areas[both_filled].sum()),
        "stroke_crossings": int((both_vis & ~both_filled).sum()),
        "nearest_neighbor": nearest_neighbor_stats(arr),
        "density_cv": density_uniformity(arr, reg),
        "coverage": coverage(arr, reg),
    }
    if reg is not None:
        out["outside"] = int(len(outside(arr, reg)))
        out["region_area"] = reg.area
    return out

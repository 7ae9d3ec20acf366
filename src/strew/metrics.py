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

from ._periodic import _as_frame, canonical, frame, images, tiled_copies
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
    "wrap_overlaps",
    "repeat_report",
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

    A periodic arrangement (``meta["periodic"]``, issue 18) lives on a torus: an element
    crossing the tile's edge wraps in at the opposite edge, so there, with no ``region``
    given, an element is outside only if its centre is not in the half-open tile.

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
    tile = frame(arr) if region is None else None
    if tile is not None:
        x0, y0, w, h = tile
        ok = (arr.x >= x0 - tolerance) & (arr.x < x0 + w) & (arr.y >= y0 - tolerance) & (arr.y < y0 + h)
        return np.flatnonzero(~ok)
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


# -- repeat tiles (issue 18) --------------------------------------------------------------


def _tile_of(arr: Arrangement, tile: Any) -> tuple[float, float, float, float]:
    f = frame(arr) if tile is None else _as_frame(tile, "tile")
    if f is None:
        raise InputError("repeat: the arrangement is not periodic (no meta.periodic); give tile=[x0, y0, W, H] to judge it as one")
    return f


def _neighbourhood(arr: Arrangement, f: tuple[float, float, float, float]) -> tuple[Arrangement, np.ndarray, np.ndarray]:
    """The tile's elements and every copy of the repeat whose bounding box reaches the
    canonical elements' bounding box (so every overlap of the repeat shows as a pair with
    one canonical element). Returns the arrangement, the original index and the tile
    offset ``(m, 2)`` int of each row (the first ``len(arr)`` rows are ``arr``, offset 0)."""
    x0, y0, w, h = f
    n = len(arr)
    b = shapely.bounds(arr.geometry)
    ok = np.isfinite(b).all(axis=1)
    if not ok.any():
        return arr, np.arange(n), np.zeros((n, 2), np.int64)
    hx0, hy0 = b[ok, 0].min(), b[ok, 1].min()
    hx1, hy1 = b[ok, 2].max(), b[ok, 3].max()
    # elements larger than the tile reach copies further than the next one
    kx = min(3, int(np.ceil((hx1 - hx0) / w)))
    ky = min(3, int(np.ceil((hy1 - hy0) / h)))
    idx, off = [np.arange(n)], [np.zeros((n, 2), np.int64)]
    for j in range(-ky, ky + 1):
        for i in range(-kx, kx + 1):
            if i == 0 and j == 0:
                continue
            dx, dy = i * w, j * h
            hit = ok & (b[:, 2] + dx > hx0) & (b[:, 0] + dx < hx1) & (b[:, 3] + dy > hy0) & (b[:, 1] + dy < hy1)
            k = np.flatnonzero(hit)
            idx.append(k)
            off.append(np.tile([i, j], (len(k), 1)))
    index = np.concatenate(idx)
    offset = np.concatenate(off)
    sub = arr.select(index)
    sub = sub.replace(x=sub.x + offset[:, 0] * w, y=sub.y + offset[:, 1] * h, region=None)
    return sub, index, offset


def wrap_overlaps(arr: Arrangement, *, tile: Any = None, tolerance: float = 1e-9) -> dict[str, Any]:
    """Overlaps of a repeat tile laid side by side: inside the tile and across the wrap.

    Every pair of the infinite repeat is counted once, as a pair of the tile's elements
    ``(i, j)`` with the tile offset of ``j``'s copy (an element may meet its own copy).
    Pairs are split as :func:`summary` splits them: filled shapes overlapping by more
    than ``tolerance`` in area, and visible strokes that cross or touch.

    Parameters
    ----------
    arr : Arrangement
        A periodic arrangement (``meta["periodic"]``), or any arrangement with ``tile``.
    tile : (4,) float, optional
        ``x0, y0, W, H``; default the arrangement's own frame.
    tolerance : float
        Intersection area at or below this does not count (as in :func:`overlaps`).

    Returns
    -------
    dict
        ``pairs`` (m, 4) int array of ``i, j, ox, oy`` (offset of j's copy; ``i <= j``),
        ``filled`` (m,) bool, ``areas`` (m,) float, and the counts ``inside`` / ``across``
        (filled overlaps with offset 0 / not 0) and ``stroke_crossings_inside`` /
        ``stroke_crossings_across``.
    """
    f = _tile_of(arr, tile)
    n = len(arr)
    empty = {"pairs": np.zeros((0, 4), np.int64), "filled": np.zeros(0, bool), "areas": np.zeros(0), "inside": 0, "across": 0, "stroke_crossings_inside": 0, "stroke_crossings_across": 0}
    if n == 0:
        return empty
    x, y = canonical(arr.x, arr.y, f)
    arr = arr.replace(x=x, y=y)
    sub, index, offset = _neighbourhood(arr, f)
    pairs, areas = overlaps(sub, tolerance=tolerance)
    if len(pairs) == 0:
        return empty
    # keep pairs with a canonical element, as (i, j, offset of j relative to i)
    a, b = pairs[:, 0], pairs[:, 1]
    keep = (a < n) | (b < n)
    a, b, areas = a[keep], b[keep], areas[keep]
    swap = a >= n  # put the canonical one first
    a, b = np.where(swap, b, a), np.where(swap, a, b)
    i, j = index[a], index[b]
    o = offset[b] - offset[a]
    # one key per pair of the repeat: i <= j, and for i == j the offset's sign fixed
    flip = (i > j) | ((i == j) & ((o[:, 0] < 0) | ((o[:, 0] == 0) & (o[:, 1] < 0))))
    i, j = np.where(flip, j, i), np.where(flip, i, j)
    o = np.where(flip[:, None], -o, o)
    key = np.c_[i, j, o]
    key, first = np.unique(key, axis=0, return_index=True)
    areas = areas[first]
    vis = visible(arr)
    filled = _filled(arr) & vis
    both_vis = vis[key[:, 0]] & vis[key[:, 1]]
    both_filled = filled[key[:, 0]] & filled[key[:, 1]] & (areas > tolerance)
    across = (key[:, 2] != 0) | (key[:, 3] != 0)
    stroke = both_vis & ~both_filled
    return {
        "pairs": key,
        "filled": both_filled,
        "areas": areas,
        "inside": int((both_filled & ~across).sum()),
        "across": int((both_filled & across).sum()),
        "stroke_crossings_inside": int((stroke & ~across).sum()),
        "stroke_crossings_across": int((stroke & across).sum()),
    }


def _ratio(a: float, b: float) -> float:
    return float(a / b) if b > 0 and np.isfinite(a) else float("nan")


def repeat_report(arr: Arrangement, exemplar: Arrangement | None = None, *, tile: Any = None, strip: float | None = None) -> dict[str, Any]:
    """How well a tile repeats: overlaps across the wrap, and the tile's edge strips
    against its interior (issue 18).

    The edge strips are the bands of width ``strip`` along the four edges of the tile;
    on the torus they are bands of width ``2 strip`` straddling the seams of the repeat.
    A seamless tile has the same density, coverage and kind fractions there as in its
    interior; a tile made without wrapping thins out along its edges (centres kept a
    radius inside).

    Parameters
    ----------
    arr : Arrangement
        A periodic arrangement (``meta["periodic"]``), or any arrangement with ``tile``
        (e.g. a non-periodic run of the same size, for comparison).
    exemplar : Arrangement, optional
        Also compare the local fidelity (:func:`fidelity`'s local map) of windows
        straddling the seams with windows inside the tile: the map is computed on the
        tile and the copies around it, cropped to the tile grown by a window and a half.
    tile : (4,) float, optional
        ``x0, y0, W, H``; default the arrangement's own frame.
    strip : float, optional
        Strip width; default twice the median nearest-neighbour distance on the torus,
        at most a quarter of the tile's shorter side.

    Returns
    -------
    dict
        ``tile``, ``count``, ``strip``, ``overlaps`` (``inside``, ``across``,
        ``stroke_crossings_inside``, ``stroke_crossings_across``), ``density``,
        ``coverage`` (each ``edge``, ``interior`` and ``ratio`` edge / interior),
        ``kind_fractions`` (``edge``, ``interior``, ``max_difference``) and, with an
        exemplar, ``fidelity`` (``seam`` and ``interior`` median window scores, their
        ``ratio``, the share of failing windows ``seam_failing`` / ``interior_failing``
        and the window counts).

    Examples
    --------
    >>> from strew import Arrangement, Shape, _periodic
    >>> a = _periodic.mark(Arrangement({"d": Shape.circle(1)}, ["d", "d"], [0.5, 9.6], [5, 5]), [0, 0, 10, 10])
    >>> repeat_report(a)["overlaps"]["across"]
    1
    """
    f = _tile_of(arr, tile)
    x0, y0, w, h = f
    n = len(arr)
    if n:
        cx, cy = canonical(arr.x, arr.y, f)
        arr = arr.replace(x=cx, y=cy)
    ov = wrap_overlaps(arr, tile=f)
    out: dict[str, Any] = {
        "tile": [x0, y0, w, h],
        "count": visible_count(arr),
        "overlaps": {k: ov[k] for k in ("inside", "across", "stroke_crossings_inside", "stroke_crossings_across")},
    }
    vis = visible(arr)
    if strip is None:
        s = float("nan")
        if vis.sum() >= 2:
            from scipy.spatial import cKDTree

            p = np.c_[arr.x[vis] - x0, arr.y[vis] - y0]
            p = np.minimum(np.maximum(p, 0.0), np.nextafter([w, h], 0))  # cKDTree's box is half-open
            d, _ = cKDTree(p, boxsize=[w, h]).query(p, k=2)
            s = float(np.median(d[:, 1]))
        strip = min(2.0 * s, 0.25 * min(w, h)) if np.isfinite(s) and s > 0 else 0.125 * min(w, h)
    strip = float(strip)
    if not 0 < strip < 0.5 * min(w, h):
        raise InputError(f"strip: must be positive and under half the tile's shorter side ({0.5 * min(w, h):g}), got {strip:g}")
    out["strip"] = strip
    inner_box = shapely.box(x0 + strip, y0 + strip, x0 + w - strip, y0 + h - strip)
    edge_area = w * h - inner_box.area
    inner_area = inner_box.area
    inner = (arr.x >= x0 + strip) & (arr.x < x0 + w - strip) & (arr.y >= y0 + strip) & (arr.y < y0 + h - strip)
    n_in, n_edge = int((vis & inner).sum()), int((vis & ~inner).sum())
    out["density"] = {"edge": n_edge / edge_area, "interior": n_in / inner_area, "ratio": _ratio(n_edge / edge_area, n_in / inner_area)}
    # coverage: the area drawn in each part, wrapped copies included (the tile as drawn);
    # summed over elements (an overlap counts twice), clipped by rectangles: fast
    cov = {"edge": float("nan"), "interior": float("nan"), "ratio": float("nan")}
    if n:
        im = images(arr, f)
        geoms = im.geometry_of("area_geometry")[visible(im)]
        geoms = geoms[shapely.area(geoms) > 0]
        if len(geoms):
            try:
                a_tile = float(shapely.area(shapely.clip_by_rect(geoms, x0, y0, x0 + w, y0 + h)).sum())
                a_in = float(shapely.area(shapely.clip_by_rect(geoms, *inner_box.bounds)).sum())
            except shapely.errors.GEOSException:  # a self-intersecting outline
                geoms = shapely.make_valid(geoms)
                a_tile = float(shapely.area(shapely.clip_by_rect(geoms, x0, y0, x0 + w, y0 + h)).sum())
                a_in = float(shapely.area(shapely.clip_by_rect(geoms, *inner_box.bounds)).sum())
            a_edge = a_tile - a_in
            cov = {"edge": a_edge / edge_area, "interior": a_in / inner_area, "ratio": _ratio(a_edge / edge_area, a_in / inner_area)}
    out["coverage"] = cov
    names = arr.kind_names[vis] if n else np.zeros(0, dtype=object)
    part = inner[vis] if n else np.zeros(0, bool)

    def fractions(sel: np.ndarray) -> dict[str, float]:
        m = int(sel.sum())
        return {k: (float(np.sum(names[sel] == k)) / m if m else float("nan")) for k in arr.kinds}

    fe, fi = fractions(~part), fractions(part)
    diffs = [abs(fe[k] - fi[k]) for k in arr.kinds if np.isfinite(fe[k]) and np.isfinite(fi[k])]
    out["kind_fractions"] = {"edge": fe, "interior": fi, "max_difference": float(max(diffs)) if diffs else float("nan")}
    if exemplar is not None:
        out["fidelity"] = _seam_fidelity(arr, exemplar, f)
    return out


def _seam_fidelity(arr: Arrangement, exemplar: Arrangement, f: tuple[float, float, float, float]) -> dict[str, Any]:
    """Local fidelity of windows straddling the repeat's seams against windows inside the tile."""
    from ._fidelity import RESULT_MARGIN, _median_nn

    x0, y0, w, h = f
    ex_vis = exemplar.select(visible(exemplar))
    s = _median_nn(ex_vis.xy) if len(ex_vis) >= 2 else 0.0
    ex_area = exemplar.region.area if exemplar.region is not None else max(float(np.prod(np.subtract(exemplar.bounds[2:], exemplar.bounds[:2]))), 0.0)
    side = float(np.sqrt(ex_area))
    # the map's windows cover the block's interior (eroded by RESULT_MARGIN s): grow the
    # tile so that windows centred on every seam fit
    m = min(RESULT_MARGIN * s + side, max(w, h))
    block = (x0 - m, y0 - m, w + 2 * m, h + 2 * m)
    big = tiled_copies(arr, 3 + 2 * int(np.ceil(m / w)), 3 + 2 * int(np.ceil(m / h)), tile=f)
    keep = (big.x >= block[0]) & (big.x < block[0] + block[2]) & (big.y >= block[1]) & (big.y < block[1] + block[3])
    big = big.select(np.flatnonzero(keep)).replace(region=Region.rectangle(block[2], block[3], block[0], block[1]))
    rep = fidelity(exemplar, big, eq5=False, local=True)
    loc = rep.local
    score = np.asarray(loc["score"], float)
    seam, interior = [], []
    if score.size:
        for r in range(score.shape[0]):
            for c in range(score.shape[1]):
                v = score[r, c]
                if not np.isfinite(v):
                    continue
                wx, wy = loc["x0"] + c * loc["step"], loc["y0"] + r * loc["step"]
                sd = loc["window"]
                # a seam crosses the window's middle half: both sides of it are in view
                kx = np.arange(np.ceil((wx + sd / 4 - x0) / w), np.floor((wx + 3 * sd / 4 - x0) / w) + 1)
                ky = np.arange(np.ceil((wy + sd / 4 - y0) / h), np.floor((wy + 3 * sd / 4 - y0) / h) + 1)
                if len(kx) or len(ky):
                    seam.append(v)
                elif wx >= x0 and wx + sd <= x0 + w and wy >= y0 and wy + sd <= y0 + h:
                    interior.append(v)
    sv, iv = np.array(seam), np.array(interior)
    med_s = float(np.median(sv)) if len(sv) else float("nan")
    med_i = float(np.median(iv)) if len(iv) else float("nan")
    return {
        "seam": med_s,
        "interior": med_i,
        "ratio": _ratio(med_s, med_i),
        "seam_failing": float(np.mean(sv > 1)) if len(sv) else float("nan"),
        "interior_failing": float(np.mean(iv > 1)) if len(iv) else float("nan"),
        "seam_windows": int(len(sv)),
        "interior_windows": int(len(iv)),
        "faithful": bool(rep.faithful),
        "window": float(loc["window"]) if loc["window"] is not None else float("nan"),
    }

"""Poisson-disk sampling in any region (Bridson-style, O(n)).

Step 1 of the fill-gap method (Sakurai & Miyata §4.1) places exclusive regions at
Poisson-disk points whose circles circumscribe them; :func:`poisson_disk` is also public.

The sampler is Bridson's "fast Poisson disk sampling in arbitrary dimensions" (2007):
a background grid of cell ``r / sqrt(2)`` holds at most one sample, an active list
grows from a seed, and each active sample spawns up to ``candidates`` trial points in
the annulus ``[r, 2r]``. Random numbers come from the shared compiled stream
(:mod:`strew._kernels.prng`, xoshiro256+) seeded from the caller's
``numpy.random.Generator``, so no global random state is touched.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numba
import numpy as np
import shapely

from .._errors import InputError
from .._kernels.prng import seed_state
from .._kernels.prng import uniform as _next
from .._rng import as_rng

__all__ = ["poisson_disk"]

_NO_CONTEXT = np.zeros((0, 2), dtype=np.float64)

@numba.njit(cache=True)
def _bridson(width: float, height: float, r: float, k: int, state: np.ndarray, max_points: int, ctx: np.ndarray) -> np.ndarray:
    """Bridson sampling of the rectangle [0, width) x [0, height); (n, 2) points.

    ``ctx`` ((m, 2), rectangle coordinates, at most one point per background cell) are
    fixed points around which the set is drawn: those within two cells of the rectangle
    are obstacles (no sample within ``r`` of them) and active seeds from the start, so the
    set reaches them (a tile next to finished ones, issue 15 point 5 / 19.1); they are not
    returned. With ``m = 0`` the run starts from one random point, as Bridson's.
    """
    cell = r / np.sqrt(2.0)
    gw = max(1, int(np.ceil(width / cell)))
    gh = max(1, int(np.ceil(height / cell)))
    # sample coordinates stored in the grid itself (far-away sentinel when empty),
    # padded by two cells so that the 5x5 neighbourhood needs no bounds checks
    # np.empty and a loop, not np.full: numba compiles np.full's generic code into every
    # first run that calls this kernel (strew run; issue 16)
    gxs = np.empty((gh + 4, gw + 4), dtype=np.float64)
    gys = np.empty((gh + 4, gw + 4), dtype=np.float64)
    for yy in range(gh + 4):
        for xx in range(gw + 4):
            gxs[yy, xx] = -1e300
            gys[yy, xx] = -1e300
    cap = min(gw * gh, max_points)
    pts = np.empty((cap + ctx.shape[0], 2), dtype=np.float64)
    active = np.empty(cap + ctx.shape[0], dtype=np.int64)
    r2 = r * r
    n = 0
    for c in range(ctx.shape[0]):
        x = ctx[c, 0]
        y = ctx[c, 1]
        cx_ = int(np.floor(x / cell)) + 2
        cy_ = int(np.floor(y / cell)) + 2
        if 0 <= cx_ < gw + 4 and 0 <= cy_ < gh + 4:
            pts[n, 0] = x
            pts[n, 1] = y
            gxs[cy_, cx_] = x
            gys[cy_, cx_] = y
            active[n] = n
            n += 1
    m = n  # the fixed points kept, pts[:m]
    na = n
    cap += m
    if m == 0:
        x = _next(state) * width
        y = _next(state) * height
        pts[0, 0] = x
        pts[0, 1] = y
        gxs[min(int(y / cell), gh - 1) + 2, min(int(x / cell), gw - 1) + 2] = x
        gys[min(int(y / cell), gh - 1) + 2, min(int(x / cell), gw - 1) + 2] = y
        active[0] = 0
        n = 1
        na = 1
    scan = 0  # the next cell to look at once the front has died out
    four_r2 = 4.0 * r2
    while True:
        while na > 0 and n < cap:
            a = int(_next(state) * na)
            if a >= na:
                a = na - 1
            i = active[a]
            px = pts[i, 0]
            py = pts[i, 1]
            found = False
            for _ in range(k):
                # uniform by area in the annulus [r, 2r]
                # uniform direction by rejection from the square (no trigonometry)
                while True:
                    ux = 2.0 * _next(state) - 1.0
                    uy = 2.0 * _next(state) - 1.0
                    q = ux * ux + uy * uy
                    if 1e-12 < q <= 1.0:
                        break
                rad = np.sqrt(r2 + _next(state) * 3.0 * r2) / np.sqrt(q)
                cx = px + rad * ux
                cy = py + rad * uy
                if cx < 0.0 or cy < 0.0 or cx >= width or cy >= height:
                    continue
                gx = int(cx / cell)
                gy = int(cy / cell)
                if gx >= gw:
                    gx = gw - 1
                if gy >= gh:
                    gy = gh - 1
                ok = True
                for yy in range(gy, gy + 5):
                    for xx in range(gx, gx + 5):
                        dx = gxs[yy, xx] - cx
                        dy = gys[yy, xx] - cy
                        if dx * dx + dy * dy < r2:
                            ok = False
                            break
                    if not ok:
                        break
                if ok:
                    pts[n, 0] = cx
                    pts[n, 1] = cy
                    gxs[gy + 2, gx + 2] = cx
                    gys[gy + 2, gx + 2] = cy
                    active[na] = n
                    na += 1
                    n += 1
                    found = True
                    break
            if not found:
                na -= 1
                active[a] = active[na]
        if n >= cap:
            break
        # Bridson's front can die out before it covers the domain: in a strip narrower
        # than 2r few candidates of the annulus fall inside it, and k misses in a row end
        # the run (5 x 27 with r = 3.25 stopped at y = 11). Restart it in the next cell
        # whose centre is at least 2r from every sample; a point anywhere in that cell
        # keeps 1.5r from them. Where the front covered the domain there is no such
        # cell, and the output is what it was.
        restarted = False
        while scan < gw * gh:
            ci = scan // gw
            cj = scan - ci * gw
            scan += 1
            if gxs[ci + 2, cj + 2] > -1e299:
                continue
            lo_x = cj * cell
            hi_x = min((cj + 1) * cell, width)
            lo_y = ci * cell
            hi_y = min((ci + 1) * cell, height)
            ccx = 0.5 * (lo_x + hi_x)
            ccy = 0.5 * (lo_y + hi_y)
            far = True
            # the two padding cells too: fixed points stored there (empty: far away)
            for yy in range(max(-2, ci - 3), min(gh + 2, ci + 4)):
                for xx in range(max(-2, cj - 3), min(gw + 2, cj + 4)):
                    dx = gxs[yy + 2, xx + 2] - ccx
                    dy = gys[yy + 2, xx + 2] - ccy
                    if dx * dx + dy * dy < four_r2:
                        far = False
                        break
                if not far:
                    break
            if far:
                x = lo_x + _next(state) * (hi_x - lo_x)
                y = lo_y + _next(state) * (hi_y - lo_y)
                pts[n, 0] = x
                pts[n, 1] = y
                gxs[ci + 2, cj + 2] = x
                gys[ci + 2, cj + 2] = y
                active[0] = n
                na = 1
                n += 1
                restarted = True
                break
        if not restarted:
            break
    return pts[m:n].copy()


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _wrap_d(d: float, period: float) -> float:
    """Shortest signed difference on a circle of length ``period``, for ``|d| < period``
    (two points of the tile)."""
    if d > 0.5 * period:
        return d - period
    if d < -0.5 * period:
        return d + period
    return d


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _wrap_i(i: int, n: int) -> int:
    """``i`` modulo ``n`` for ``-n <= i < 2 n``."""
    if i >= n:
        return i - n
    if i < 0:
        return i + n
    return i


@numba.njit(cache=True)
def _bridson_torus(width: float, height: float, r: float, k: int, state: np.ndarray, max_points: int) -> np.ndarray:
    """Bridson sampling of the torus [0, width) x [0, height) (issue 18): distances and
    the background grid wrap around, so the points tile without a seam; (n, 2) points.

    The grid has a whole number of cells across each side (cells ``width / gw`` by
    ``height / gh``, each at most ``r / sqrt(2)``, so a cell holds at most one sample),
    and a candidate looks at the cells within ``r`` of it, wrapped.
    """
    cell0 = r / np.sqrt(2.0)
    gw = max(1, int(np.ceil(width / cell0)))
    gh = max(1, int(np.ceil(height / cell0)))
    cw = width / gw
    ch = height / gh
    grid = np.empty(gw * gh, dtype=np.int64)
    for i in range(gw * gh):
        grid[i] = -1
    cap = min(gw * gh, max_points)
    pts = np.empty((cap, 2), dtype=np.float64)
    active = np.empty(cap, dtype=np.int64)
    r2 = r * r
    four_r2 = 4.0 * r2
    # cells to look at on each side (all of them, once, when the torus is that narrow)
    rx = int(np.ceil(r / cw))
    ry = int(np.ceil(r / ch))
    rx2 = int(np.ceil(2.0 * r / cw)) + 1
    ry2 = int(np.ceil(2.0 * r / ch)) + 1
    # a window of 2 reach + 1 cells, or every cell once where the torus is narrower
    nx, sx = (2 * rx + 1, rx) if 2 * rx + 1 < gw else (gw, 0)
    ny, sy = (2 * ry + 1, ry) if 2 * ry + 1 < gh else (gh, 0)
    nx2, sx2 = (2 * rx2 + 1, rx2) if 2 * rx2 + 1 < gw else (gw, 0)
    ny2, sy2 = (2 * ry2 + 1, ry2) if 2 * ry2 + 1 < gh else (gh, 0)
    n = 0
    na = 0
    scan = 0
    x = _next(state) * width
    y = _next(state) * height
    while True:
        if n == 0 or na == 0:
            # the first sample, or a restart (see _bridson) at (x, y) set below
            if n >= cap:
                break
            gx = min(int(x / cw), gw - 1)
            gy = min(int(y / ch), gh - 1)
            pts[n, 0] = x
            pts[n, 1] = y
            grid[gy * gw + gx] = n
            active[0] = n
            na = 1
            n += 1
        while na > 0 and n < cap:
            a = int(_next(state) * na)
            if a >= na:
                a = na - 1
            i = active[a]
            px = pts[i, 0]
            py = pts[i, 1]
            found = False
            for _ in range(k):
                while True:
                    ux = 2.0 * _next(state) - 1.0
                    uy = 2.0 * _next(state) - 1.0
                    q = ux * ux + uy * uy
                    if 1e-12 < q <= 1.0:
                        break
                rad = np.sqrt(r2 + _next(state) * 3.0 * r2) / np.sqrt(q)
                cx = px + rad * ux
                cy = py + rad * uy
                # wrapped into the tile (the torus has no edge to reject at)
                cx -= width * np.floor(cx / width)
                cy -= height * np.floor(cy / height)
                if cx >= width:
                    cx = 0.0
                if cy >= height:
                    cy = 0.0
                gx = min(int(cx / cw), gw - 1)
                gy = min(int(cy / ch), gh - 1)
                if grid[gy * gw + gx] >= 0:
                    continue
                ok = True
                for oy in range(ny):
                    yy = _wrap_i(gy - sy + oy, gh)
                    for ox in range(nx):
                        xx = _wrap_i(gx - sx + ox, gw)
                        j = grid[yy * gw + xx]
                        if j >= 0:
                            dx = _wrap_d(pts[j, 0] - cx, width)
                            dy = _wrap_d(pts[j, 1] - cy, height)
                            if dx * dx + dy * dy < r2:
                                ok = False
                                break
                    if not ok:
                        break
                if ok:
                    pts[n, 0] = cx
                    pts[n, 1] = cy
                    grid[gy * gw + gx] = n
                    active[na] = n
                    na += 1
                    n += 1
                    found = True
                    break
            if not found:
                na -= 1
                active[a] = active[na]
        if n >= cap:
            break
        # restart the front in the next empty cell whose centre is at least 2r from every
        # sample (as _bridson); none: the torus is covered
        restarted = False
        while scan < gw * gh:
            ci = scan // gw
            cj = scan - ci * gw
            scan += 1
            if grid[scan - 1] >= 0:
                continue
            ccx = (cj + 0.5) * cw
            ccy = (ci + 0.5) * ch
            far = True
            for oy in range(ny2):
                yy = _wrap_i(ci - sy2 + oy, gh)
                for ox in range(nx2):
                    xx = _wrap_i(cj - sx2 + ox, gw)
                    j = grid[yy * gw + xx]
                    if j >= 0:
                        dx = _wrap_d(pts[j, 0] - ccx, width)
                        dy = _wrap_d(pts[j, 1] - ccy, height)
                        if dx * dx + dy * dy < four_r2:
                            far = False
                            break
                if not far:
                    break
            if far:
                x = (cj + _next(state)) * cw
                y = (ci + _next(state)) * ch
                restarted = True
                break
        if not restarted:
            break
    return pts[:n].copy()


@numba.njit(cache=True)
def _bridson_variable(
    width: float, height: float, rmap: np.ndarray, mcell: float, rmin: float, rmax: float, k: int, state: np.ndarray, max_points: int
) -> np.ndarray:
    """Bridson sampling with a radius map: points p, q keep ``|p - q| >= max(r(p), r(q))``."""
    mh, mw = rmap.shape
    cell = rmin / np.sqrt(2.0)  # every pair is at least rmin apart: one point per cell
    gw = max(1, int(np.ceil(width / cell)))
    gh = max(1, int(np.ceil(height / cell)))
    reach = int(np.ceil(rmax / cell))
    grid = np.empty((gh, gw), dtype=np.int64)  # np.empty and a loop: see _bridson
    for yy in range(gh):
        for xx in range(gw):
            grid[yy, xx] = -1
    cap = min(gw * gh, max_points)
    pts = np.empty((cap, 2), dtype=np.float64)
    rad = np.empty(cap, dtype=np.float64)
    active = np.empty(cap, dtype=np.int64)
    x = _next(state) * width
    y = _next(state) * height
    pts[0, 0] = x
    pts[0, 1] = y
    rad[0] = rmap[min(int(y / mcell), mh - 1), min(int(x / mcell), mw - 1)]
    grid[min(int(y / cell), gh - 1), min(int(x / cell), gw - 1)] = 0
    active[0] = 0
    n = 1
    na = 1
    while na > 0 and n < cap:
        a = min(int(_next(state) * na), na - 1)
        i = active[a]
        r = rad[i]
        found = False
        for _ in range(k):
            while True:
                ux = 2.0 * _next(state) - 1.0
                uy = 2.0 * _next(state) - 1.0
                q = ux * ux + uy * uy
                if 1e-12 < q <= 1.0:
                    break
            t = np.sqrt(1.0 + 3.0 * _next(state)) / np.sqrt(q)
            cx = pts[i, 0] + t * r * ux
            cy = pts[i, 1] + t * r * uy
            if cx < 0.0 or cy < 0.0 or cx >= width or cy >= height:
                continue
            rc = rmap[min(int(cy / mcell), mh - 1), min(int(cx / mcell), mw - 1)]
            if rc > r:
                # the annulus of the larger radius, so that growth crosses from small
                # radii into large ones
                cx = pts[i, 0] + t * rc * ux
                cy = pts[i, 1] + t * rc * uy
                if cx < 0.0 or cy < 0.0 or cx >= width or cy >= height:
                    continue
                rc = rmap[min(int(cy / mcell), mh - 1), min(int(cx / mcell), mw - 1)]
            gx = min(int(cx / cell), gw - 1)
            gy = min(int(cy / cell), gh - 1)
            ok = True
            for yy in range(max(gy - reach, 0), min(gy + reach + 1, gh)):
                for xx in range(max(gx - reach, 0), min(gx + reach + 1, gw)):
                    j = grid[yy, xx]
                    if j >= 0:
                        dx = pts[j, 0] - cx
                        dy = pts[j, 1] - cy
                        need = max(rc, rad[j])
                        if dx * dx + dy * dy < need * need:
                            ok = False
                            break
                if not ok:
                    break
            if ok:
                pts[n, 0] = cx
                pts[n, 1] = cy
                rad[n] = rc
                grid[gy, gx] = n
                active[na] = n
                na += 1
                n += 1
                found = True
                break
        if not found:
            na -= 1
            active[a] = active[na]
    return pts[:n].copy()


def _as_geometry(region: Any) -> shapely.Geometry | tuple[float, float, float, float]:
    """A polygonal geometry, or the bounds of a rectangle given as (W, H)."""
    from ..region import Region

    if isinstance(region, Region):
        return region.geometry
    if isinstance(region, (shapely.Polygon, shapely.MultiPolygon)):
        return region
    if isinstance(region, (tuple, list)) and len(region) == 2:
        w, h = float(region[0]), float(region[1])
        if not (np.isfinite(w) and np.isfinite(h) and w > 0 and h > 0):
            raise InputError(f"region: width and height must be positive, got {w} x {h}")
        return (0.0, 0.0, w, h)
    if isinstance(region, (tuple, list)) and len(region) == 4:
        x0, y0, x1, y1 = (float(v) for v in region)
        if not (np.all(np.isfinite([x0, y0, x1, y1])) and x1 > x0 and y1 > y0):
            raise InputError(f"region: bounds (x0, y0, x1, y1) must have x1 > x0 and y1 > y0, got {tuple(region)}")
        return (x0, y0, x1, y1)
    raise InputError(f"region: expected a Region, a shapely polygon, (W, H) or (x0, y0, x1, y1), got {type(region).__name__}")


def _context_cells(context: Any, x0: float, y0: float, w: float, h: float, radius: float) -> np.ndarray:
    """The points of ``context`` that :func:`_bridson` keeps (within its two padding cells
    of the rectangle), in rectangle coordinates, C-contiguous (m, 2); refuses two in one
    background cell (closer than ``radius``: the grid holds one point a cell)."""
    try:
        ctx = np.asarray(context, dtype=np.float64).reshape(-1, 2)
    except (TypeError, ValueError):
        raise InputError(f"context: expected (m, 2) points, got {np.shape(context)}") from None
    if not np.all(np.isfinite(ctx)):
        raise InputError("context: points must be finite")
    rel = ctx - np.array([x0, y0])
    cell = radius / np.sqrt(2.0)  # as _bridson's
    gw = max(1, int(np.ceil(w / cell)))
    gh = max(1, int(np.ceil(h / cell)))
    ij = np.floor(rel / cell) + 2  # the padded grid's cells, as _bridson computes them
    near = (ij[:, 0] >= 0) & (ij[:, 0] < gw + 4) & (ij[:, 1] >= 0) & (ij[:, 1] < gh + 4)
    rel, ij = rel[near], ij[near].astype(np.int64)
    flat = ij[:, 1] * (gw + 4) + ij[:, 0]
    if len(np.unique(flat)) < len(flat):
        raise InputError(f"context: two points are closer than the radius {radius:g} (context must be a Poisson-disk set of that radius)")
    return np.ascontiguousarray(rel)


def poisson_disk(
    region: Any,
    radius: float | Callable[[np.ndarray], np.ndarray],
    *,
    candidates: int = 30,
    max_points: int = 50_000_000,
    rng: int | np.random.Generator | None = None,
    periodic: bool = False,
    context: np.ndarray | None = None,
) -> np.ndarray:
    """Poisson-disk points in a region: no two closer than ``radius``.

    Bridson's O(n) dart throwing with a background grid. Arbitrary regions (holes,
    several parts) are sampled by covering their bounding box and keeping the points
    inside, so the result is maximal up to the boundary.

    Parameters
    ----------
    region : Region, shapely (Multi)Polygon, (W, H) or (x0, y0, x1, y1)
        ``(W, H)`` means the rectangle ``[0, W) x [0, H)``, ``(x0, y0, x1, y1)`` the
        half-open rectangle ``[x0, x1) x [y0, y1)``.
    radius : float or callable
        Minimum distance between two points (as ``scipy.stats.qmc.PoissonDisk``'s
        ``radius``). A callable ``radius(points) -> radii`` (``(m, 2)`` to ``(m,)``,
        positive) gives a variable radius: it is sampled at the cell centres of a map
        of 512 cells across the bounding box's longer side, and points ``p, q`` keep
        ``|p - q| >= max(r(p), r(q))`` with ``r`` read from that map.
    candidates : int
        Trial points per active sample (Bridson's ``k``).
    max_points : int
        Safety cap on the number of points generated in the bounding box.
    rng : int, Generator or None
    periodic : bool
        Sample the torus of a rectangular region (issue 18): distances wrap around its
        edges, so that copies of the points laid side by side keep ``radius`` apart
        across the seams too. Needs a constant ``radius``.
    context : (m, 2) float, optional
        Fixed points to sample around (a Poisson-disk set of the same ``radius``: no two
        closer than it): no returned point comes within ``radius`` of one, and those
        near the bounding box also seed the dart throwing, so the set reaches them
        without a gap. A tile sampled around its finished neighbours' points this way
        joins them into one Poisson-disk set (program's tiled worlds, issue 19.1). They
        are not returned. Needs a constant ``radius`` and ``periodic=False``; without
        context the run starts from one random point (Bridson's), with it from the
        context points.

    Returns
    -------
    (n, 2) float ndarray
        Points in generation order.

    Examples
    --------
    >>> pts = poisson_disk((1.0, 1.0), 0.1, rng=0)
    >>> from scipy.spatial.distance import pdist
    >>> bool(pdist(pts).min() >= 0.1)
    True
    >>> right = poisson_disk((1.0, 0.0, 2.0, 1.0), 0.1, rng=1, context=pts)
    >>> bool(pdist(np.r_[pts, right]).min() >= 0.1)
    True
    """
    if not callable(radius):
        try:
            radius = float(radius)
        except (TypeError, ValueError):
            raise InputError(f"radius: must be a number or a callable, got {radius!r}") from None
        if not (np.isfinite(radius) and radius > 0):
            raise InputError(f"radius: must be positive and finite, got {radius}")
    if int(candidates) < 1:
        raise InputError(f"candidates: must be at least 1, got {candidates}")
    gen = as_rng(rng)
    geom = _as_geometry(region)
    if context is not None and (periodic or callable(radius)):
        raise InputError("context: needs a constant radius and periodic=False")
    if periodic:
        from .._periodic import frame_of_region

        if callable(radius):
            raise InputError("radius: periodic sampling needs a constant radius, not a callable")
        if isinstance(geom, tuple):
            x0, y0, w, h = geom[0], geom[1], geom[2] - geom[0], geom[3] - geom[1]
        else:
            x0, y0, w, h = frame_of_region(geom)
        if w * h / (radius * radius) > 4 * max_points:
            raise InputError(f"radius: {radius} is too small for a region of {w:g} x {h:g} (over {max_points} points)")
        state = seed_state(gen)
        pts = _bridson_torus(float(w), float(h), radius, int(candidates), state, int(max_points))
        pts[:, 0] += x0
        pts[:, 1] += y0
        return pts
    if isinstance(geom, tuple):
        x0, y0, x1, y1 = geom
        poly = None
    else:
        if geom.is_empty or geom.area <= 0:
            return np.zeros((0, 2))
        x0, y0, x1, y1 = (float(v) for v in geom.bounds)
        poly = geom
    w, h = x1 - x0, y1 - y0
    rmap = None
    if callable(radius):
        mcell = max(w, h) / 512
        mw, mh = max(1, int(np.ceil(w / mcell))), max(1, int(np.ceil(h / mcell)))
        gx, gy = np.meshgrid(x0 + (np.arange(mw) + 0.5) * mcell, y0 + (np.arange(mh) + 0.5) * mcell)
        rmap = np.asarray(radius(np.c_[gx.ravel(), gy.ravel()]), dtype=float)
        if rmap.shape != (mw * mh,):
            raise InputError(f"radius: the callable must return one radius per point, got shape {rmap.shape}")
        if not (np.all(np.isfinite(rmap)) and np.all(rmap > 0)):
            raise InputError("radius: the callable must return positive, finite radii")
        rmap = rmap.reshape(mh, mw)
        rmin = float(rmap.min())
    else:
        rmin = radius
    cells = (w / rmin * np.sqrt(2) + 1) * (h / rmin * np.sqrt(2) + 1)
    if cells > 4 * max_points:
        raise InputError(f"radius: {rmin} is too small for a region of {w:g} x {h:g} (over {max_points} points)")
    if rmap is None:
        ctx = _NO_CONTEXT if context is None else _context_cells(context, x0, y0, w, h, radius)
        state = seed_state(gen)
        pts = _bridson(float(w), float(h), radius, int(candidates), state, int(max_points), ctx)
    else:
        state = seed_state(gen)
        pts = _bridson_variable(float(w), float(h), rmap, float(mcell), rmin, float(rmap.max()), int(candidates), state, int(max_points))
    pts[:, 0] += x0
    pts[:, 1] += y0
    if poly is not None:
        pts = pts[shapely.contains_xy(poly, pts[:, 0], pts[:, 1])]
    elif x0 != 0.0 or y0 != 0.0:
        # x0 + (a coordinate below x1 - x0) can round up to x1: keep the rectangle half-open
        pts = pts[(pts[:, 0] < x1) & (pts[:, 1] < y1)]
    return pts

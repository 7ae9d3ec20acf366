"""The distance field of the fill-gap method (Sakurai & Miyata §4.2).

A raster over the domain holds, for each free pixel, the distance to the nearest placed
exclusive region or to the domain boundary. Candidate points Q are drawn pixel by pixel
with probability ``alpha = d**n`` of the normalised distance ``d`` (n = 16 in the
paper), and P of them are chosen as placement candidates. The field is built once
with an exact Euclidean distance transform and then updated locally: after a placement,
only a window around the new region, grown by the current largest distance, is
recomputed (distances only shrink, so pixels farther away cannot change).

The paper computes the field on the GPU over an image plane; here the whole pipeline
runs on the CPU with numpy/scipy. The raster only proposes candidates: every placement
is then tested exactly on the polygons.
"""

from __future__ import annotations

import numba
import numpy as np
import shapely

from .._kernels.geometry import seg_dist2
from .._kernels.geometry import seg_dist2_min as _seg_dist2
from .._kernels.raster import edt as _edt
from .._kernels.raster import edt_torus as _edt_torus
from .._kernels.raster import row_crossings as _row_crossings
from .._kernels.raster import scan_fill as _scan_fill
from ..region import Region

__all__ = ["DistanceField"]


class DistanceField:
    """Distance to placed exclusive regions and to the domain boundary, on a raster.

    Parameters
    ----------
    region : Region
    cell : float
        Pixel side, in document units.
    placed : list of shapely geometries, optional
        Exclusive regions already placed.
    segments : ((s, 4) float, (k + 1,) int), optional
        Exclusive regions already placed, as ring edges ``x0, y0, x1, y1`` and the
        offsets of each region's edges (e.g. :meth:`._fit.FitEngine.segments`).

    Attributes
    ----------
    d : (rows, cols) float
        Distance of each pixel centre to the nearest obstacle, in document units
        (0 outside the domain and inside placed regions).
    """

    def __init__(self, region: Region, cell: float, placed: list | None = None,
                 segments: tuple[np.ndarray, np.ndarray] | None = None, periodic: tuple | None = None) -> None:
        if periodic is not None:
            self._init_torus(cell, segments, periodic)
            return
        # The same grid as Region.rasterize (pixel centres at x0 + (c + 0.5) * cell), but
        # filled by even-odd scanlines over the domain's rings and then cleared inside
        # the regions placed so far (Step 1), and one exact Euclidean distance transform
        # (Felzenszwalb & Huttenlocher), all compiled: no per-pixel shapely test (the shared
        # kernels of strew._kernels.raster; why this EDT and not scipy's: see there).
        x0, y0, x1, y1 = region.bounds
        cell = float(cell)
        self.x0, self.y0, self.cell = float(x0), float(y0), cell
        self.cols = max(1, int(np.ceil((x1 - x0) / cell)))
        self.rows = max(1, int(np.ceil((y1 - y0) / cell)))
        free = np.zeros((self.rows, self.cols), dtype=np.bool_)
        segs, offsets = _segments([region.geometry])
        _scan_fill(free, self.x0, self.y0, cell, segs, offsets, True)
        placed = [g for g in (placed or []) if not g.is_empty]
        if placed:
            # pixels whose centres lie inside the regions placed so far are obstacles too
            segs, offsets = _segments(placed)
            _scan_fill(free, self.x0, self.y0, cell, segs, offsets, False)
        if segments is not None and len(segments[0]):
            _scan_fill(free, self.x0, self.y0, cell, segments[0], segments[1], False)
        # distance of each free pixel centre to the nearest obstacle pixel centre, with
        # the pixels just outside the raster as obstacles (the box edge is boundary)
        self.d = _edt(free) * cell
        self.dmax = float(self.d.max()) if self.d.size else 0.0
        self.cell_y = cell

    def _init_torus(self, cell: float, segments: tuple[np.ndarray, np.ndarray] | None, tile: tuple) -> None:
        """The field on the torus of a repeat tile ``(x0, y0, W, H)`` (issue 18).

        The raster has a whole number of pixels across each side, so that it wraps
        exactly: pixels ``W / cols`` by ``H / rows``, each side at most ``cell``. Placed
        regions are marked with their wrapped images, and the distance transform runs on
        the mask padded by its own wrapped rows and columns
        (:func:`strew._kernels.raster.edt_torus`): the
        wrapped distances to the obstacle pixel centres (at least the true distances,
        as in the plane).
        """
        x0, y0, w, h = (float(v) for v in tile)
        cell = float(cell)
        self.x0, self.y0 = x0, y0
        self.cols = max(1, int(np.ceil(w / cell)))
        self.rows = max(1, int(np.ceil(h / cell)))
        self.cell = w / self.cols
        self.cell_y = h / self.rows
        free = np.ones((self.rows, self.cols), dtype=np.bool_)
        if segments is not None and len(segments[0]):
            segs, offsets = segments
            # the scanline fill works on square pixels: scale y by cell / cell_y, which
            # keeps every even-odd decision
            sy = self.cell / self.cell_y
            for i in (-1, 0, 1):
                for j in (-1, 0, 1):
                    t = np.asarray(segs, dtype=float) + [i * w, j * h, i * w, j * h]
                    t[:, [1, 3]] = y0 + (t[:, [1, 3]] - y0) * sy
                    _scan_fill(free, x0, y0, self.cell, np.ascontiguousarray(t), offsets, False)
        if free.all():
            # nothing placed: no obstacle anywhere; a distance larger than any element
            self.d = np.full(free.shape, float(w + h))
        else:
            self.d = _edt_torus(free, self.cell, self.cell_y)
        self.dmax = float(self.d.max()) if self.d.size else 0.0

    def occupy(self, geoms: np.ndarray | list) -> None:
        """Mark placed exclusive regions as obstacles and update the field locally.

        Distances only shrink and no pixel holds more than the current largest distance
        ``dmax``, so only pixels within ``dmax`` of a new region's bounding box can
        change; for those, the exact distance to the region's polygon (0 inside) is
        computed and the field keeps the minimum.

        Parameters
        ----------
        geoms : (k,) shapely geometries
        """
        geoms = [g for g in geoms if not g.is_empty]
        if not geoms:
            return
        segs, offsets = _segments(geoms)
        bounds = shapely.bounds(np.asarray(geoms, dtype=object)).reshape(-1, 4)
        _occupy(self.d, self.x0, self.y0, self.cell, segs, offsets, bounds, self.dmax + self.cell)

    def sample(self, count: int, power: float, rng: np.random.Generator) -> np.ndarray:
        """Candidate points P drawn from the normalised field (§4.2).

        Each free pixel yields a point of Q with probability ``(d / max d) ** power``;
        ``count`` points of Q are then chosen at random, each jittered uniformly within
        its pixel.

        Returns
        -------
        (m, 2) float, m <= count (0 when no free pixel remains)
        """
        flat = self.d.ravel()
        self.dmax = float(flat.max()) if flat.size else 0.0
        if self.dmax <= 0:
            return np.zeros((0, 2))
        # Pixels whose probability is below 1e-9 are skipped without a draw: over a
        # million pixels they would add one point in a thousand rounds.
        idx = np.flatnonzero(flat > self.dmax * 1e-9 ** (1.0 / power))
        alpha = flat[idx] / self.dmax
        if power == 16:  # four products instead of a general power
            for _ in range(4):
                alpha *= alpha
        else:
            alpha **= power
        q = idx[rng.random(len(idx)) < alpha]
        if len(q) == 0:
            return np.zeros((0, 2))
        if len(q) > count:
            q = rng.choice(q, size=count, replace=False)
        else:
            q = q[rng.permutation(len(q))]
        r, c = np.divmod(q, self.cols)
        jitter = rng.random((len(q), 2))
        return np.c_[self.x0 + (c + jitter[:, 0]) * self.cell, self.y0 + (r + jitter[:, 1]) * self.cell]


def _segments(geoms: list) -> tuple[np.ndarray, np.ndarray]:
    """All ring edges of the geometries: (s, 4) ``x0, y0, x1, y1`` and (k + 1,) offsets."""
    parts, part_owner = shapely.get_parts(np.asarray(geoms, dtype=object), return_index=True)
    ring_geoms, ring_part = shapely.get_rings(parts, return_index=True)
    owner = part_owner[ring_part]
    coords, ring_idx = shapely.get_coordinates(ring_geoms, return_index=True)
    same = ring_idx[1:] == ring_idx[:-1]  # consecutive vertices of one ring form an edge
    starts = np.flatnonzero(same)
    segs = np.c_[coords[starts], coords[starts + 1]]
    seg_owner = owner[ring_idx[starts]]
    offsets = np.searchsorted(seg_owner, np.arange(len(geoms) + 1))
    return np.ascontiguousarray(segs), offsets.astype(np.int64)


@numba.njit(cache=True)
def _occupy(d, x0, y0, cell, segs, offsets, bounds, grow):  # pragma: no cover - numba
    """Mark the regions ``segs[offsets[g]:offsets[g + 1]]`` (boxes ``bounds``) as
    obstacles in ``d``: 0 at the pixel centres inside, the smaller of the current value
    and the exact distance to the edges elsewhere, within ``grow`` of each box.

    Inside-ness comes from each row's sorted crossings (the shared scanline's
    :func:`strew._kernels.raster.row_crossings`, found once a row and only for rows that
    reach the test), not from a crossing test per pixel and edge."""
    rows, cols = d.shape
    xs = np.empty(max(len(segs), 1))
    for g in range(len(offsets) - 1):
        s0, s1 = offsets[g], offsets[g + 1]
        ylo = np.inf
        yhi = -np.inf
        for s in range(s0, s1):
            ylo = min(ylo, segs[s, 1], segs[s, 3])
            yhi = max(yhi, segs[s, 1], segs[s, 3])
        c0 = max(int(np.floor((bounds[g, 0] - grow - x0) / cell)), 0)
        r0 = max(int(np.floor((bounds[g, 1] - grow - y0) / cell)), 0)
        c1 = min(int(np.ceil((bounds[g, 2] + grow - x0) / cell)) + 1, cols)
        r1 = min(int(np.ceil((bounds[g, 3] + grow - y0) / cell)) + 1, rows)
        for r in range(r0, r1):
            py = y0 + (r + 0.5) * cell
            m = -1  # crossings not found yet (0 outside the edges' y range)
            if py < ylo or py >= yhi:
                m = 0
            j = 0
            for c in range(c0, c1):
                cur = d[r, c]
                if cur <= 0.0:
                    continue
                px = x0 + (c + 0.5) * cell
                # the polygon is no nearer than its bounding box: skip pixels that
                # already hold a smaller distance (most of the window)
                bx = max(bounds[g, 0] - px, 0.0, px - bounds[g, 2])
                by = max(bounds[g, 1] - py, 0.0, py - bounds[g, 3])
                if bx * bx + by * by >= cur * cur:
                    continue
                if m < 0:
                    m = _row_crossings(segs, s0, s1, py, xs)
                while j < m and xs[j] <= px:  # px grows along the row
                    j += 1
                if (m - j) & 1:  # an odd number of crossings right of px: inside
                    d[r, c] = 0.0
                    continue
                best = cur * cur
                for s in range(s0, s1):
                    dd = seg_dist2(px, py, segs[s, 0], segs[s, 1], segs[s, 2], segs[s, 3])
                    if dd < best:
                        best = dd
                if best < cur * cur:
                    d[r, c] = np.sqrt(best)


@numba.njit(cache=True)
def _occupy_posed(d, x0, y0, cell, cell_y, segs, bounds, grow, tx, ty, c, sn, lbb):  # pragma: no cover - numba
    """:func:`_occupy` for one region placed with a known pose (pixels ``cell`` by
    ``cell_y``, equal but on a repeat tile's torus): its rings are a kind's
    rings ``p`` in local coordinates mapped to ``(tx, ty) + (c, -sn; sn, c) p`` (``c = s
    cos t``, ``sn = s sin t``), whose local bounding box is ``lbb``.

    Besides the world bounding box, a pixel is skipped when its distance to the posed
    (oriented) local box is at least its current value: the region lies in that box,
    so it is no nearer. For rotated elongated regions this skips most of the window.
    Skipping is safe in any case: a value left as it was is still at least the true
    distance. Inside tests use each row's crossings (the same even-odd rule), so the
    distance loop over the edges has no branches.
    """
    rows, cols = d.shape
    ns = len(segs)
    # explicit loops, not array expressions or column slices, and ``x * x``, not
    # ``x ** 2``: the same values, but numba compiles the latter into extra ufunc and
    # power kernels, seconds of a first run (issue 16)
    ax = np.empty(ns)
    ay = np.empty(ns)
    ex = np.empty(ns)
    ey = np.empty(ns)
    il2 = np.empty(ns)
    for k in range(ns):
        ax[k] = segs[k, 0]
        ay[k] = segs[k, 1]
        ex[k] = segs[k, 2] - segs[k, 0]
        ey[k] = segs[k, 3] - segs[k, 1]
        l2 = ex[k] * ex[k] + ey[k] * ey[k]
        il2[k] = 1.0 / l2 if l2 > 0.0 else 0.0
    xs = np.empty(max(ns, 1))
    ylo = np.inf
    yhi = -np.inf
    for k in range(ns):
        ylo = min(ylo, segs[k, 1], segs[k, 3])
        yhi = max(yhi, segs[k, 1], segs[k, 3])
    s2 = c * c + sn * sn
    c0 = max(int(np.floor((bounds[0] - grow - x0) / cell)), 0)
    r0 = max(int(np.floor((bounds[1] - grow - y0) / cell_y)), 0)
    c1 = min(int(np.ceil((bounds[2] + grow - x0) / cell)) + 1, cols)
    r1 = min(int(np.ceil((bounds[3] + grow - y0) / cell_y)) + 1, rows)
    for r in range(r0, r1):
        py = y0 + (r + 0.5) * cell_y
        # the row's sorted crossings (the shared scanline's, half-open in y), found when a
        # pixel of the row first reaches the inside test; none outside the edges' y range
        m = -1
        if py < ylo or py >= yhi:
            m = 0
        j = 0
        for cc in range(c0, c1):
            cur = d[r, cc]
            if cur <= 0.0:
                continue
            px = x0 + (cc + 0.5) * cell
            bx = max(bounds[0] - px, 0.0, px - bounds[2])
            by = max(bounds[1] - py, 0.0, py - bounds[3])
            if bx * bx + by * by >= cur * cur:
                continue
            # the oriented box: local coordinates times s (a distance in world units)
            vx = px - tx
            vy = py - ty
            lx = (c * vx + sn * vy) / s2
            ly = (c * vy - sn * vx) / s2
            ox = max(lbb[0] - lx, 0.0, lx - lbb[2])
            oy = max(lbb[1] - ly, 0.0, ly - lbb[3])
            if (ox * ox + oy * oy) * s2 >= cur * cur:
                continue
            if m < 0:
                m = _row_crossings(segs, 0, ns, py, xs)
            while j < m and xs[j] <= px:  # px grows along the row
                j += 1
            if (m - j) & 1:  # an odd number of crossings right of px: inside
                d[r, cc] = 0.0
                continue
            best = _seg_dist2(px, py, ax, ay, ex, ey, il2, cur * cur)
            if best < cur * cur:
                d[r, cc] = np.sqrt(best)

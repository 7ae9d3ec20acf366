"""The growth framework: repeatedly grow into the largest empty circle (Wong et al. 1998, §4.1).

Pseudocode of §4.1, as implemented by :class:`_Grower`::

    initialize element tree with seed points
    render boundary elements into buffer
    compute initial MAT
    initialize empty exclude list
    repeat
        C <- FindEmptyCircle()
        find elements within delta of C
        try elements in order of distance from C
            try rules in order specified in rule file
            if rule succeeds, break
        if some rule succeeded
            update element tree; render new elements into buffer
            incrementally update MAT
            remove points on exclude list within epsilon of C
        else
            add center of empty circle to exclude list

The raster buffer and distance fields live in :mod:`._raster`. The circle found on the
raster is then measured exactly against the proxies (shapely / analytic circles), and
all intersection and containment tests that rules ask for are exact.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import shapely
from scipy import ndimage

from .._errors import InputError
from .._kernels.grid import HashGrid
from .._progress import Reporter
from .._rng import as_rng
from ..region import Region
from ._pattern import Element, Pattern, load_pattern
from ._proxies import Circle, Point, Polygon, Proxy, vec
from ._raster import (
    BLOCK as _BLOCK,
    climb,
    cover_disc,
    cover_polygon,
    cover_polyline,
    lower_wave,
    mark_excluded,
    mark_near,
    mark_rect,
    scan_blocks,
    segments_distance,
    tree_build,
)

__all__ = ["Goal", "RuleContext", "Ornament", "grow_elements", "default_seed"]


@dataclass(frozen=True)
class Goal:
    """The empty circle C that a rule grows into (``$goal``).

    Attributes
    ----------
    center : (2,) float
    radius : float
    """

    center: np.ndarray
    radius: float


class _Image:
    """A proxy translated by a whole number of tile periods (issue 18: periodic growth).

    Stands in :class:`_Placed` for the wrapped copies of an element near the tile's
    edges: it answers ``geometry``, ``polyline``, ``closed`` and ``bounding_circle`` as
    the translated proxy would.
    """

    __slots__ = ("base", "dx", "dy", "_geom")

    def __init__(self, base: Proxy, dx: float, dy: float) -> None:
        self.base, self.dx, self.dy = base, float(dx), float(dy)
        self._geom = None

    @property
    def geometry(self) -> shapely.Geometry:
        if self._geom is None:
            d = np.array([self.dx, self.dy])
            self._geom = shapely.transform(self.base.geometry, lambda p: p + d)
        return self._geom

    def polyline(self) -> np.ndarray:
        return self.base.polyline() + np.array([self.dx, self.dy])

    @property
    def closed(self) -> bool:
        return self.base.closed

    def bounding_circle(self) -> tuple[float, float, float]:
        cx, cy, r = self.base.bounding_circle()
        return cx + self.dx, cy + self.dy, r


class _Placed:
    """Placed proxies: bounding circles in growable arrays, exact geometry on demand."""

    def __init__(self, bucket: float = 8.0, bounds: tuple[float, float, float, float] | None = None) -> None:
        self.n = 0
        # a uniform grid over bounding boxes answers small queries without a scan: the
        # shared hashed incremental grid (strew._kernels.grid, issue 15 point 5), whose
        # cells are unbounded, so proxies beyond ``bounds`` (wrapped images) cost nothing
        # more; ``bounds`` only sizes its table (a chain per cell of them, at most 2^16)
        self.bucket = float(bucket)
        cells = 1024
        if bounds is not None:
            x0, y0, x1, y1 = (float(v) for v in bounds)
            cells = min(max(int((x1 - x0) / self.bucket + 1) * int((y1 - y0) / self.bucket + 1), 1024), 1 << 16)
        self.grid = HashGrid(self.bucket, table=1 << (cells - 1).bit_length())
        cap = 256
        self.bx = np.empty(cap)
        self.by = np.empty(cap)
        self.br = np.empty(cap)
        self.round = np.empty(cap, bool)  # point or circle: exact analytic tests
        self.owner = np.empty(cap, np.int64)
        self.ox = np.empty(cap)  # the image's translation (periodic growth), 0 for the proxy itself
        self.oy = np.empty(cap)
        self.proxies: list[Any] = []

    def add(self, proxy: Proxy, owner: int, dx: float = 0.0, dy: float = 0.0) -> None:
        rnd = isinstance(proxy, (Circle, Point))
        if dx != 0.0 or dy != 0.0:
            proxy = _Image(proxy, dx, dy)  # type: ignore[assignment]
        if self.n == len(self.bx):
            for name in ("bx", "by", "br", "round", "owner", "ox", "oy"):
                a = getattr(self, name)
                b = np.empty(2 * len(a), a.dtype)
                b[: self.n] = a
                setattr(self, name, b)
        cx, cy, r = proxy.bounding_circle()
        i = self.n
        self.bx[i], self.by[i], self.br[i] = cx, cy, r
        self.round[i] = rnd
        self.owner[i] = owner
        self.ox[i], self.oy[i] = dx, dy
        self.proxies.append(proxy)
        self.n += 1
        self.grid.insert(i, cx - r, cy - r, cx + r, cy + r)

    def segments(self, i: int) -> np.ndarray:
        """(m, 4) outline segments of proxy ``i`` (closed outlines include the closing edge)."""
        pr = self.proxies[i]
        pts = pr.polyline()
        if pr.closed:
            pts = np.vstack([pts, pts[:1]])
        if len(pts) == 1:
            pts = np.vstack([pts, pts])
        return np.c_[pts[:-1], pts[1:]]

    def near(self, cx: float, cy: float, reach: float) -> np.ndarray:
        """Indices of proxies whose bounding circle comes within ``reach`` of ``(cx, cy)``."""
        n = self.n
        b = self.bucket
        i0, i1 = int(math.floor((cx - reach) / b)), int(math.floor((cx + reach) / b))
        j0, j1 = int(math.floor((cy - reach) / b)), int(math.floor((cy + reach) / b))
        # the buckets cost about 64 times what one proxy of a vectorised scan costs: use
        # them when they cover fewer cells than that fraction of the proxies (issue 19.6:
        # a scan of every proxy made each query linear in the number placed). Both give
        # the same sorted indices.
        if (i1 - i0 + 1) * (j1 - j0 + 1) * 64 <= n:
            found = self.grid.query(cx - reach, cy - reach, cx + reach, cy + reach)
            if not len(found):
                return np.zeros(0, np.int64)
            idx = np.sort(found)
            dx = self.bx[idx] - cx
            dy = self.by[idx] - cy
            lim = self.br[idx] + reach
            return idx[dx * dx + dy * dy <= lim * lim]
        dx = self.bx[:n] - cx
        dy = self.by[:n] - cy
        lim = self.br[:n] + reach
        return np.flatnonzero(dx * dx + dy * dy <= lim * lim)

    def distances(self, idx: np.ndarray, cx: float, cy: float) -> np.ndarray:
        """Exact distances from ``(cx, cy)`` to proxies ``idx`` (0 inside a circle)."""
        d = np.hypot(self.bx[idx] - cx, self.by[idx] - cy) - self.br[idx]
        other = ~self.round[idx]
        if other.any():
            geoms = [self.proxies[i].geometry for i in idx[other]]
            d[other] = shapely.distance(np.asarray(geoms, dtype=object), shapely.Point(cx, cy))
        return np.maximum(d, 0.0)


def _proxies_of(item: Any) -> list[Proxy]:
    if isinstance(item, Proxy):
        return [item]
    if isinstance(item, Element):
        return list(item.proxies)
    if isinstance(item, (list, tuple)):
        out: list[Proxy] = []
        for x in item:
            out.extend(_proxies_of(x))
        return out
    raise InputError(f"expected an element, a proxy or a list of them, got {type(item).__name__}")


class RuleContext:
    """What a rule body sees besides its parent and children (§4.2).

    Attributes
    ----------
    goal : Goal
        The empty circle C (``$goal``).
    state : SimpleNamespace
        The pattern's global state for this run (``state.phase`` is the current phase).
    rng : numpy.random.Generator
        The run's random generator; use it for every random choice.
    region : Region
        The panel.
    elements : list of Element
        The placed elements, in placement order (read only).
    """

    def __init__(self, grower: _Grower, goal: Goal, parent: Element) -> None:
        self._g = grower
        self.goal = goal
        self.parent = parent
        self.state = grower.state
        self.rng = grower.rng
        self.region = grower.region
        self.elements = grower.elements
        self.dynamic: list[Element] = []

    def new_child(self, type_name: str, **fields: Any) -> Element:
        """Create a dynamic child of ``type_name`` (the paper's ``new`` plus ``new_child``)."""
        et = self._g.pattern.types.get(type_name)
        if et is None:
            raise InputError(f"new_child: unknown element type {type_name!r} (declared: {', '.join(self._g.pattern.types)})")
        el = Element(et)
        for k, v in fields.items():
            setattr(el, k, v)
        self.dynamic.append(el)
        return el

    def intersects(self, item: Any, *, ignore: Iterable[Element] = ()) -> bool:
        """Whether ``item`` (element, proxy or list) overlaps a placed element, exactly.

        Touching does not count for circles (a dot tangent to its parent is fine); lines
        and polygons use shapely's ``intersects``. Elements in ``ignore`` are skipped.
        """
        return self._g.intersects(_proxies_of(item), {e.index for e in ignore})

    def inside(self, item: Any) -> bool:
        """Whether ``item`` lies wholly inside the region (exact)."""
        return self._g.inside(_proxies_of(item))

    def hits_boundary(self, item: Any) -> bool:
        """Whether ``item`` crosses the region boundary or lies outside."""
        return not self.inside(item)

    def boundary_distance(self, point: Any) -> float:
        """Distance from ``point`` to the region boundary: positive inside, negative outside."""
        p = vec(point)
        if self._g.periodic is not None:
            return math.inf  # a torus has no boundary
        # (a tiled world's open edges, strew.tiles._open_edges, are no boundary: the
        # distance to the closed part, inf where there is none)
        d = float(shapely.distance(self._g.closed_boundary, shapely.Point(p)))
        if not math.isfinite(d) or shapely.is_empty(self._g.closed_boundary):
            d = math.inf
        return d if self._g.region.contains(p[None])[0] else -(d if math.isfinite(d) else 0.0)

    def clearance(self, point: Any, *, ignore: Iterable[Element] = ()) -> float:
        """Radius of the largest empty circle at ``point``: distance to the nearest placed
        element (``ignore`` skipped) or to the boundary, whichever is nearer (<= 0 outside)."""
        p = vec(point)
        d = self.boundary_distance(p)
        if d <= 0:
            return d
        return min(d, self._g.element_distance(p, {e.index for e in ignore}, d))

    def clear_exclude(self) -> None:
        """Empty the exclude list (§4.1: a state change may open new possibilities)."""
        self._g.clear_exclude_all()


@dataclass
class Ornament:
    """The grown geometry: elements with proxies, before rendering.

    Attributes
    ----------
    pattern : Pattern
    region : Region
    elements : list of Element
        In placement order; seeds first.
    seeds : (k, 2) float
    stats : dict
        ``iterations``, ``successes``, ``failures`` (exclude-list additions),
        ``rejected`` (circles discarded after the exact test), ``largest_circle`` (radius
        of the largest eligible circle when growth stopped), ``seconds``, ``resolution``.
    params : dict
    """

    pattern: Pattern
    region: Region
    elements: list[Element]
    seeds: np.ndarray
    stats: dict[str, Any] = field(default_factory=dict)
    params: dict[str, Any] = field(default_factory=dict)

    def of_type(self, name: str) -> list[Element]:
        """Placed elements of one type."""
        return [e for e in self.elements if e.type == name]

    def render(self, style: str = "outline", **kwargs: Any) -> Any:
        """The ornament drawn in a named style as an :class:`~strew.Arrangement`."""
        from ._render import render_ornament

        return render_ornament(self, style, **kwargs)


def default_seed(region: Region) -> np.ndarray:
    """A sensible default seed: the centre of the largest circle inscribed in the region."""
    g = region.geometry
    try:
        mic = shapely.maximum_inscribed_circle(g, tolerance=max(1e-9, 1e-3 * math.sqrt(region.area)))
        p = np.asarray(shapely.get_coordinates(mic)[0], dtype=float)
    except AttributeError:  # shapely < 2.1
        p = np.asarray(g.representative_point().coords[0], dtype=float)
    return p.reshape(1, 2)


class _Grower:
    def __init__(
        self,
        pattern: Pattern,
        region: Region,
        seeds: np.ndarray,
        rng: np.random.Generator,
        resolution: int | None,
        min_radius: float,
        delta: float | None,
        epsilon: float | None,
        max_elements: int | None,
        reporter: Reporter,
        incremental: bool = True,
        periodic: tuple[float, float, float, float] | None = None,
        thin_boundary: bool = False,
        context: list[Element] | None = None,
        holes: Sequence[Sequence[Any]] | None = None,
        open_edges: Sequence[Sequence[float]] | None = None,
    ) -> None:
        # incremental=False recomputes the whole distance transform after every placement
        # instead of the lower wave: the baseline of benchmarks/ornament.py
        self.incremental = incremental
        self.pattern = pattern
        self.region = region
        self.rng = rng
        self.state = pattern.new_state()
        self.min_radius = min_radius
        self.delta = delta
        self.epsilon = epsilon
        self.max_elements = max_elements
        self.rep = reporter
        self.elements: list[Element] = []
        self.placed = _Placed(bucket=max(4.0 * min_radius, 1e-3), bounds=region.bounds)
        self.rules_by_parent: dict[str, list] = {}
        for r in pattern.rules:
            self.rules_by_parent.setdefault(r.parent, []).append(r)
        bx0, by0, bx1, by1 = region.bounds
        size = max(bx1 - bx0, by1 - by0)
        # Periodic growth (issue 18; the paper grows in a panel): the region is the tile of
        # a torus. Every placed proxy gets its 8 translates by whole periods (ghost images
        # for the exact tests), the raster covers the tile and a margin around it into
        # which those images are rendered, and only cells of the tile itself are candidate
        # centres. Distances, empty circles and collisions therefore wrap around the torus.
        self.periodic = periodic
        self.margin = 0.0
        if periodic is not None:
            # the medial axis of the field restricted to the tile lies within half the
            # tile's diagonal of the obstacles that shape it: render their images that far
            self.margin = 0.5 * math.hypot(bx1 - bx0, by1 - by0)
            bx0, by0, bx1, by1 = bx0 - self.margin, by0 - self.margin, bx1 + self.margin, by1 + self.margin
        self.open_edges = None
        self.centre_zone = None
        if periodic is None and open_edges is not None and len(open_edges):
            self.open_edges = np.asarray(open_edges, float)
            if self.open_edges.shape[1] > 4 and (self.open_edges[:, 4] > 0).any():
                # candidate centres up to m past an open edge (its fifth value): a circle
                # there, measured against the elements alone, is one that one run would
                # have grown into; only its elements must lie in the region
                m = float(self.open_edges[:, 4].max())
                ox = self.open_edges
                if np.any((ox[:, 0] == ox[:, 2]) & (ox[:, 0] <= bx0)):
                    bx0 -= m
                if np.any((ox[:, 0] == ox[:, 2]) & (ox[:, 0] >= bx1)):
                    bx1 += m
                if np.any((ox[:, 1] == ox[:, 3]) & (ox[:, 1] <= by0)):
                    by0 -= m
                if np.any((ox[:, 1] == ox[:, 3]) & (ox[:, 1] >= by1)):
                    by1 += m
                strips = [shapely.buffer(shapely.linestrings([(a, b), (c, d)]), mm, cap_style="flat") for a, b, c, d, mm in ox if mm > 0]
                self.centre_zone = shapely.union_all([region.geometry, *strips])
                shapely.prepare(self.centre_zone)
            self.open_edges = self.open_edges[:, :4]
        if resolution is None:
            # cells of half the minimum radius, between 256 and 2048 along the longer side
            resolution = int(np.clip(np.ceil(size / (0.5 * min_radius)), 256, 2048))
        if not (isinstance(resolution, (int, np.integer)) and 8 <= resolution <= 8192):
            raise InputError(f"cells: expected an integer between 8 and 8192 cells, got {resolution!r}")
        self.resolution = int(resolution)
        h = size / resolution  # (cells along the region's, or the tile's, longer side)
        self.h = h
        self.pad = h * math.sqrt(0.5)
        self.tol = 1e-9 * max(1.0, size)
        self.x0, self.y0 = bx0 - h, by0 - h
        self.cols = int(np.ceil((bx1 - bx0) / h)) + 2
        self.rows = int(np.ceil((by1 - by0) / h)) + 2
        rows, cols = self.rows, self.cols
        # -- render the boundary of R into the buffer (§4.1) ---------------------------
        xs = self.x0 + (np.arange(cols) + 0.5) * h
        ys = self.y0 + (np.arange(rows) + 0.5) * h
        gx, gy = np.meshgrid(xs, ys)
        # GEOS's vectorised point test, not the shared scanline (strew._kernels.raster):
        # a centre on the boundary stays outside, and it costs 1-2% of a growth
        inside = shapely.contains_xy(region.prepared, gx.ravel(), gy.ravel()).reshape(rows, cols)
        # a tiled world's halo edges that face a later tile (issue 19.4, strew.tiles
        # ._open_edges): segments (x0, y0, x1, y1) of the region's boundary that stop no
        # circle (see _open_boundary)
        if periodic is None:
            covered = np.where(inside, 0, 1).astype(np.int8)
            if self.open_edges is not None:
                oc = _open_cells(region, self.open_edges, gx, gy, inside, size)
                covered[oc] = 4
                if self.centre_zone is not None:
                    # cells past an open edge within m are candidates
                    z = shapely.contains_xy(self.centre_zone, gx.ravel(), gy.ravel()).reshape(rows, cols)
                    covered[oc & z] = 0
            if thin_boundary:
                # Around context (issue 19.4): the region is the panel less the context's
                # footprint, whose thin parts (willow's stems, a hair wide) hold no cell
                # centre, so the raster saw no boundary where the exact test did; every
                # circle near them was then discarded as stopped by the boundary, and a
                # tiled willow world's tile grew nothing. The boundary is drawn as lines
                # are (cells within half a cell diagonal). Not for a plain panel, whose
                # results stay as they were.
                pad = h * math.sqrt(0.5)
                for p in region.paths:
                    ring = np.ascontiguousarray(np.vstack([p.points, p.points[:1]]), dtype=np.float64)
                    covered.flat[cover_polyline(rows, cols, self.x0, self.y0, h, ring, pad)] = 1
        else:
            # no boundary on a torus: cells outside the tile are only not candidates (bit 4)
            covered = np.where(inside, 0, 4).astype(np.int8)
        # Cells whose centre lies outside R are covered. Circles cover the cells whose
        # centre they contain; lines and points cover the cells within half a cell
        # diagonal, so that none slips between cell centres. Raster distances therefore
        # overestimate the exact ones near circles and the boundary, and underestimate
        # them by at most that half diagonal near lines (see `slack` in `run`).
        self.has_lines = False
        self.covered = covered
        # -- initial distance transform (the MAT's values) ------------------------------
        if periodic is None:
            # (cells past an open edge, bit 4, are no obstacle: only not candidates)
            d, (ii, jj) = ndimage.distance_transform_edt((covered & 3) == 0, return_indices=True)
            self.dist_all = d.astype(np.float64)
            self.near_all = (ii.astype(np.int64) * cols + jj).astype(np.int64)
        else:  # nothing covered yet: the seeds' waves set every distance
            self.dist_all = np.full((rows, cols), np.inf)
            self.near_all = np.full((rows, cols), -1, np.int64)
        self.dist_el = np.full((rows, cols), np.inf)
        self.near_el = np.full((rows, cols), -1, np.int64)
        self.skip = np.zeros((rows, cols), bool)
        # On a torus the waves of the dist_all field stop where the distance exceeds the
        # largest empty circle still in the tile (plus slack): no tile cell's nearest
        # obstacle lies farther, so cells of the margin beyond it need no update.
        self._tile_rows = self._tile_cols = slice(0)
        if periodic is not None:
            ii, jj = np.nonzero(covered == 0)
            self._tile_rows, self._tile_cols = slice(int(ii.min()), int(ii.max()) + 1), slice(int(jj.min()), int(jj.max()) + 1)
        self._commits = 0
        self._edge_dist = None
        if periodic is not None:
            # distance in cells from each cell to the tile's cells
            ci = np.arange(rows)
            cj = np.arange(cols)
            di = np.maximum(0, np.maximum(self._tile_rows.start - ci, ci - (self._tile_rows.stop - 1)))
            dj = np.maximum(0, np.maximum(self._tile_cols.start - cj, cj - (self._tile_cols.stop - 1)))
            self._edge_dist = np.hypot(di[:, None].astype(float), dj[None, :].astype(float))
        self._cap_cells = math.inf
        self._cap_all = np.full((rows, cols), np.inf) if periodic is not None else None
        self._ring = np.empty(rows * cols, np.int64)
        self._inq = np.zeros(rows * cols, bool)
        br, bc = -(-rows // _BLOCK), -(-cols // _BLOCK)
        # the blocks' best candidates, their dirty flags and list, their largest
        # distances and the tournament tree over the best (see ._raster; issue 19.6)
        self.dirty = np.zeros((br, bc), bool)
        self.dlist = np.empty(br * bc, np.int64)
        self.dcount = np.zeros(1, np.int64)
        self.best_val = np.full((br, bc), -1.0)
        self.best_idx = np.full((br, bc), -1, np.int64)
        self.bmax = np.zeros((br, bc))
        self.tree = np.empty(2 << max(0, int(br * bc - 1).bit_length()), np.int64)
        tree_build(self.tree, self.best_val)
        self._mark_all()
        self.ex = np.empty((64, 2))
        self.n_ex = 0
        self.adj_tol = 2.0  # cells: raster pre-filter of "stopped by an element"
        rings = []
        for p in region.paths:
            ring = np.vstack([p.points, p.points[:1]])
            rings.append(np.c_[ring[:-1], ring[1:]])
        self.boundary_segs = np.ascontiguousarray(np.vstack(rings), dtype=np.float64)
        self.closed_boundary = region.boundary
        if self.open_edges is not None:
            self.boundary_segs, self.closed_boundary = _closed_part(region, self.open_edges, size)
        if periodic is not None:
            self.boundary_segs = np.zeros((0, 4))
        self.region_cover = shapely.buffer(region.geometry, 1e-7 * max(1.0, size))
        shapely.prepare(self.region_cover)
        self.stats: dict[str, Any] = dict(iterations=0, successes=0, failures=0, rejected=0, outside=0)
        seed_type = pattern.types["seed"]
        self.n_seeds = len(seeds)
        # a tiled world's finished neighbours (issue 19.4, strew.ornament._context): placed
        # first, as elements, so that they stop circles and parent growth as the tile's own
        # elements do; not drawn, not counted
        self.n_context = len(context or ())
        # a tiled world's handed-over room (issue 19.4, strew.ornament._context.HOLES_KEY):
        # the empty circles (x, y, r) of the successes a finished neighbour grew and dropped
        # and the phase each was grown in (None: any), see _holes_of_phase
        self.holes, self.hole_phases = _holes_in(holes, region.bounds)
        self._hole_cache: dict[str, np.ndarray] = {}
        if context:
            phases = [el.phase for el in context]
            self._commit(None, list(context))
            for el, ph in zip(context, phases):
                el.phase = ph
        for s in seeds:
            el = Element(seed_type)
            el.proxy.set(s)  # type: ignore[attr-defined]
            self._commit(None, [el])

    # -- exact environment queries --------------------------------------------------------
    def element_distance(self, p: np.ndarray, ignore: set[int], reach: float) -> float:
        if not math.isfinite(reach):  # on a torus (no boundary): as far as the images reach
            reach = self.margin
        idx = self.placed.near(p[0], p[1], reach)
        if ignore:
            idx = idx[~np.isin(self.placed.owner[idx], list(ignore))]
        if len(idx) == 0:
            return math.inf
        return float(self.placed.distances(idx, p[0], p[1]).min())

    def intersects(self, proxies: Sequence[Proxy], ignore: set[int]) -> bool:
        pl = self.placed
        tol = self.tol
        for pr in proxies:
            if not pr.is_set:
                raise InputError(f"intersects: {pr.kind} proxy was not set")
            cx, cy, r = pr.bounding_circle()
            idx = pl.near(cx, cy, r + tol)
            if ignore and len(idx):
                idx = idx[~np.isin(pl.owner[idx], list(ignore))]
            if len(idx) == 0:
                continue
            rnd = pl.round[idx]
            if isinstance(pr, (Circle, Point)):
                ci = idx[rnd]
                if len(ci):
                    d = np.hypot(pl.bx[ci] - cx, pl.by[ci] - cy) - pl.br[ci] - r
                    if np.any(d < -tol):
                        return True
                oi = idx[~rnd]
                if len(oi):
                    geoms = np.asarray([pl.proxies[i].geometry for i in oi], dtype=object)
                    if np.any(shapely.distance(geoms, shapely.Point(cx, cy)) < r - tol):
                        return True
            else:
                g = pr.geometry
                ci = idx[rnd]
                if len(ci):
                    d = shapely.distance(g, shapely.points(np.c_[pl.bx[ci], pl.by[ci]]))
                    if np.any(d < pl.br[ci] - tol):
                        return True
                oi = idx[~rnd]
                if len(oi):
                    geoms = np.asarray([pl.proxies[i].geometry for i in oi], dtype=object)
                    if np.any(shapely.intersects(g, geoms)):
                        return True
        return False

    def inside(self, proxies: Sequence[Proxy]) -> bool:
        if self.periodic is not None:
            # on a torus every place is inside; an element wider than the raster's margin
            # would reach past the images that stand for its neighbours, so it is refused
            for pr in proxies:
                if not pr.is_set:
                    raise InputError(f"inside: {pr.kind} proxy was not set")
                if not pr.bounding_circle()[2] < self.margin:
                    return False
            return True
        for pr in proxies:
            if not pr.is_set:
                raise InputError(f"inside: {pr.kind} proxy was not set")
            if isinstance(pr, (Circle, Point)):
                c = pr.center
                if not self.region.contains(c[None])[0]:  # type: ignore[index]
                    return False
                r = pr.radius if isinstance(pr, Circle) else 0.0
                if r > 0 and float(shapely.distance(self.region.boundary, shapely.Point(c))) < r - self.tol:
                    return False
            elif not shapely.covers(self.region_cover, pr.geometry):
                return False
        return True

    # -- buffer updates -----------------------------------------------------------------
    def _cells(self, pr: Proxy, dx: float = 0.0, dy: float = 0.0) -> np.ndarray:
        # the proxy translated by (dx, dy) covers the cells the proxy covers in a raster
        # whose origin is moved by (-dx, -dy)
        a = (self.rows, self.cols, self.x0 - dx, self.y0 - dy, self.h)
        if isinstance(pr, (Circle, Point)):
            cx, cy = float(pr.center[0]), float(pr.center[1])  # type: ignore[index]
            cells = cover_disc(*a, cx, cy, pr.radius, 0.0) if isinstance(pr, Circle) else np.empty(0, np.int64)
            if not len(cells):
                cells = cover_disc(*a, cx, cy, 0.0, self.pad)
            if not len(cells):
                # a point on a cell corner: the four centres lie at exactly the half
                # diagonal, which rounding may put a hair beyond it. It covered nothing,
                # so no circle was stopped by it and growth never began (issue 19.4: a
                # tile of 180 at (210, 210), seed (300, 300), cells of 0.6 grew nothing
                # and left its tile empty); it covers the cell that holds it (none when it
                # lies off the raster: a far image on a torus)
                j, i = math.floor((cx - a[2]) / self.h), math.floor((cy - a[3]) / self.h)
                if 0 <= i < self.rows and 0 <= j < self.cols:
                    cells = np.array([i * self.cols + j], np.int64)
            return cells
        self.has_lines = True
        pts = np.ascontiguousarray(pr.polyline(), dtype=np.float64)
        if isinstance(pr, Polygon):
            ring = np.ascontiguousarray(np.vstack([pts, pts[:1]]))
            return np.concatenate([cover_polygon(*a, pts), cover_polyline(*a, ring, self.pad)])
        return cover_polyline(*a, pts, self.pad)

    def _commit(self, parent: Element | None, children: list[Element]) -> None:
        cells = []
        first = len(self.elements)
        for ch in children:
            ch.group = first  # type: ignore[attr-defined]  # the rule success that made it (a tiled world keeps it whole)
            ch.parent = parent
            if parent is not None:
                parent.children.append(ch)
            ch.index = len(self.elements)
            ch.phase = self.state.phase
            self.elements.append(ch)
            for pr in ch.proxies:
                bc = pr.bounding_circle()
                for dx, dy in self._offsets(ch):
                    self.placed.add(pr, ch.index, dx, dy)
                    if self._renders(bc, dx, dy):
                        cells.append(self._cells(pr, dx, dy))
        if not cells:
            return
        c = np.unique(np.concatenate(cells))
        if len(c) == 0:
            return
        self.covered.flat[c] |= 2
        if not self.incremental:
            d, (ii, jj) = ndimage.distance_transform_edt((self.covered & 3) == 0, return_indices=True)
            changed = d < self.dist_all
            self.dist_all, self.near_all = d, ii.astype(np.int64) * self.cols + jj
            d, (ii, jj) = ndimage.distance_transform_edt((self.covered & 2) == 0, return_indices=True)
            changed |= d < self.dist_el
            self.dist_el, self.near_el = d, ii.astype(np.int64) * self.cols + jj
            self.skip &= ~changed
            self._mark_all()
            return
        w = (self._ring, self._inq)
        d = (self.dirty, self.dlist, self.dcount)
        if self._cap_all is None:
            lower_wave(self.dist_all, self.near_all, self.skip, c, *d, True, self.dist_all, 0.0, False, *w)
        else:
            lower_wave(self.dist_all, self.near_all, self.skip, c, *d, True, self._cap_all, 0.0, True, *w)
            self._commits += 1
            if self._commits % 8 == 1:
                r = float(self.dist_all[self._tile_rows, self._tile_cols].max()) + 4.0
                if r < 0.75 * self._cap_cells:
                    # a wave reaching a tile cell within r passes margin cells at most r
                    # minus their distance to the tile from its obstacle
                    self._cap_cells = r
                    np.subtract(r, self._edge_dist, out=self._cap_all)
        lower_wave(self.dist_el, self.near_el, self.skip, c, *d, False, self.dist_all, self.adj_tol + 1.0, True, *w)

    def _offsets(self, el: Element) -> list[tuple[float, float]]:
        """Translations at which element ``el`` is placed: itself only, or on a torus the
        3 x 3 translates around its canonical position (its first proxy's centre moved
        into the tile), which keep their place however far growth carried the element."""
        if self.periodic is None or not el.proxies:
            return [(0.0, 0.0)]
        x0, y0, w, h = self.periodic
        cx, cy, _ = el.proxies[0].bounding_circle()
        sx, sy = math.floor((cx - x0) / w) * w, math.floor((cy - y0) / h) * h
        return [(i * w - sx, j * h - sy) for j in (0, -1, 1) for i in (0, -1, 1)]

    def _renders(self, bc: tuple[float, float, float], dx: float, dy: float) -> bool:
        """Whether a proxy (bounding circle ``bc``) translated by ``(dx, dy)`` goes into
        the raster: always in a panel; on a torus only when it comes within the largest
        empty circle still in the tile of the tile (farther, it is no cell's nearest)."""
        if self.periodic is None or (dx == 0.0 and dy == 0.0):
            return True
        x0, y0, w, h = self.periodic
        cx, cy, r = bc[0] + dx, bc[1] + dy, bc[2]
        gx = max(x0 - cx, 0.0, cx - (x0 + w))
        gy = max(y0 - cy, 0.0, cy - (y0 + h))
        return math.hypot(gx, gy) - r <= (self._cap_cells + 2.0) * self.h

    def _wrap_points(self, p: np.ndarray) -> np.ndarray:
        """``p`` (2,) and, on a torus, its translates that fall in the raster, (k, 2)."""
        if self.periodic is None:
            return p[None, :]
        x0, y0, w, h = self.periodic
        q = np.array([[p[0] + i * w, p[1] + j * h] for j in (-1, 0, 1) for i in (-1, 0, 1)])
        m = self.margin
        keep = (q[:, 0] >= x0 - m) & (q[:, 0] <= x0 + w + m) & (q[:, 1] >= y0 - m) & (q[:, 1] <= y0 + h + m)
        return q[keep]

    # -- exclude list ---------------------------------------------------------------------
    def _mark_all(self) -> None:
        mark_rect(self.dirty, self.dlist, self.dcount, 0, self.dirty.shape[0], 0, self.dirty.shape[1])

    def add_exclude(self, p0: np.ndarray) -> None:
        for p in self._wrap_points(p0):  # on a torus: the point and its translates
            if self.n_ex == len(self.ex):
                self.ex = np.vstack([self.ex, np.empty_like(self.ex)])
            self.ex[self.n_ex] = p
            self.n_ex += 1
            # the blocks whose best circle contains the point: within the largest best
            # radius of it (the tree's root), not a pass over every block (issue 19.6)
            rmax = float(self.best_val.flat[self.tree[1]]) * self.h
            mark_excluded(
                self.dirty, self.dlist, self.dcount, self.best_val, self.best_idx, self.cols, self.x0, self.y0, self.h,
                float(p[0]), float(p[1]), rmax,
            )  # fmt: skip

    def clear_exclude_near(self, p: np.ndarray, eps: float) -> None:
        if self.n_ex == 0:
            return
        pts = self.ex[: self.n_ex]
        dx, dy = pts[:, 0] - p[0], pts[:, 1] - p[1]
        if self.periodic is not None:  # distance around the torus: a point goes with its translates
            w, h = self.periodic[2], self.periodic[3]
            dx, dy = dx - w * np.floor(dx / w + 0.5), dy - h * np.floor(dy / h + 0.5)
        gone = np.hypot(dx, dy) <= eps
        if not gone.any():
            return
        removed = pts[gone].copy()
        keep = pts[~gone].copy()
        self.n_ex = len(keep)
        self.ex[: self.n_ex] = keep
        # circles that contained a removed point may be eligible again: the cells within
        # their own radius of it, so the blocks within their largest distance of it (each
        # block keeps its own; once a global bound, and a pass over the raster every 32
        # successes kept it: issue 19.6)
        gmax = float(self.bmax.max())
        for q in removed:
            mark_near(self.dirty, self.dlist, self.dcount, self.bmax, self.x0, self.y0, self.h, float(q[0]), float(q[1]), 2 * self.h, gmax)

    def _skip_disc(self, c: np.ndarray, radius: float) -> None:
        """Mark every cell centred within ``radius`` of ``c`` as rejected."""
        if not radius > 0 or not math.isfinite(radius):
            return
        h = self.h
        j0 = max(0, int((c[0] - radius - self.x0) / h))
        j1 = min(self.cols, int((c[0] + radius - self.x0) / h) + 1)
        i0 = max(0, int((c[1] - radius - self.y0) / h))
        i1 = min(self.rows, int((c[1] + radius - self.y0) / h) + 1)
        if j0 >= j1 or i0 >= i1:
            return
        xs = self.x0 + (np.arange(j0, j1) + 0.5) * h - c[0]
        ys = self.y0 + (np.arange(i0, i1) + 0.5) * h - c[1]
        inside = xs[None, :] ** 2 + ys[:, None] ** 2 < radius * radius
        self.skip[i0:i1, j0:j1] |= inside
        mark_rect(self.dirty, self.dlist, self.dcount, i0 // _BLOCK, (i1 - 1) // _BLOCK + 1, j0 // _BLOCK, (j1 - 1) // _BLOCK + 1)

    def clear_exclude_all(self) -> None:
        self.n_ex = 0
        self.skip[:] = False
        self._mark_all()

    def _measure(self, c: np.ndarray, reach: float) -> tuple[float, float, float, np.ndarray, np.ndarray]:
        """Exact radius of the empty circle at ``c``: (rho, d_boundary, d_element, idx, dists)."""
        d_b = float(segments_distance(float(c[0]), float(c[1]), self.boundary_segs))
        idx = self.placed.near(c[0], c[1], reach)
        dists = self.placed.distances(idx, c[0], c[1]) if len(idx) else np.empty(0)
        d_e = float(dists.min()) if len(dists) else math.inf
        return min(d_b, d_e), d_b, d_e, idx, dists

    def _climb(self, c: np.ndarray, rho: float, reach: float, target: float) -> tuple[np.ndarray, float]:
        """Pattern search for the exact centre of the largest empty circle near ``c``."""
        pl = self.placed
        idx = pl.near(c[0], c[1], reach)
        rnd = pl.round[idx]
        circ = np.c_[pl.bx[idx[rnd]], pl.by[idx[rnd]], pl.br[idx[rnd]]]
        segs = [pl.segments(k) for k in idx[~rnd]]
        b = self.boundary_segs
        lo = np.minimum(b[:, :2], b[:, 2:])
        hi = np.maximum(b[:, :2], b[:, 2:])
        gap = np.maximum(np.maximum(lo - c, c - hi), 0)
        segs.append(b[np.hypot(gap[:, 0], gap[:, 1]) <= reach])
        allsegs = np.ascontiguousarray(np.vstack(segs))
        x, y, v = climb(float(c[0]), float(c[1]), np.ascontiguousarray(circ), allsegs, 0.5 * self.h, 0.02 * self.h, target)
        if self.periodic is not None:
            x0, y0, w, h = self.periodic
            ok = x0 - self.margin / 2 <= x <= x0 + w + self.margin / 2 and y0 - self.margin / 2 <= y <= y0 + h + self.margin / 2
        elif self.centre_zone is not None:
            ok = bool(shapely.contains_xy(self.centre_zone, x, y))
        else:
            ok = bool(self.region.contains(np.array([[x, y]]))[0])
        if v > rho and ok:
            return np.array([x, y]), float(v)
        return c, rho

    # -- main loop (§4.1) -----------------------------------------------------------------
    def _phase_threshold(self, k: int) -> float:
        phases = self.pattern.phases
        if not phases or k >= len(phases) - 1:
            return self.min_radius
        mr = phases[k].min_radius
        return self.min_radius if mr is None else max(mr, self.min_radius)

    def run(self) -> None:
        h = self.h
        phase_k = 0
        threshold = self._phase_threshold(0)
        # The candidate centre lies within sqrt(2)/2 cells of the exact medial point, and
        # near lines the raster radius may fall short by another sqrt(2)/2 cells.
        slack = 0.75 * h
        largest = 0.0
        while True:
            if self.max_elements is not None and len(self.elements) - self.n_context >= self.max_elements:
                break
            grown = len(self.elements) - self.n_seeds - self.n_context  # the seeds are not drawn; not counted (issue 23)
            self.rep.tick(grown, message=f"{grown} grown")
            k = scan_blocks(
                self.dist_all, self.dist_el, self.covered, self.skip, self.dirty, self.dlist, self.dcount,
                self.best_val, self.best_idx, self.bmax, self.tree, self.adj_tol, self.ex, self.n_ex, self.x0, self.y0, h,
            )  # fmt: skip
            v = float(self.best_val.flat[k])
            if v < 0 or v * h + slack + (self.pad if self.has_lines else 0.0) < threshold:
                if self.pattern.phases and phase_k < len(self.pattern.phases) - 1:
                    phase_k += 1
                    self.state.phase = self.pattern.phases[phase_k].name
                    threshold = self._phase_threshold(phase_k)
                    self.clear_exclude_all()
                    continue
                largest = max(0.0, v * h) if v >= 0 else 0.0
                break
            cell = int(self.best_idx.flat[k])
            i, j = divmod(cell, self.cols)
            c = c0 = np.array([self.x0 + (j + 0.5) * h, self.y0 + (i + 0.5) * h])
            # -- exact radius of C, and whether an element (not the boundary) stopped it
            reach = self.dist_el[i, j] * h + 4 * h + max(2 * h, 0.25 * (self.dist_all[i, j] * h + h))
            rho, d_b, d_e, idx, dists = self._measure(c, reach)
            if threshold - 0.75 * h <= rho < threshold and d_e <= d_b + h:
                # The raster circle is centred on a cell; the exact medial point lies within
                # half a cell diagonal of it, so (the clearance being 1-Lipschitz) only
                # circles this close to the threshold may reach it: climb to the medial
                # point before giving them up.
                c, rho = self._climb(c, rho, reach + 2 * h, threshold)
                rho, d_b, d_e, idx, dists = self._measure(c, reach + 2 * h)
            if d_e > d_b + h or rho < threshold:
                # §4.1: a circle stopped by the boundary before it reaches an element is
                # discarded; so is one that is too small once measured exactly. The
                # clearance is 1-Lipschitz, so every circle centred within (threshold -
                # rho) of c is too small as well (less `slack`: a cell stands for centres
                # up to that far), and every centre within (d_e - d_b - h) / 2 is stopped
                # by the boundary too: skip those cells at once.
                self.skip[i, j] = True
                mark_rect(self.dirty, self.dlist, self.dcount, i // _BLOCK, i // _BLOCK + 1, j // _BLOCK, j // _BLOCK + 1)
                self._skip_disc(c, max(threshold - rho - slack, (d_e - d_b - h) / 2))
                self.stats["rejected"] += 1
                continue
            self.stats["iterations"] += 1
            goal = Goal(c, rho)
            scaled = goal if self.holes is None else _handed_over(goal, self._holes_of_phase())
            delta = self.delta if self.delta is not None else max(2 * h, 0.1 * rho)
            owners = self.placed.owner[idx]
            order: dict[int, float] = {}
            shift: dict[int, tuple[float, float]] = {}
            for o, dd, k in zip(owners.tolist(), dists.tolist(), idx.tolist()):
                if dd - rho <= delta and (o not in order or dd < order[o]):
                    order[o] = dd
                    shift[o] = (float(self.placed.ox[k]), float(self.placed.oy[k]))
            cand = sorted(order, key=lambda o: (order[o], o))
            # (a goal no hand-over scaled: _try's call as it always was)
            success = self._try(goal, cand, shift) if scaled is goal else self._try(scaled, cand, shift, circle=goal)
            if success:
                self.stats["successes"] += 1
                eps = self.epsilon if self.epsilon is not None else 2 * rho
                self.clear_exclude_near(c, eps)
            else:
                self.stats["failures"] += 1
                self.add_exclude(c)
                if c is not c0:
                    # the climb moved C's centre off the raster candidate, possibly out of
                    # the candidate's own circle: exclude the candidate too, or the same
                    # cell is found, climbed and failed again forever
                    self.add_exclude(c0)
        self.stats["largest_circle_raster"] = largest
        self.stats["phase"] = self.state.phase

    def _holes_of_phase(self) -> np.ndarray:
        """The handed-over circles grown into in the current phase, or of no phase
        (``(k, 3)``, possibly empty: no goal is raised).

        Why (issue 19.4, hierarchy): a circle a vine grew into in the vines phase raised
        the later tile's leaves and fillers to a vine's scale (Wong et al. §5: each phase
        grows its own kind, the phase handing over when no circle as large as its
        threshold is left); the refill grew fewer, larger elements and the strips
        thinned (tile 100, seed 1: +-2 s density 0.835, against 0.996 with nothing
        handed over). A finished tile's circle scales only the rules of the phase it was
        grown in (benchmarks/dot19r_handover.py, orn19m_willow.py)."""
        ph = self.state.phase
        if ph is None or self.hole_phases is None:
            return self.holes
        key = str(ph)
        if key not in self._hole_cache:
            ok = np.array([p is None or p == key for p in self.hole_phases], bool)
            self._hole_cache[key] = self.holes[ok]
        return self._hole_cache[key]

    def _try(self, goal: Goal, candidates: list[int], shift: dict[int, tuple[float, float]] | None = None,
             circle: Goal | None = None) -> bool:
        """Try the rules of ``candidates`` on ``goal`` (the rule's $goal); ``circle`` is the
        empty circle grown into (``goal`` itself unless a hand-over scaled it, _handed_over)."""
        circle = goal if circle is None else circle
        types = self.pattern.types
        for o in candidates:
            parent = self.elements[o]
            if parent.sterile:
                continue
            g = goal
            if shift and shift.get(o, (0.0, 0.0)) != (0.0, 0.0):
                # C touches a translate of the parent (across the tile's edge): the rule
                # sees C in the parent's own frame
                dx, dy = shift[o]
                g = Goal(goal.center - np.array([dx, dy]), goal.radius)
            for rule in self.rules_by_parent.get(parent.type, ()):
                if rule.phase is not None and rule.phase != self.state.phase:
                    continue  # state precondition (§5): the rule fails at once
                if rule.when is not None and not rule.when(self.state):
                    continue
                children = [Element(types[t]) for t in rule.children]
                ctx = RuleContext(self, g, parent)
                result = rule.body(ctx, parent, *children)
                if not isinstance(result, (bool, np.bool_)):
                    raise InputError(f"rule {rule.name!r} returned {result!r}; return SUCCESS or FAILURE")
                if not result:
                    continue
                new = children + ctx.dynamic
                for ch in new:
                    for k, pr in enumerate(ch.proxies):
                        if not pr.is_set:
                            raise InputError(f"rule {rule.name!r}: proxy {k} ({pr.kind}) of child {ch.type!r} was not set")
                # Not in the paper: the framework keeps every element inside the panel
                # (a rule that places a child across the boundary fails).
                if new and not self.inside([pr for ch in new for pr in ch.proxies]):
                    self.stats["outside"] += 1
                    continue
                self._commit(parent, new)
                for ch in new:
                    # the empty circle C it grew into, in the panel's frame: a tiled world
                    # hands over a finished tile's border by it (issue 19.4,
                    # strew.ornament._context.GOAL_COLUMN)
                    ch.goal_circle = (float(circle.center[0]), float(circle.center[1]), float(circle.radius))  # type: ignore[attr-defined]
                if new:
                    return True
        return False


def _open_cells(region: Region, open_edges: np.ndarray, gx: np.ndarray, gy: np.ndarray, inside: np.ndarray, size: float) -> np.ndarray:
    """(rows, cols) bool: the raster cells outside ``region`` whose centre lies nearer an
    open edge (:func:`_closed_part`) than the rest of the boundary: they stop no circle."""
    out = np.zeros(inside.shape, bool)
    ii, jj = np.nonzero(~inside)
    if not len(ii):
        return out
    pts = shapely.points(gx[ii, jj], gy[ii, jj])
    lines = shapely.multilinestrings([[(a, b), (c, d)] for a, b, c, d in open_edges])
    _, closed = _closed_part(region, open_edges, size)
    d_open = shapely.distance(lines, pts)
    d_closed = shapely.distance(closed, pts) if not shapely.is_empty(closed) else np.full(len(ii), np.inf)
    out[ii, jj] = d_open < d_closed
    return out


def _closed_part(region: Region, open_edges: np.ndarray, size: float) -> tuple[np.ndarray, Any]:
    """The segments ``(m, 4)`` and the linework of ``region``'s boundary less its open
    edges ``(k, 4)``.

    Why (issue 19.4, hierarchy): a tiled world's tile grows in its rectangle widened by
    the halo, and §4.1 discards a circle the boundary stops before it reaches an
    element. Where the halo's edge faces a tile that runs later, the world goes on
    there: one run would have measured that circle against the elements alone. A
    finished tile's vines phase (circles of radius >= 8, halo 12-17 at tiles 48-68)
    lost every circle centred past half the halo and squeezed its vines into the first
    half (1.82 and 3.06 times the interior's rate; benchmarks/hie15_halo.py). Departure
    from §4.1: these edges are no boundary; the region still bounds the circle's centre
    and the elements grown (``inside``).
    """
    tol = 1e-7 * max(1.0, size)
    lines = shapely.multilinestrings([[(a, b), (c, d)] for a, b, c, d in open_edges])
    closed = shapely.difference(region.boundary, shapely.buffer(lines, tol, cap_style="flat"))
    segs = []
    for part in shapely.get_parts(shapely.line_merge(closed) if not shapely.is_empty(closed) else closed):
        xy = shapely.get_coordinates(part)
        if len(xy) >= 2:
            segs.append(np.c_[xy[:-1], xy[1:]])
    arr = np.vstack(segs) if segs else np.zeros((0, 4))
    return np.ascontiguousarray(arr, dtype=np.float64), closed


def _holes_in(holes: Sequence[Sequence[Any]] | None, bounds: tuple[float, float, float, float]) -> tuple[np.ndarray | None, np.ndarray | None]:
    """The handed-over circles ``(m, 3)`` that reach into ``bounds`` (None for none), and
    the phase each was grown in (``(m,)`` object; None where no circle has one)."""
    if holes is None or not len(holes):
        return None, None
    h = np.array([v[:3] for v in holes], float).reshape(-1, 3)
    # (x, y, r[, phase]): the phase the circle was grown in (strew.tiles._ornament_holes)
    ph = np.array([v[3] if len(v) > 3 else None for v in holes], dtype=object)
    x0, y0, x1, y1 = bounds
    ok = (h[:, 0] + h[:, 2] > x0) & (h[:, 0] - h[:, 2] < x1) & (h[:, 1] + h[:, 2] > y0) & (h[:, 1] - h[:, 2] < y1)
    if not ok.any():
        return None, None
    return h[ok], (None if all(p is None for p in ph[ok]) else ph[ok])


def _handed_over(goal: Goal, holes: np.ndarray) -> Goal:
    """``goal`` at the scale a finished neighbour grew at there: its radius raised to the
    largest handed-over circle (``holes``) that holds its centre (the first such circle
    the neighbour grew into, §4.1 taking the largest first).

    Why (issue 19.4, willow): a later tile refills the room its finished neighbour
    dropped (strew.tiles._keep_groups) between the elements that neighbour kept, and
    Wong et al. scale a rule's elements to the empty circle it grows into (§5: the
    pattern "simplifies as it wanders into narrower spaces"). The refill's circles were
    narrower than the interior's (radius 0.85 s on average against 1.35 s; 0.7 % of
    them over 3 s against 9.2 %), its stems as long as the interior's in circles of the
    same size (1.08 s against 1.09 s under 0.6 s) but shorter on the whole (1.66 s
    against 2.07 s), and the finished side of the +-2 s strips denser than the interior
    (seed 1, tiles 100, 112, 124; benchmarks/orn19m_willow.py). Departure from §5: the
    rule sees the circle the finished tile had grown into there, not the narrower one
    the cut left; it grows fewer, larger elements into it, as the one run would have.
    The empty circle itself is still the one recorded (GOAL_COLUMN) and tried.
    """
    c = goal.center
    inside = np.hypot(holes[:, 0] - c[0], holes[:, 1] - c[1]) < holes[:, 2]
    if not inside.any():
        return goal
    r = float(holes[inside, 2].max())
    return Goal(c, r) if r > goal.radius else goal


def grow_elements(
    pattern: Pattern | str,
    region: Region,
    *,
    seeds: Sequence[Sequence[float]] | np.ndarray | None = None,
    rng: int | np.random.Generator | None = None,
    resolution: int | None = None,
    min_radius: float | None = None,
    delta: float | None = None,
    epsilon: float | None = None,
    max_elements: int | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
    periodic: bool = False,
    _thin_boundary: bool = False,
    _context: list[Element] | None = None,
    _holes: Sequence[Sequence[Any]] | None = None,
    _open: Sequence[Sequence[float]] | None = None,
) -> Ornament:
    """Grow a pattern in a region; returns the elements and their proxies (no rendering).

    See :func:`strew.ornament.grow_ornament` for the parameters. With ``periodic`` the
    region must be a rectangle, the tile of a torus: growth wraps around its edges, and
    elements keep the positions they were grown at (``params["periodic"]`` holds the tile
    ``[x0, y0, W, H]``; rendering draws them whole, unclipped, and
    :func:`strew._periodic.mark` moves the drawn elements into the tile).
    """
    import time

    pat = load_pattern(pattern)
    if not isinstance(region, Region):
        raise InputError(f"region: expected a Region, got {type(region).__name__}")
    if _context and seeds is not None and len(seeds) == 0:
        pts = np.zeros((0, 2))  # growth goes on from the context elements alone
    elif seeds is None or len(seeds) == 0:
        pts = default_seed(region)
    else:
        pts = np.asarray(seeds, dtype=float).reshape(-1, 2)
        if not np.all(np.isfinite(pts)):
            raise InputError("seed points: NaN or inf coordinate")
        outside = ~region.contains(pts)
        if outside.any():
            x, y = pts[np.flatnonzero(outside)[0]]
            raise InputError(f"seeds {x:g},{y:g} lies outside the region")
    mr = pat.min_radius if min_radius is None else float(min_radius)
    if not (math.isfinite(mr) and mr > 0):
        raise InputError(f"min_radius: must be positive, got {min_radius!r}")
    tile = None
    if periodic:
        from .._periodic import frame_of_region

        tile = frame_of_region(region)
        if min(tile[2], tile[3]) < 4 * mr:
            raise InputError(
                f"periodic: a {tile[2]:g} x {tile[3]:g} tile is smaller than two elements of the minimum radius "
                f"{mr:g}; use a larger --size or a smaller --min-radius"
            )
    for name, val in (("delta", delta), ("epsilon", epsilon)):
        if val is not None and not (math.isfinite(val) and val >= 0):
            raise InputError(f"{name}: must be a finite number >= 0, got {val!r}")
    if max_elements is not None and max_elements < 0:
        raise InputError(f"max_elements: must be >= 0, got {max_elements!r}")
    from .._limits import check_work  # refuse work beyond the limits (issue 17): discs of min_radius

    check_work("--min-radius" if min_radius is not None else "--size/--region", count=max_elements, region=region, per_element=math.pi * mr * mr)
    rep = Reporter(progress, should_cancel, message="growing")
    t0 = time.perf_counter()
    g = _Grower(pat, region, pts, as_rng(rng), resolution, mr, delta, epsilon, max_elements, rep, periodic=tile,
                thin_boundary=_thin_boundary, context=_context, holes=None if _holes is None else [list(v) for v in _holes], open_edges=_open)
    g.run()
    rep.done(len(g.elements) - g.n_seeds - g.n_context)
    stats = dict(g.stats)
    stats["seconds"] = time.perf_counter() - t0
    stats["resolution"] = g.resolution
    stats["cell"] = g.h
    stats["exclude_list"] = g.n_ex
    params = dict(
        pattern=pat.name,
        seeds=pts.tolist(),
        resolution=g.resolution,
        min_radius=mr,
        delta=delta,
        epsilon=epsilon,
        max_elements=max_elements,
    )
    if tile is not None:
        params["periodic"] = list(tile)
    return Ornament(pat, region, g.elements, pts, stats, params)

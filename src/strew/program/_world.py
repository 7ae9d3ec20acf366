"""Program scripts over worlds too large for one evaluation: tiles (issue 19.1).

A world ``[0, W] x [0, H]`` is cut into the tiles of :mod:`strew.tiles`. Each tile runs
the script on its rectangle grown by ``halo`` (clipped to the world) and keeps the pieces
of the resulting planar map's cells that lie in its own rectangle: every bounded face
clipped to the rectangle, every edge clipped to it (a piece along a tile border goes to
the tile whose half-open rectangle holds its midpoint). The pieces of a cell from all the
tiles it crosses make up the cell of one evaluation on the whole world, because every
tile computes the cells it shares with its neighbours to the same bits:

- stripes and grids (§5.1, regular) are fixed in the plane; in a world their lines are
  polylines whose vertices are fixed in the plane too, so that crops by different tiles
  keep the same inner segments (:func:`strew.program._operators._fixed_stripe_lines`);
- the uniform and random partitions (§5.1, non-regular) take their sites from a *field*
  of square cells fixed in the plane, ``FIELD_CELL`` mean spacings wide. A cell's sites
  are drawn from a generator seeded by (the partition's seed, the cell), the Poisson-disk
  ones with the sites of its lower-phase neighbour cells as obstacles (Wei 2008's 2 x 2
  phase groups: cells of one phase are a cell apart): the field's sets together are one
  Poisson-disk (or Poisson) set of the plane, whatever the tiles. Voronoi vertices are
  the circumcentres of their sites and labels are drawn per site (faces), site pair
  (edges) and vertex, so a cell is the same in every tile that holds it;
- mappers (§6.1) already draw every random value from the cell's own geometry
  (:meth:`PlanarMap.cell_key`), so a face gets the same curves in every tile that holds it
  whole.

So the world depends on the seed and the script only, not on ``tile_size`` nor on the
number of workers, as long as ``halo`` holds every cell (and every neighbourhood a mapper
queries, §6.1's bounded neighbourhood) that reaches into a tile. Where it does not, the
tile says so (:class:`HaloError`, naming ``halo`` and the cell's size) instead of drawing
a different world: a cell that ``KEEP_INSIDE`` drops for crossing a side of the grown
rectangle inside the world, a face given to ``map_to_faces`` that such a side closes
or cuts open, or an edge given to ``map_to_edges`` that ends on one, if it reaches into
the tile (:func:`check_dropped_faces`, :func:`check_open_faces`, :func:`check_cut_edges`;
the world's own outline closes cells in one evaluation too and does not count). The
check is conservative: a mapper whose curves happen to stay outside the tile would
still give the same world. The tiles need nothing
from each other: the field's phases are computed where they are needed (each process
keeps the cells it drew), so all tiles can run at once.

Departures (issue 19.1; the paper evaluates a script once, on one region): the field's
sites are a Poisson-disk set drawn cell by cell (Wei's phases) rather than one Bridson
run (each cell by :func:`strew.pack.poisson_disk` with its lower-phase neighbours' sites
as ``context``: obstacles and seeds of the same compiled Bridson, issue 15 point 5), and
face, edge and vertex labels of the non-regular partitions are drawn per cell from hashes
instead of from one stream in the order of the cells (§5.1 asks only for the given
apparition probabilities).
"""

from __future__ import annotations

import math
import threading
from contextvars import ContextVar
from typing import Any

import numpy as np

from .._errors import InputError
from ._curves import Curve

__all__ = ["field_sites", "run_tile", "evaluate_world", "FIELD_CELL", "HaloError"]

#: Side of a field cell in mean site spacings (1 / sqrt(density)): about 64 sites a cell.
FIELD_CELL = 8.0

_CACHE: dict[tuple[Any, ...], np.ndarray] = {}

_RUN_LOCK = threading.Lock()

#: Label of a tile's grown outline (see :func:`evaluate_tile`).
SEAM = "__strew_world_seam__"
_CACHE_LIMIT = 50_000


def _cell_sites(name: str, density: float, key: int, i: int, j: int) -> np.ndarray:
    """The sites of field cell ``(i, j)`` (drawn once per process, then kept)."""
    from ._context import derive_seed
    from ._sampling import tile_poisson, tile_poisson_disk

    ck = (name, density, key, i, j)
    got = _CACHE.get(ck)
    if got is not None:
        return got
    c = FIELD_CELL / math.sqrt(density)
    rect = (i * c, j * c, (i + 1) * c, (j + 1) * c)
    rng = np.random.default_rng(derive_seed(key, "field", i, j))
    if name == "random_partition":
        pts = tile_poisson(rect, density, rng)
    else:
        phase = (j % 2) * 2 + i % 2
        ctx = [
            _cell_sites(name, density, key, i + di, j + dj)
            for dj in (-1, 0, 1)
            for di in (-1, 0, 1)
            if (di or dj) and ((j + dj) % 2) * 2 + (i + di) % 2 < phase
        ]
        context = np.concatenate(ctx) if ctx else np.zeros((0, 2))
        pts = tile_poisson_disk(rect, density, context, rng)
    if len(_CACHE) >= _CACHE_LIMIT:
        _CACHE.clear()
    _CACHE[ck] = pts
    return pts


def field_sites(name: str, density: float, key: int, bounds: tuple[float, float, float, float]) -> np.ndarray:
    """(n, 2) the field's sites in ``bounds`` for the partition ``name`` seeded ``key``."""
    c = FIELD_CELL / math.sqrt(density)
    x0, y0, x1, y1 = bounds
    i0, i1 = math.floor(x0 / c), math.floor(x1 / c)
    j0, j1 = math.floor(y0 / c), math.floor(y1 / c)
    if (i1 - i0 + 1) * (j1 - j0 + 1) > 4 * _CACHE_LIMIT // 5:
        raise InputError(f"{name}: density {density:g} asks for too many sites on one tile; lower it or the tile size")
    parts = [_cell_sites(name, density, key, i, j) for j in range(j0, j1 + 1) for i in range(i0, i1 + 1)]
    pts = np.concatenate(parts) if parts else np.zeros((0, 2))
    inside = (pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)
    return pts[inside]


def _placeholder() -> dict[str, Any]:
    """The world's two kinds: every element draws its own geometry (``parts``), so that
    the tiles' libraries agree (a Parquet dataset has one library)."""
    from ..shape import Path as ShapePath
    from ..shape import Shape

    sq = np.array([[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]])
    return {
        "face": Shape((ShapePath(sq, True),), style={"fill": "none", "stroke": "none"}),
        "edge": Shape((ShapePath(sq[:2], False),), style={"fill": "none", "stroke": "#1d1f24"}),
    }


def _owned(x: np.ndarray, y: np.ndarray, rect: tuple[float, float, float, float], size: tuple[float, float]) -> np.ndarray:
    """Whether each ``(x, y)`` is in the half-open ``rect`` (the world's far edges closed)."""
    x0, y0, x1, y1 = rect
    okx = (x >= x0) & ((x < x1) | ((x == x1) & (x1 >= size[0])))
    oky = (y >= y0) & ((y < y1) | ((y == y1) & (y1 >= size[1])))
    return okx & oky


def _owned_runs(xy: np.ndarray, rect: tuple[float, float, float, float], size: tuple[float, float]) -> list[np.ndarray]:
    """The runs of consecutive segments of the polyline ``xy`` (a piece of an edge clipped
    to the closed ``rect``) whose midpoints the tile owns: a segment along a tile border
    goes to one tile only, also when the rest of its edge lies in the other."""
    mid = 0.5 * (xy[1:] + xy[:-1])
    own = _owned(mid[:, 0], mid[:, 1], rect, size)
    if own.all():
        return [xy]
    runs = []
    k = np.flatnonzero(np.diff(np.r_[0, own.astype(np.int8), 0]))
    for a, b in zip(k[::2].tolist(), k[1::2].tolist()):
        runs.append(xy[a : b + 1])
    return runs


class HaloError(InputError):
    """A tile's halo does not hold a cell that reaches into the tile (issue 19.1)."""


class _Tile:
    """The tile a script runs for: its rectangle, the grown rectangle it runs on, the
    sides of that rectangle that lie inside the world (the world's own edges close cells
    in the untiled evaluation too), and the halo."""

    def __init__(self, rect: tuple[float, float, float, float], grown: tuple[float, float, float, float],
                 size: tuple[float, float], halo: float) -> None:
        import shapely

        self.rect, self.grown, self.halo = rect, grown, halo
        self.tol = 1e-9 * max(size)
        gx0, gy0, gx1, gy1 = grown
        sides = []
        if gx0 > self.tol:
            sides.append([(gx0, gy0), (gx0, gy1)])
        if gx1 < size[0] - self.tol:
            sides.append([(gx1, gy0), (gx1, gy1)])
        if gy0 > self.tol:
            sides.append([(gx0, gy0), (gx1, gy0)])
        if gy1 < size[1] - self.tol:
            sides.append([(gx0, gy1), (gx1, gy1)])
        self.sides = shapely.MultiLineString(sides) if sides else None
        self.box = shapely.box(*rect)
        if self.sides is not None:
            shapely.prepare(self.sides)

    def refuse(self, geom: Any, what: str) -> None:
        x0, y0, x1, y1 = geom.bounds
        seen = max(x1 - x0, y1 - y0)
        need = max(seen, 2.0 * self.halo)
        r, g = self.rect, self.grown
        raise HaloError(
            f"halo: {self.halo:g} is too small: {what} reaching into the tile [{r[0]:g}, {r[2]:g}] x [{r[1]:g}, {r[3]:g}] "
            f"runs past the tile's rectangle grown by the halo, [{g[0]:g}, {g[2]:g}] x [{g[1]:g}, {g[3]:g}] (it is at "
            f"least {seen:.4g} across), so the tiled world would differ from one evaluation on the whole world; raise "
            f"halo to at least {need:.4g} (tile_size at least {2 * need:.4g}) or use a larger tile_size")


_TILE: ContextVar[_Tile | None] = ContextVar("strew_program_world_tile", default=None)


def check_cut_faces(polys: Any, what: str) -> None:
    """Refuse (:class:`InputError` naming ``halo``) when one of the faces ``polys`` about to
    be used whole (a mapper's cell) is closed in part by the grown rectangle's inner sides
    and reaches into the tile: the untiled cell extends beyond what the tile saw."""
    t = _TILE.get()
    if t is None or t.sides is None or not len(polys):
        return
    import shapely

    polys = np.asarray(polys, dtype=object)
    hit = np.flatnonzero(shapely.intersects(polys, t.sides))
    if not len(hit):
        return
    cut = shapely.length(shapely.intersection(shapely.boundary(polys[hit]), t.sides)) > t.tol
    for k in hit[cut].tolist():
        if shapely.area(shapely.intersection(polys[k], t.box)) > 0:
            t.refuse(polys[k], what)


def check_open_faces(pm: Any, geom: Any, what: str) -> None:
    """Refuse when a cell of the planar map ``pm`` reaching into the tile is cut open by an inner side
    of the grown rectangle, or closed in part by it: the whole world may close it (and
    give it to the mapper) beyond what the tile saw. The inner sides are added as open
    lines, so a region open through the world's own outline stays open as in the untiled
    evaluation (the world's outline closes nothing before the script's end)."""
    t = _TILE.get()
    if t is None or t.sides is None:
        return
    import shapely

    if not shapely.intersects(geom, t.sides):
        return
    from ._curves import Curves
    from ._planar_map import PlanarMap

    curves = pm.curves
    whole = pm._t.face_polygons[1:]
    check_cut_faces(whole, what)  # closed in part by the region's outline (CROP_ADD_BOUNDARY)
    sides = tuple(Curve(np.asarray(ln.coords), False, frozenset([SEAM])) for ln in t.sides.geoms)
    polys = np.asarray(PlanarMap(Curves(curves.curves + sides, curves.points, curves.marks))._t.face_polygons[1:], dtype=object)
    if not len(polys):
        return
    if len(whole):
        # the sides cut whole cells (KEEP_OUTSIDE's, beyond the region) into pieces: only
        # the regions that no cell of ``curves`` holds are the open ones
        inside = shapely.STRtree(np.asarray(whole, dtype=object)).query(shapely.point_on_surface(polys), predicate="within")[0]
        polys = np.delete(polys, np.unique(inside))
    check_cut_faces(polys, what)


def check_dropped_faces(polys: Any, what: str) -> None:
    """Refuse when one of the faces ``polys`` that a border rule drops for crossing the
    domain's outline crosses an inner side of the grown rectangle and reaches into the
    tile (inside the world it may be kept: Fig. 6's KEEP_INSIDE grid cells)."""
    t = _TILE.get()
    if t is None or t.sides is None or not len(polys):
        return
    import shapely

    polys = np.asarray(polys, dtype=object)
    for k in np.flatnonzero(shapely.intersects(polys, t.sides)).tolist():
        if shapely.area(shapely.intersection(polys[k], t.box)) > 0:
            t.refuse(polys[k], what)


def check_cut_edges(pm: Any, geom: Any, what: str) -> None:
    """Refuse when one of the edges of the planar map ``pm`` about to be used whole (a
    mapper's cell) ends on an inner side of the grown rectangle (cut there) and runs
    into the tile."""
    t = _TILE.get()
    if t is None or t.sides is None or not pm.n_edges:
        return
    import shapely

    if not shapely.intersects(geom, t.sides):
        return
    lines = np.array([shapely.LineString(pm._t.edge_points[e]) for e in range(pm.n_edges)], dtype=object)
    ends = shapely.boundary(lines)
    hit = np.flatnonzero(shapely.dwithin(ends, t.sides, t.tol) & ~shapely.is_empty(ends))
    for k in hit.tolist():
        if shapely.length(shapely.intersection(lines[k], t.box)) > 0:
            t.refuse(lines[k], what)


def clip_cells(pm: Any, rect: tuple[float, float, float, float], size: tuple[float, float], stroke_width: float) -> Any:
    """The pieces of ``pm``'s cells in the tile ``rect`` as an Arrangement (faces, then edges).

    Kinds ``face`` and ``edge``; each element's geometry is in ``parts`` (as in
    :func:`strew.program.to_strew`: faces filled by their labels' colour, edges stroked),
    its position the centre of its piece's box; columns ``cell`` and ``labels``.
    """
    import shapely

    from ..arrangement import PARTS_COLUMN, Arrangement
    from ..shape import Path as ShapePath
    from ..shape import Shape
    from ._script import _PALETTE, _STROKE_PALETTE, _label_color

    t = pm._t
    box = shapely.box(*rect)
    kinds, xs, ys, cells, labels, parts = [], [], [], [], [], []
    polys = np.array(t.face_polygons[1:], dtype=object)
    if len(polys):
        b = shapely.bounds(polys)
        near = np.flatnonzero((b[:, 2] >= rect[0]) & (b[:, 0] <= rect[2]) & (b[:, 3] >= rect[1]) & (b[:, 1] <= rect[3]))
        for f, piece in zip(near.tolist(), shapely.intersection(polys[near], box).tolist()):
            labs = t.face_labels[f + 1]
            style = {"fill": _label_color(labs, _PALETTE), "fill_opacity": 0.45, "stroke": "none"} if labs else {"fill": "none", "stroke": "none"}
            for poly in shapely.get_parts(piece):
                if not isinstance(poly, shapely.Polygon) or not (poly.area > 0):
                    continue
                x0, y0, x1, y1 = poly.bounds
                c = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
                paths = tuple(ShapePath(np.asarray(r.coords)[:-1] - c, True) for r in [poly.exterior, *poly.interiors])
                kinds.append(0)
                xs.append(c[0])
                ys.append(c[1])
                cells.append("face")
                labels.append(" ".join(sorted(labs)))
                parts.append([Shape(paths, style=style)])
    if pm.n_edges:
        pts = [t.edge_points[e] for e in range(pm.n_edges)]
        lines = np.array([shapely.LineString(p) for p in pts], dtype=object)
        b = shapely.bounds(lines)
        near = np.flatnonzero((b[:, 2] >= rect[0]) & (b[:, 0] <= rect[2]) & (b[:, 3] >= rect[1]) & (b[:, 1] <= rect[3]))
        drawn = None
        for e, piece in zip(near.tolist(), shapely.intersection(lines[near], box).tolist()):
            labs = t.edge_labels[e]
            if SEAM in labs:
                if labs == frozenset([SEAM]):
                    # only the seam (along the world's edge): drawn if a curve runs along it
                    if drawn is None:
                        drawn = _drawn_near(pm.curves, box)
                    if drawn.is_empty or not shapely.covered_by(piece, shapely.buffer(drawn, 1e-7 * max(size))):
                        continue
                labs = labs - {SEAM}
            style = {"fill": "none", "stroke": _label_color(labs, _STROKE_PALETTE) if labs else "#1d1f24", "stroke_width": stroke_width}
            for ln in shapely.get_parts(shapely.line_merge(piece) if piece.geom_type == "MultiLineString" else piece):
                if not isinstance(ln, shapely.LineString) or not (ln.length > 0):
                    continue
                for xy in _owned_runs(np.asarray(ln.coords), rect, size):
                    c = (xy.min(axis=0) + xy.max(axis=0)) / 2
                    kinds.append(1)
                    xs.append(c[0])
                    ys.append(c[1])
                    cells.append("edge")
                    labels.append(" ".join(sorted(labs)))
                    parts.append([Shape((ShapePath(xy - c, False),), style=style)])
    return Arrangement(_placeholder(), np.asarray(kinds, np.int64), xs, ys,
                       columns={"cell": np.asarray(cells, dtype=object), "labels": np.asarray(labels, dtype=object),
                                PARTS_COLUMN: parts},
                       meta={"method": "program"})


def _drawn_near(curves: Any, box: Any) -> Any:
    """The lines of ``curves`` (but the seam) that meet ``box``'s outline."""
    import shapely

    ring = box.exterior
    lines = [shapely.LineString(c.polyline) for c in curves.curves if SEAM not in c.labels and len(c.polyline) >= 2]
    arr = np.array(lines, dtype=object)
    if not len(arr):
        return shapely.LineString()
    hit = shapely.intersects(arr, shapely.buffer(ring, 1e-6))
    return shapely.union_all(arr[hit]) if hit.any() else shapely.LineString()


def evaluate_tile(script: Any, name: str, size: tuple[float, float], rect: tuple[float, float, float, float], halo: float,
                  seed: int) -> Any:
    """The cells of the world's planar map in tile ``rect`` (see the module docstring).

    The script runs on ``rect`` grown by ``halo`` (clipped to the world) with
    ``run_size() == max(W, H)``, as if it ran on the whole world.
    """
    from pathlib import Path

    import shapely

    from ..region import Region
    from ._context import Field, field_evaluation
    from ._script import ScriptError, _run_on

    path = Path(script)
    if not path.is_file():
        raise ScriptError(f"{str(script)!r}: no such script")
    w, h = size
    x0, y0, x1, y1 = rect
    grown = (max(0.0, x0 - halo), max(0.0, y0 - halo), min(w, x1 + halo), min(h, y1 + halo))
    region = Region(shapely.box(*grown))
    # the grown rectangle's outline closes the faces that reach beyond it (a face larger
    # than the halo, e.g. the gap left by deleted cells): their pieces in the tile are
    # still the world's faces there; it is a seam, not a line of the arrangement
    gx0, gy0, gx1, gy1 = grown
    seam = Curve(np.array([[gx0, gy0], [gx1, gy0], [gx1, gy1], [gx0, gy1]]), True, frozenset([SEAM]))
    # one script at a time per process: running a script swaps sys.argv, sys.path and
    # sys.modules["__main__"] (runpy), which threads of one Dask worker would share
    with _RUN_LOCK, field_evaluation(Field(region.geometry)):
        token = _TILE.set(_Tile(rect, grown, (w, h), halo))
        try:
            pm, _ = _run_on(path, name, region, int(seed), float(max(w, h)), convert=False, seam=seam)
        except InputError as exc:
            # the script's and mappers' wrappers prefix where it happened: say halo first
            cause: BaseException | None = exc
            while cause is not None and not isinstance(cause, HaloError):
                cause = cause.__cause__ or cause.__context__
            if cause is None:
                raise
            raise HaloError(f"{cause} ({path.name})") from None
        finally:
            _TILE.reset(token)
    return clip_cells(pm, rect, size, max(w, h) / 1000.0)


def run_tile(job: Any, t: Any) -> Any:
    """:func:`strew.tiles.run_tile` for program: one tile, independent of the others."""
    if job.periodic:
        raise InputError("periodic: a program world is not periodic; run the script with periodic=True (strew run --periodic) for a repeat tile")
    arr = evaluate_tile(job.input, job.params.get("name", "arrangement"), job.size, t.rect, job.halo, job.seed)
    return arr.replace(meta={"tile": t.index}, region=None)


def evaluate_world(script: Any, size: tuple[float, float], *, seed: int = 0, name: str = "arrangement") -> Any:
    """The whole world in one evaluation, as the tiles see it (the reference a tiled world
    is made of: the same sites, the same cells)."""
    w, h = float(size[0]), float(size[1])
    return evaluate_tile(script, name, (w, h), (0.0, 0.0, w, h), 0.0, seed)

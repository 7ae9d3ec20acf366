"""The growth's spatial index: point and edge grids and the crossing test (§5.4).

Split from the grower of :mod:`strew.grow._growth` (issue 15 point 7): the grower
decides what to grow (matching, seeding, the heuristics of Fig. 6, relaxation); this
class answers where things are:

- which seeds and elements lie within a distance of a point (Fig. 6 (b), the overlap
  guard, the closeness rules), :meth:`GrowIndex.near`;
- whether a new edge would cross an existing one (Fig. 6 (d), edge collision),
  :meth:`GrowIndex.crosses`, on the plane or on the torus of a repeat tile.

It also holds the connectivity graph (``adj``, the set ``edges``), since the edge grid
follows it.

Both grids are the shared hashed incremental grid (:class:`strew._kernels.grid.HashGrid`,
issue 15 point 5): unbounded cells of side ``cell`` hashed into a table of chains. A
point is listed in its cell; moving
it to another cell lists it anew and leaves the old entry stale, and removing it only
marks it gone. An edge is listed in every cell its bounding box covers; a moved endpoint
lists it anew (stale entries stay until the grid is rebuilt, and cost only a test).
Entries in a cell are met in the order they were made, the order the dict-of-lists grid
this replaced gave, so the growth is unchanged (same bytes for the same seed). A query
walks only the cells any entry was made in, so a disc far wider than the pattern costs no
more than the pattern.

The compiled kernels, point queries (one: :func:`strew.grow._index_kernels.near_one`;
many: the grid's :func:`~strew._kernels.grid.hash_near`) and the crossing test
(:func:`~strew._kernels.grid.hash_cross`), are numba's, cached; each first run on a fresh
install compiles them (issue 16).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from .._kernels.grid import GONE, HashGrid, hash_cross, hash_near
from ._index_kernels import cross_any, edge_insert, near_one

__all__ = ["GrowIndex"]


class GrowIndex:
    """Point grid, edge grid and connectivity of a growth.

    Parameters
    ----------
    cell : float
        Side of the grid cells.
    pos : (cap, 2) float
        The objects' positions (the grower's array; :meth:`rebind` after it grows).
    state : (cap,) int8
        The objects' states (DEAD, SEED, ELEMENT, OBSTACLE: 0-3), likewise.
    xy : list of (float, float)
        The same positions as Python floats (the grower's list, kept in step).
    """

    def __init__(self, cell: float, pos: np.ndarray, state: np.ndarray, xy: list[tuple[float, float]]) -> None:
        self.cell = float(cell)
        self.pos = pos
        self.state = state
        self.xy = xy
        self.points = HashGrid(self.cell, len(state))
        # buffer of single queries' answers (:func:`near_one`)
        self.out = np.zeros(len(state), dtype=np.int64)
        # edges: (end, end, original of the first, original of the second); ids by pair
        self.edge_cells = HashGrid(self.cell, 1024)
        self.ends = np.zeros((1024, 4), dtype=np.int64)
        self.n_edges = 0
        self.edge_id: dict[tuple[int, int], int] = {}
        self.adj: list[set[int]] = []
        self.edges: set[tuple[int, int]] = set()

    @property
    def n_live(self) -> int:
        """Objects in the point grid."""
        return self.points.live

    def rebind(self, pos: np.ndarray, state: np.ndarray) -> None:
        """The grower's arrays after they grew."""
        self.pos = pos
        self.state = state
        if len(state) > len(self.out):
            self.points.reserve(len(state))
            self.out = np.zeros(len(state), dtype=np.int64)

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        return (math.floor(x / self.cell), math.floor(y / self.cell))

    # -- points -------------------------------------------------------------------------
    def insert(self, i: int, x: float, y: float) -> None:
        """Object ``i`` at (x, y) joins the point grid."""
        self.points.insert_point(i, float(x), float(y))

    def remove(self, i: int) -> None:
        """Object ``i`` leaves the point grid (it died); no-op when not in it."""
        self.points.remove(i)

    def move(self, i: int, ox: float, oy: float, x: float, y: float) -> bool:
        """Object ``i`` moved from (ox, oy) to (x, y) (``pos`` and ``xy`` already say so);
        True when it changed cells (its edges are listed again)."""
        h = self.cell
        if math.floor(ox / h) == math.floor(x / h) and math.floor(oy / h) == math.floor(y / h):
            return False
        pts = self.points
        if pts.cur[i] != GONE:
            pts.insert_point(i, float(x), float(y))
        eid = self.edge_id
        for j in self.adj[i]:
            self._index_edge(eid[(i, j) if i < j else (j, i)], i, j)
        return True

    def near(self, x: float, y: float, r: float, states: int, limit: int = -1) -> list[int]:
        """Objects within ``r`` of (x, y) whose state ``s`` has bit ``1 << s`` in
        ``states``, in grid order; at most ``limit`` (-1: all)."""
        pts = self.points
        # (one query as scalars: hash_near's answer, four array arguments fewer)
        k = near_one(float(x), float(y), float(r), states, limit if limit > 0 else len(self.out), self.cell,
                     pts.head, pts.ent, pts.cur, pts.ext, self.pos, self.state, self.out)
        return self.out[:k].tolist()

    def near_many(self, xs: np.ndarray, ys: np.ndarray, rs: np.ndarray, states: int) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`near` for queries (m,) at once: the pairs (query index, object), (k,)
        each, ordered by query and, within one, as :meth:`near` gives them."""
        pts = self.points
        xs = np.ascontiguousarray(xs, dtype=np.float64)
        ys = np.ascontiguousarray(ys, dtype=np.float64)
        rs = np.ascontiguousarray(rs, dtype=np.float64)
        cap = max(64, 16 * len(xs))
        while True:
            oq = np.empty(cap, dtype=np.int64)
            oi = np.empty(cap, dtype=np.int64)
            k = hash_near(xs, ys, rs, states, len(self.out), self.cell, pts.head, pts.ent, pts.cur, pts.ext, self.pos, self.state, oq, oi)
            if k >= 0:
                return oq[:k], oi[:k]
            cap *= 4

    # -- edges --------------------------------------------------------------------------
    def _index_edge(self, e: int, a: int, b: int) -> None:
        """List edge ``e`` = (a, b) in every cell its bounding box covers."""
        ec = self.edge_cells
        if ec._ext is not None and ec.n < 2 * len(ec.head) and e < len(ec.cur):
            # HashGrid.insert's listing in one compiled call (the same entries, extent
            # and current listing; issue 14 point 5); its Python fields kept in step
            n, widened, new = edge_insert(ec.cell, ec.head, ec.tail, ec.ent, ec.ext, ec.n, ec.cur, e, self.pos, a, b)
            if n >= 0:
                ec.n = n
                if widened:
                    ec._ext[:] = ec.ext.tolist()
                if new:
                    ec.live += 1
                return
        xa, ya = self.xy[a]
        xb, yb = self.xy[b]
        ec.insert(e, min(xa, xb), min(ya, yb), max(xa, xb), max(ya, yb))

    def add_edge(self, a: int, b: int, oa: int, ob: int) -> None:
        """Edge (a, b), whose ends are images of originals ``oa``, ``ob``."""
        if a == b or b in self.adj[a]:
            return
        self.adj[a].add(b)
        self.adj[b].add(a)
        key = (a, b) if a < b else (b, a)
        self.edges.add(key)
        e = self.n_edges
        if e == len(self.ends):
            ends = np.zeros((2 * e, 4), dtype=np.int64)
            ends[:e] = self.ends
            self.ends = ends
        self.n_edges = e + 1
        self.ends[e] = (a, b, oa, ob)
        self.edge_id[key] = e
        self._index_edge(e, a, b)

    def remove_edge(self, a: int, b: int) -> None:
        self.adj[a].discard(b)
        self.adj[b].discard(a)
        key = (a, b) if a < b else (b, a)
        self.edges.discard(key)
        e = self.edge_id.pop(key, None)
        if e is not None:
            self.edge_cells.remove(e)

    def crosses_plane(self, ia: int, pa: Sequence[float], ib: int, pb: Sequence[float]) -> bool:
        """:meth:`crosses` on the plane (no tile), with the least Python around the kernel:
        the growth asks it for every new seed and edge."""
        ec = self.edge_cells
        if ec.n == 0:
            return False
        return hash_cross(float(pa[0]), float(pa[1]), float(pb[0]), float(pb[1]), ia, ib, self.cell, ec.head, ec.ent, ec.cur, ec.ext, self.ends, self.pos)

    def crosses_plane_any(self, ia: int, pa: Sequence[float], ibs: Sequence[int], pbs: Sequence[Sequence[float]]) -> bool:
        """:meth:`crosses_plane` of the segments from ``pa`` to each of ``pbs`` (ends
        ``ia``, ``ibs[k]``): does any cross an edge? One compiled call for all (the same
        answers; the tests are pure, so their order does not matter)."""
        ec = self.edge_cells
        if ec.n == 0 or not len(pbs):
            return False
        qs = np.array(pbs, dtype=np.float64).reshape(-1, 2)
        tbs = np.array(ibs, dtype=np.int64)
        return cross_any(float(pa[0]), float(pa[1]), qs, ia, tbs, self.cell, ec.head, ec.ent, ec.cur, ec.ext, self.ends, self.pos)

    def crosses(self, ia: int, pa: Sequence[float], ib: int, pb: Sequence[float], tile: tuple[float, float, float, float] | None = None, margin: float = 0.0) -> bool:
        """Edge collision (§5.4, Fig. 6d): does segment pa-pb cross an existing edge at a
        point interior to both? Edges at an image of original ``ia`` or ``ib`` (-2: none)
        do not count. On the torus of ``tile`` (x0, y0, W, H) the segment's images that
        reach within ``margin`` of the tile are tested (each edge is kept at both ends,
        so one image meets every edge that crosses it)."""
        ec = self.edge_cells
        if ec.n == 0:
            return False
        px, py = float(pa[0]), float(pa[1])
        qx, qy = float(pb[0]), float(pb[1])
        if tile is None:
            return hash_cross(px, py, qx, qy, ia, ib, self.cell, ec.head, ec.ent, ec.cur, ec.ext, self.ends, self.pos)
        x0, y0, w, h = tile
        m = margin
        lx, hx = min(px, qx), max(px, qx)
        ly, hy = min(py, qy), max(py, qy)
        for ki in (-1, 0, 1):
            dx = ki * w
            if hx + dx < x0 - m or lx + dx > x0 + w + m:
                continue
            for kj in (-1, 0, 1):
                dy = kj * h
                if hy + dy < y0 - m or ly + dy > y0 + h + m:
                    continue
                if hash_cross(px + dx, py + dy, qx + dx, qy + dy, ia, ib, self.cell, ec.head, ec.ent, ec.cur, ec.ext, self.ends, self.pos):
                    return True
        return False

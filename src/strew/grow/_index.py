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

Both grids are uniform cells of side ``cell`` hashed into one table of chains (flat
arrays: a chain links the entries of every cell with the same hash, in the order they
were made). A point has one current entry; moving it to another cell makes a new one and
leaves the old one stale, and removing it only marks it gone. An edge is listed in every
cell its bounding box covers; a moved endpoint lists it again (stale entries of its old
cells stay until the table is rebuilt, and cost only a test). Entries in a cell are met in
the order they were made, the order the dict-of-lists grid this replaces gave, so the
growth is unchanged (same bytes for the same seed). A query walks only the cells any
entry was made in, so a disc far wider than the pattern costs no more than the pattern.

Two compiled kernels (numba, cached): point queries (one or many) and the crossing test.
Each first run on a fresh install compiles them (issue 16), so they are few and small;
listing an item in the cells of its box stays in Python (a kernel for it cost 0.46 s of
CPU on a cold ``strew grow`` and gained nothing measurable).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numba
import numpy as np

from .._kernels.geometry import seg_cross

__all__ = ["GrowIndex"]

_HX = 73856093
_HY = 19349663


def _hash(cx: int, cy: int, mask: int) -> int:
    """Chain of cell (cx, cy); Python's integers give the low bits of numba's wrapping int64."""
    return ((cx * _HX) ^ (cy * _HY)) & mask


@numba.njit(cache=True, nogil=True)
def _near_kernel(xs, ys, rs, states, limit, h, head, ent, cur, ext, pos, state, out_q, out_i):  # pragma: no cover - compiled
    """Points within ``rs[q]`` of ``(xs[q], ys[q])`` whose state bit is set in ``states``,
    for each query q in turn, at most ``limit`` each, in cell order (x-major) and entry
    order within a cell: the pairs (q, point) in ``out_q, out_i``; their count, or -1
    when those are too short (the caller grows them and asks again). The cells walked
    are clipped to ``ext`` (x0, y0, x1, y1), the cells any entry was ever made in."""
    mask = head.shape[0] - 1
    k = 0
    cap = out_q.shape[0]
    for q in range(xs.shape[0]):
        x = xs[q]
        y = ys[q]
        r = rs[q]
        r2 = r * r
        found = 0
        # (comparisons, not min/max: each builtin is one more function to compile)
        cx0 = math.floor((x - r) / h)
        cy0 = math.floor((y - r) / h)
        cx1 = math.floor((x + r) / h)
        cy1 = math.floor((y + r) / h)
        if cx0 < ext[0]:
            cx0 = ext[0]
        if cy0 < ext[1]:
            cy0 = ext[1]
        if cx1 > ext[2]:
            cx1 = ext[2]
        if cy1 > ext[3]:
            cy1 = ext[3]
        for cx in range(cx0, cx1 + 1):
            for cy in range(cy0, cy1 + 1):
                e = head[((cx * _HX) ^ (cy * _HY)) & mask]
                while e >= 0 and found < limit:
                    if ent[e, 1] == cx and ent[e, 2] == cy:
                        i = ent[e, 0]
                        if cur[i] == e:
                            dx = pos[i, 0] - x
                            dy = pos[i, 1] - y
                            if dx * dx + dy * dy <= r2 and ((states >> state[i]) & 1) != 0:
                                if k >= cap:
                                    return -1
                                out_q[k] = q
                                out_i[k] = i
                                k += 1
                                found += 1
                    e = ent[e, 3]
    return k


@numba.njit(cache=True, nogil=True)
def _cross_kernel(px, py, qx, qy, ia, ib, h, head, ent, ends, alive, pos):  # pragma: no cover - compiled
    """Does segment pq cross, at a point interior to both, a live edge none of whose
    ends is an image of ``ia`` or ``ib`` (the originals' ids)?"""
    mask = head.shape[0] - 1
    lx, hx = (px, qx) if px <= qx else (qx, px)
    ly, hy = (py, qy) if py <= qy else (qy, py)
    for cx in range(math.floor(lx / h), math.floor(hx / h) + 1):
        for cy in range(math.floor(ly / h), math.floor(hy / h) + 1):
            e = head[((cx * _HX) ^ (cy * _HY)) & mask]
            while e >= 0:
                if ent[e, 1] == cx and ent[e, 2] == cy:
                    d = ent[e, 0]
                    ou = ends[d, 2]
                    ov = ends[d, 3]
                    if alive[d] and ou != ia and ou != ib and ov != ia and ov != ib:
                        u = ends[d, 0]
                        v = ends[d, 1]
                        if seg_cross(px, py, qx, qy, pos[u, 0], pos[u, 1], pos[v, 0], pos[v, 1]):
                            return True
                e = ent[e, 3]
    return False


class _Chains:
    """Entries (item, cell) in a hash table of chains over grid cells: ``ent`` (cap, 4)
    holds each entry's item, cell x, cell y and the next entry of its chain (-1: last)."""

    def __init__(self, table: int = 1024) -> None:
        self.head = np.full(table, -1, dtype=np.int64)
        self.tail = np.full(table, -1, dtype=np.int64)
        self.ent = np.full((1024, 4), -1, dtype=np.int64)
        self.n = 0

    def append_box(self, item: int, x0: float, y0: float, x1: float, y1: float, h: float) -> int:
        """List ``item`` in the cells of a box (x0 <= x1, y0 <= y1); its first entry.

        In Python, not compiled: a box covers one to four cells, and a kernel would cost
        its compilation on every fresh install (issue 16) for about the same speed."""
        first = e = self.n
        cx0, cx1 = math.floor(x0 / h), math.floor(x1 / h)
        cy0, cy1 = math.floor(y0 / h), math.floor(y1 / h)
        need = e + (cx1 - cx0 + 1) * (cy1 - cy0 + 1)
        ent = self.ent
        if need > len(ent):
            ent = np.full((2 * need, 4), -1, dtype=np.int64)
            ent[:e] = self.ent[:e]
            self.ent = ent
        head, tail = self.head, self.tail
        mask = len(head) - 1
        for cx in range(cx0, cx1 + 1):
            for cy in range(cy0, cy1 + 1):
                hh = ((cx * _HX) ^ (cy * _HY)) & mask
                ent[e] = (item, cx, cy, -1)
                t = tail[hh]
                if t >= 0:
                    ent[t, 3] = e
                else:
                    head[hh] = e
                tail[hh] = e
                e += 1
        self.n = e
        return first

    def rebuild(self, keep: np.ndarray, table: int) -> np.ndarray:
        """Keep the entries ``keep`` (bool, (n,)), in order, in a table of ``table``
        chains (a power of two); returns the kept entries' old indices."""
        old = np.flatnonzero(keep)
        m = len(old)
        cap = max(1024, 1 << int(2 * m - 1).bit_length()) if m else 1024
        ent = np.full((cap, 4), -1, dtype=np.int64)
        ent[:m, :3] = self.ent[old, :3]
        self.n = m
        hh = ((ent[:m, 1] * _HX) ^ (ent[:m, 2] * _HY)) & (table - 1)
        order = np.argsort(hh, kind="stable")
        hs = hh[order]
        same = hs[1:] == hs[:-1]
        ent[order[:-1][same], 3] = order[1:][same]
        self.ent = ent
        self.head = np.full(table, -1, dtype=np.int64)
        self.tail = np.full(table, -1, dtype=np.int64)
        if m:
            first = np.r_[True, ~same]
            last = np.r_[~same, True]
            self.head[hs[first]] = order[first]
            self.tail[hs[last]] = order[last]
        return old


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
        self.points = _Chains()
        self.cur = np.full(len(state), -1, dtype=np.int64)  # each object's current entry
        self.n_live = 0
        # the cells any entry was made in (x0, y0, x1, y1): queries walk no cell outside
        self.ext = np.array([0, 0, -1, -1], dtype=np.int64)
        self._ext: list[int] | None = None
        # buffers of single queries: the query, the pairs found
        self.qx, self.qy, self.qr = np.zeros(1), np.zeros(1), np.zeros(1)
        self.out_q = np.zeros(len(state), dtype=np.int64)
        self.out = np.zeros(len(state), dtype=np.int64)
        # edges: (end, end, original of the first, original of the second), alive; ids by pair
        self.edge_cells = _Chains()
        self.ends = np.zeros((1024, 4), dtype=np.int64)
        self.alive = np.zeros(1024, dtype=np.bool_)
        self.n_edges = 0
        self.edge_id: dict[tuple[int, int], int] = {}
        self.adj: list[set[int]] = []
        self.edges: set[tuple[int, int]] = set()

    def rebind(self, pos: np.ndarray, state: np.ndarray) -> None:
        """The grower's arrays after they grew."""
        self.pos = pos
        self.state = state
        if len(state) > len(self.cur):
            cur = np.full(len(state), -1, dtype=np.int64)
            cur[: len(self.cur)] = self.cur
            self.cur = cur
            self.out_q = np.zeros(len(state), dtype=np.int64)
            self.out = np.zeros(len(state), dtype=np.int64)

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        return (math.floor(x / self.cell), math.floor(y / self.cell))

    # -- points -------------------------------------------------------------------------
    def insert(self, i: int, x: float, y: float) -> None:
        """Object ``i`` at (x, y) joins the point grid."""
        pts = self.points
        if self.cur[i] < 0:
            self.n_live += 1
        if pts.n >= 2 * len(pts.head):
            self._rebuild_points()
        x, y = float(x), float(y)
        h = self.cell
        cx, cy = math.floor(x / h), math.floor(y / h)
        ext = self._ext
        if ext is None:
            self._ext = ext = [cx, cy, cx, cy]
            self.ext[:] = ext
        elif cx < ext[0] or cy < ext[1] or cx > ext[2] or cy > ext[3]:
            ext[:] = [min(cx, ext[0]), min(cy, ext[1]), max(cx, ext[2]), max(cy, ext[3])]
            self.ext[:] = ext
        self.cur[i] = pts.append_box(i, x, y, x, y, h)

    def remove(self, i: int) -> None:
        """Object ``i`` leaves the point grid (it died); no-op when not in it."""
        if self.cur[i] >= 0:
            self.cur[i] = -1
            self.n_live -= 1

    def move(self, i: int, ox: float, oy: float, x: float, y: float) -> bool:
        """Object ``i`` moved from (ox, oy) to (x, y) (``pos`` and ``xy`` already say so);
        True when it changed cells (its edges are listed again)."""
        h = self.cell
        if math.floor(ox / h) == math.floor(x / h) and math.floor(oy / h) == math.floor(y / h):
            return False
        if self.cur[i] >= 0:
            self.remove(i)
            self.insert(i, x, y)
        eid = self.edge_id
        for j in self.adj[i]:
            self._index_edge(eid[(i, j) if i < j else (j, i)], i, j)
        return True

    def _rebuild_points(self) -> None:
        pts = self.points
        n = pts.n
        keep = self.cur[pts.ent[:n, 0]] == np.arange(n)
        table = max(1024, 1 << int(max(int(keep.sum()), 1)).bit_length())
        old = pts.rebuild(keep, table)
        self.cur[pts.ent[: len(old), 0]] = np.arange(len(old))

    def near(self, x: float, y: float, r: float, states: int, limit: int = -1) -> list[int]:
        """Objects within ``r`` of (x, y) whose state ``s`` has bit ``1 << s`` in
        ``states``, in grid order; at most ``limit`` (-1: all)."""
        pts = self.points
        self.qx[0] = x
        self.qy[0] = y
        self.qr[0] = r
        k = _near_kernel(self.qx, self.qy, self.qr, states, limit if limit > 0 else len(self.out), self.cell,
                         pts.head, pts.ent, self.cur, self.ext, self.pos, self.state, self.out_q, self.out)
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
            k = _near_kernel(xs, ys, rs, states, len(self.out), self.cell, pts.head, pts.ent, self.cur, self.ext, self.pos, self.state, oq, oi)
            if k >= 0:
                return oq[:k], oi[:k]
            cap *= 4

    # -- edges --------------------------------------------------------------------------
    def _index_edge(self, e: int, a: int, b: int) -> None:
        """List edge ``e`` = (a, b) in every cell its bounding box covers."""
        xa, ya = self.xy[a]
        xb, yb = self.xy[b]
        ec = self.edge_cells
        if ec.n >= 2 * len(ec.head):
            self._rebuild_edges()
        ec.append_box(e, min(xa, xb), min(ya, yb), max(xa, xb), max(ya, yb), self.cell)

    def _rebuild_edges(self) -> None:
        """Drop the entries of removed edges and of cells an edge no longer covers."""
        ec = self.edge_cells
        n = ec.n
        e = ec.ent[:n, 0]
        keep = self.alive[e].copy()
        if keep.any():
            h = self.cell
            pu = np.floor(self.pos[self.ends[e, 0]] / h).astype(np.int64)
            pv = np.floor(self.pos[self.ends[e, 1]] / h).astype(np.int64)
            lo, hi = np.minimum(pu, pv), np.maximum(pu, pv)
            cx, cy = ec.ent[:n, 1], ec.ent[:n, 2]
            keep &= (cx >= lo[:, 0]) & (cx <= hi[:, 0]) & (cy >= lo[:, 1]) & (cy <= hi[:, 1])
            # one entry per (edge, cell)
            sel = np.flatnonzero(keep)
            _, first = np.unique(ec.ent[sel, :3], axis=0, return_index=True)
            keep[:] = False
            keep[sel[first]] = True
        m = int(keep.sum())
        ec.rebuild(keep, max(1024, 1 << int(max(m, 1)).bit_length()))

    def add_edge(self, a: int, b: int, oa: int, ob: int) -> None:
        """Edge (a, b), whose ends are images of originals ``oa``, ``ob``."""
        if a == b or b in self.adj[a]:
            return
        self.adj[a].add(b)
        self.adj[b].add(a)
        key = (a, b) if a < b else (b, a)
        self.edges.add(key)
        e = self.n_edges
        if e == len(self.alive):
            ends = np.zeros((2 * e, 4), dtype=np.int64)
            ends[:e] = self.ends
            alive = np.zeros(2 * e, dtype=np.bool_)
            alive[:e] = self.alive
            self.ends, self.alive = ends, alive
        self.n_edges = e + 1
        self.ends[e] = (a, b, oa, ob)
        self.alive[e] = True
        self.edge_id[key] = e
        self._index_edge(e, a, b)

    def remove_edge(self, a: int, b: int) -> None:
        self.adj[a].discard(b)
        self.adj[b].discard(a)
        key = (a, b) if a < b else (b, a)
        self.edges.discard(key)
        e = self.edge_id.pop(key, None)
        if e is not None:
            self.alive[e] = False

    def crosses_plane(self, ia: int, pa: Sequence[float], ib: int, pb: Sequence[float]) -> bool:
        """:meth:`crosses` on the plane (no tile), with the least Python around the kernel:
        the growth asks it for every new seed and edge."""
        ec = self.edge_cells
        if ec.n == 0:
            return False
        return _cross_kernel(float(pa[0]), float(pa[1]), float(pb[0]), float(pb[1]), ia, ib, self.cell, ec.head, ec.ent, self.ends, self.alive, self.pos)

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
            return _cross_kernel(px, py, qx, qy, ia, ib, self.cell, ec.head, ec.ent, self.ends, self.alive, self.pos)
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
                if _cross_kernel(px + dx, py + dy, qx + dx, qy + dy, ia, ib, self.cell, ec.head, ec.ent, self.ends, self.alive, self.pos):
                    return True
        return False

"""Planar maps induced from labelled curves (Loi et al. §4).

The planar map of a collection of curves is the set of cells partitioning the plane:

- *edges*: the maximal pairwise-disjoint subcurves, each oriented by the curve it comes
  from (source and target vertex);
- *vertices*: the end points of edges (crossings, curve ends, and the first point of a
  closed curve, which needs one vertex);
- *faces*: the maximal connected parts of the plane minus the curves; face 0 is the
  unbounded face;
- an incidence graph between them, and labels on every cell.

Robustness (§4 "Implementation"). The paper uses CGAL with exact rationals. Here every
curve is snap-rounded onto a precision grid (``grid``, default 1e-6 units) by GEOS'
fixed-precision overlay (``shapely.union_all(..., grid_size=grid)``), which nodes all
crossings and merges overlapping pieces; every vertex then has integer grid
coordinates, so two vertices closer than the grid are one vertex, no duplicate vertex
appears, and faces are built by ``shapely.polygonize`` from exactly those coordinates.

Face labels (§4 "Face labels reconstruction", after Asente et al. [3]) are stored on
curves (each curve's left and right side labels) and rebuilt here: a face gets the side
labels of every edge side facing it. Edges that carry no label on either side (curves
drawn without face labels, e.g. imported drawings) are transparent: the faces they
separate inherit the labels of the face they split, so that labels survive re-noding
and merging. The unbounded face never has labels.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from ._curves import EMPTY, Curve, Curves

__all__ = ["PlanarMap", "Vertex", "Edge", "Face", "induce", "DEFAULT_GRID"]

#: Precision grid (document units) onto which every planar map is snap-rounded.
DEFAULT_GRID = 1e-6


def _hash_bytes(tag: bytes, data: bytes) -> bytes:
    return hashlib.blake2b(tag + b"\0" + data, digest_size=16).digest()


class _Ragged:
    """A read-only sequence of (n_k, 2) arrays kept as one flat array and offsets.

    Compact storage of the edges' polylines (issue 19.6: a tuple of small arrays cost
    about 200 bytes of array headers per edge): ``r[k]`` is a view (or, with ``scale``,
    the grid coordinates times ``scale``), ``len(r)`` the number of items.

    Parameters
    ----------
    flat : (N, 2) array
        Every item's rows, one after the other.
    offsets : (K + 1,) int64
        Item ``k`` is ``flat[offsets[k]:offsets[k + 1]]``.
    scale : float or None
        Multiplies every item on access (grid coordinates to positions).
    """

    __slots__ = ("flat", "offsets", "scale")

    def __init__(self, flat: np.ndarray, offsets: np.ndarray, scale: float | None = None) -> None:
        self.flat = flat
        self.offsets = offsets
        self.scale = scale

    def __len__(self) -> int:
        return len(self.offsets) - 1

    def __getitem__(self, k: int) -> np.ndarray:
        n = len(self.offsets) - 1
        k = int(k)
        if k < 0:
            k += n
        if not 0 <= k < n:
            raise IndexError(k)
        a = self.flat[self.offsets[k] : self.offsets[k + 1]]
        return a if self.scale is None else a * self.scale

    def __iter__(self) -> Any:
        for k in range(len(self)):
            yield self[k]

    def lengths(self) -> np.ndarray:
        """(K,) rows per item."""
        return np.diff(self.offsets)

    def all_rows(self) -> np.ndarray:
        """(N, 2) every item's rows, concatenated (scaled)."""
        return self.flat if self.scale is None else self.flat * self.scale


@dataclass(frozen=True)
class _Topology:
    grid: float
    vertex_ij: np.ndarray  # (V, 2) int64 grid coordinates
    vertex_labels: tuple[frozenset[str], ...]
    edge_points: _Ragged | tuple[np.ndarray, ...]  # each (n, 2) float
    edge_ij: _Ragged | tuple[np.ndarray, ...]  # each (n, 2) int64
    edge_source: np.ndarray  # (E,) int
    edge_target: np.ndarray  # (E,) int
    edge_left: np.ndarray  # (E,) int face index
    edge_right: np.ndarray  # (E,) int face index
    edge_labels: tuple[frozenset[str], ...]
    face_polygons: tuple[Any, ...]  # (F,) shapely Polygon, None for the unbounded face 0
    face_labels: tuple[frozenset[str], ...]


class PlanarMap:
    """The planar map induced from a collection of curves (§4).

    Induction is lazy: the curves are kept, and the map is built on the first query. An
    arrangement evaluated on a region returns a PlanarMap; a mapper may return one (the
    result of ``arrangement(face)``), which contributes its curves.

    Parameters
    ----------
    curves : Curves
    grid : float
        Precision grid of the snap rounding.

    Attributes
    ----------
    n_vertices, n_edges, n_faces : int
        Cell counts; ``n_faces`` counts the unbounded face.
    """

    def __init__(self, curves: Curves, grid: float = DEFAULT_GRID) -> None:
        if not isinstance(curves, Curves):
            raise InputError(f"planar map: expected Curves, got {type(curves).__name__}")
        if not (grid > 0):
            raise InputError(f"planar map: grid must be positive, got {grid!r}")
        self.curves = curves
        self.grid = float(grid)

    @cached_property
    def _t(self) -> _Topology:
        return _induce(self.curves, self.grid)

    # -- counts and cells ---------------------------------------------------------------
    @property
    def n_vertices(self) -> int:
        return len(self._t.vertex_ij)

    @property
    def n_edges(self) -> int:
        return len(self._t.edge_points)

    @property
    def n_faces(self) -> int:
        return len(self._t.face_polygons)

    @property
    def vertices(self) -> list[Vertex]:
        return [Vertex(self, i) for i in range(self.n_vertices)]

    @property
    def edges(self) -> list[Edge]:
        return [Edge(self, i) for i in range(self.n_edges)]

    @property
    def faces(self) -> list[Face]:
        """Every face; ``faces[0]`` is the unbounded face."""
        return [Face(self, i) for i in range(self.n_faces)]

    @property
    def bounded_faces(self) -> list[Face]:
        return [Face(self, i) for i in range(1, self.n_faces)]

    @property
    def unbounded_face(self) -> Face:
        return Face(self, 0)

    @property
    def vertex_xy(self) -> np.ndarray:
        """(V, 2) vertex positions."""
        return self._t.vertex_ij * self.grid

    def face_areas(self) -> np.ndarray:
        """(F - 1,) areas of the bounded faces."""
        return np.array([p.area for p in self._t.face_polygons[1:]], dtype=float)

    # -- incidence (§4, Fig. 4) -----------------------------------------------------------
    @cached_property
    def _vertex_edges(self) -> list[list[int]]:
        t = self._t
        out: list[list[tuple[float, int]]] = [[] for _ in range(self.n_vertices)]
        for e, pts in enumerate(t.edge_points):
            s, d = int(t.edge_source[e]), int(t.edge_target[e])
            a0 = pts[1] - pts[0]
            out[s].append((float(np.arctan2(a0[1], a0[0])), e))
            a1 = pts[-2] - pts[-1]
            out[d].append((float(np.arctan2(a1[1], a1[0])), e))
        res = []
        for lst in out:
            lst.sort()
            seen: list[int] = []
            for _, e in lst:
                if e not in seen:
                    seen.append(e)
            res.append(seen)
        return res

    @cached_property
    def _face_edges(self) -> list[list[int]]:
        t = self._t
        res: list[list[int]] = [[] for _ in range(self.n_faces)]
        for e in range(self.n_edges):
            for f in (int(t.edge_left[e]), int(t.edge_right[e])):
                if e not in res[f][-1:]:
                    res[f].append(e)
        # order along the boundary: by angle about the face's centroid (local, stationary)
        for f in range(1, self.n_faces):
            c = np.asarray(t.face_polygons[f].centroid.coords[0])

            def key(e: int, c: np.ndarray = c) -> float:
                m = t.edge_points[e][len(t.edge_points[e]) // 2] - c
                if len(t.edge_points[e]) == 2:
                    m = t.edge_points[e].mean(axis=0) - c
                return float(np.arctan2(m[1], m[0]))

            res[f] = sorted(dict.fromkeys(res[f]), key=key)
        return res

    def cell_key(self, kind: str, i: int) -> bytes:
        """A digest of a cell's own geometry (grid coordinates), independent of its index.

        Per-cell random values (§6.1) are functions of this key, so they do not depend on
        the order of cells, on execution order, or on the rest of the map.
        """
        t = self._t
        from ._context import periodic

        per = periodic()
        if per is not None and not (kind == "face" and i == 0):
            return self._periodic_key(kind, i, per)
        if kind == "vertex":
            return _hash_bytes(b"v", t.vertex_ij[i].tobytes())
        if kind == "edge":
            ij = t.edge_ij[i]
            fwd, bwd = ij.tobytes(), ij[::-1].tobytes()
            return _hash_bytes(b"e", min(fwd, bwd))
        if i == 0:
            return _hash_bytes(b"f", b"unbounded")
        poly = t.face_polygons[i]
        ij = np.rint(shapely.get_coordinates(poly) / t.grid).astype(np.int64)
        ij = ij[np.lexsort((ij[:, 1], ij[:, 0]))]
        ij = ij[np.r_[True, np.any(ij[1:] != ij[:-1], axis=1)]]
        return _hash_bytes(b"f", np.ascontiguousarray(ij).tobytes())

    def _periodic_key(self, kind: str, i: int, per: Any) -> bytes:
        """:meth:`cell_key` on a periodic tile (issue 18): the same for a cell and its
        translates by whole periods, so that they draw the same random values.

        The cell is moved into the tile (by the periods that take its centre there) and
        quantised on a grid of 1e-5 of the tile's size, coarser than the map's own grid,
        so that a translate computed with other rounding still gives the same digest.
        """
        t = self._t
        q = 1e-5 * max(per.tile[2], per.tile[3])
        if kind == "vertex":
            pts = t.vertex_ij[i][None, :] * t.grid
        elif kind == "edge":
            pts = t.edge_points[i]
        else:
            pts = shapely.get_coordinates(t.face_polygons[i])
        c = 0.5 * (pts.min(axis=0) + pts.max(axis=0))
        # the window that decides the shift is offset by an odd fraction of the tile, so
        # that no regular partition puts centres on its edge (where rounding would pick
        # different periods for a cell and its translate)
        sx, sy = per.shift(float(c[0]) - 0.3183098861837907 * per.tile[2], float(c[1]) - 0.3183098861837907 * per.tile[3])
        ij = np.rint((pts - np.array([sx, sy])) / q).astype(np.int64)
        tag = kind[0].encode() + b"p"
        if kind == "edge":
            return _hash_bytes(tag, min(ij.tobytes(), ij[::-1].tobytes()))
        if kind == "face":
            ij = ij[np.lexsort((ij[:, 1], ij[:, 0]))]
            ij = ij[np.r_[True, np.any(ij[1:] != ij[:-1], axis=1)]]
        return _hash_bytes(tag, np.ascontiguousarray(ij).tobytes())

    @cached_property
    def vertex_index(self) -> dict[tuple[int, int], int]:
        """Vertex index by grid coordinates ``(round(x / grid), round(y / grid))``."""
        return {(int(x), int(y)): k for k, (x, y) in enumerate(self._t.vertex_ij.tolist())}

    def __repr__(self) -> str:
        if "_t" not in self.__dict__:
            return f"PlanarMap({len(self.curves)} curves, not yet induced)"
        return f"PlanarMap({self.n_vertices} vertices, {self.n_edges} edges, {self.n_faces} faces)"


class _Cell:
    """A cell of a planar map, seen by mappers only through the built-in operators."""

    __slots__ = ("_map", "_i")
    kind = "cell"

    def __init__(self, pmap: PlanarMap, index: int) -> None:
        self._map = pmap
        self._i = int(index)

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other._map is self._map and other._i == self._i  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash((type(self).__name__, id(self._map), self._i))

    @property
    def key(self) -> bytes:
        return self._map.cell_key(self.kind, self._i)

    def __repr__(self) -> str:
        labs = getattr(self, "labels", EMPTY)
        labs = f" {sorted(labs)}" if labs else ""
        return f"<{type(self).__name__}{labs}>"


class Vertex(_Cell):
    """A vertex of a planar map."""

    __slots__ = ()
    kind = "vertex"

    @property
    def labels(self) -> frozenset[str]:
        return self._map._t.vertex_labels[self._i]

    @property
    def xy(self) -> np.ndarray:
        return self._map._t.vertex_ij[self._i] * self._map.grid


class Edge(_Cell):
    """An edge of a planar map: a maximal subcurve, oriented by its source curve."""

    __slots__ = ()
    kind = "edge"

    @property
    def labels(self) -> frozenset[str]:
        return self._map._t.edge_labels[self._i]

    @property
    def points(self) -> np.ndarray:
        """(n, 2) the polyline from source to target."""
        return self._map._t.edge_points[self._i]


class Face(_Cell):
    """A face of a planar map; the unbounded face has no polygon."""

    __slots__ = ()
    kind = "face"

    @property
    def labels(self) -> frozenset[str]:
        return self._map._t.face_labels[self._i]

    @property
    def is_unbounded(self) -> bool:
        return self._i == 0

    @property
    def polygon(self) -> shapely.Polygon | None:
        """The face as a shapely Polygon (with holes); None for the unbounded face."""
        return self._map._t.face_polygons[self._i]


def induce(curves: Curves, grid: float = DEFAULT_GRID) -> PlanarMap:
    """The planar map induced from ``curves`` (built at once, not lazily)."""
    pm = PlanarMap(curves, grid)
    _ = pm._t
    return pm


# -- construction -------------------------------------------------------------------------
def _unique_rows(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(a, axis=0, return_inverse=True)`` for (n, 2) int rows, by lexsort."""
    if len(a) == 0:
        return a.reshape(0, 2), np.zeros(0, dtype=np.int64)
    order = np.lexsort((a[:, 1], a[:, 0]))
    s = a[order]
    flag = np.empty(len(s), dtype=bool)
    flag[0] = True
    np.any(s[1:] != s[:-1], axis=1, out=flag[1:])
    ids = np.cumsum(flag) - 1
    inv = np.empty(len(a), dtype=np.int64)
    inv[order] = ids
    return s[flag], inv


def _match_rows(table: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (i, j) with ``table[i] == rows[j]``; ``table`` holds unique (n, 2) int rows."""
    if len(rows) == 0 or len(table) == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    _, inv = _unique_rows(np.concatenate([table, rows]))
    pos = np.full(int(inv.max()) + 1, -1, dtype=np.int64)
    pos[inv[: len(table)]] = np.arange(len(table))
    hit = pos[inv[len(table) :]]
    j = np.flatnonzero(hit >= 0)
    return hit[j], j


def _empty_topology(grid: float) -> _Topology:
    return _Topology(
        grid,
        np.zeros((0, 2), dtype=np.int64),
        (),
        (),
        (),
        np.zeros(0, dtype=np.int64),
        np.zeros(0, dtype=np.int64),
        np.zeros(0, dtype=np.int64),
        np.zeros(0, dtype=np.int64),
        (),
        (None,),
        (EMPTY,),
    )


#: Above this many source segments the curves are noded strip by strip (issue 19.6): GEOS'
#: overlay holds about 3 KB per segment while it nodes, the planar map's memory peak.
CHUNK_SEGMENTS = 4096


def _pieces_along(ca: np.ndarray, cb: np.ndarray, tree: Any, sa: np.ndarray, sb: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (noded piece, source segment) with the piece lying along the segment.

    ``ca``, ``cb``: (m, 2) piece ends; ``tree``: an STRtree of the source segments
    ``sa``-``sb`` ((n, 2) each). A piece lies along a segment when both its ends are
    within ``tol`` of it; a piece along none takes its nearest segment. Returns
    (piece indices, segment indices), (k,) each.
    """
    mids = shapely.points((ca + cb) / 2)
    qi, qj = tree.query(mids, predicate="dwithin", distance=tol)
    from .._kernels.geometry import point_segment_distance  # the shared rule (issue 15.5); numba loads here, not on import
    ok = (point_segment_distance(ca[qi], sa[qj], sb[qj]) <= tol) & (point_segment_distance(cb[qi], sa[qj], sb[qj]) <= tol)
    qi, qj = qi[ok], qj[ok]
    covered = np.zeros(len(ca), dtype=bool)
    covered[qi] = True
    missing = np.flatnonzero(~covered)
    if len(missing):
        mi, mj = tree.query_nearest(mids[missing], return_distance=False)
        qi = np.r_[qi, missing[mi]]
        qj = np.r_[qj, mj]
    return qi, qj


def _noded_segments(noded: Any, g: float) -> tuple[np.ndarray, np.ndarray]:
    """The non-degenerate segments ``(a_ij, b_ij)``, each (m, 2) int64 grid coordinates,
    of GEOS' noded linework ``noded``."""
    coords, idx = shapely.get_coordinates(shapely.get_parts(noded), return_index=True)
    ij = np.rint(coords / g).astype(np.int64)
    same = idx[1:] == idx[:-1]
    a, b = ij[:-1][same], ij[1:][same]
    nz = np.any(a != b, axis=1)
    return a[nz], b[nz]


def _node_in_strips(a: np.ndarray, b: np.ndarray, curve: np.ndarray, g: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Snap-round and node segments strip by strip (issue 19.6: memory), and attribute the
    noded pieces to the source segments they lie along.

    GEOS' overlay nodes the whole linework at once and holds about 3 KB per segment while it
    does so (4.4 KB per segment of peak RSS in all at 40k random segments). Here each
    segment is *owned* by the vertical strip its midpoint falls in (strips of about
    ``CHUNK_SEGMENTS / 2`` segments), and each strip is noded on its own with every segment
    whose box comes within 6 grid pixels of the box of a segment it owns. Every segment
    that crosses an owned segment, and every vertex or crossing whose hot pixel an owned
    segment passes through, is then in the strip's input, so GEOS' snap rounding (hot
    pixels, a local rule) nodes an owned segment exactly as one global run would; a strip
    keeps the noded pieces lying along an owned segment. A piece shared by two strips (two
    overlapping segments of two owners) is kept once. Segments are never cut, so the result
    is the global noding, not an approximation of it.

    Which pieces a strip keeps is decided by one attribution of every strip's pieces to all
    source segments (:func:`_pieces_along`), the same that ``_induce`` needs for the kept
    pieces: attributing in every strip and again globally cost the Fig. 11(d) mosaic 1.25-1.45x
    the CPU of one global noding (issue 19.6). A piece lying along a segment lies along it
    wherever it is tested, so the kept pieces are those of a per-strip test.

    Parameters
    ----------
    a, b : (n, 2) int64
        Source segments in grid coordinates, curve by curve, in order along each curve.
    curve : (n,) int
        The curve of each segment.
    g : float
        The grid.

    Returns
    -------
    na, nb : (s, 2) int64
        Noded segments, each once (``na`` <= ``nb`` lexicographically).
    qi, qj : (k,) int64
        The pairs (noded segment, source segment) of :func:`_pieces_along` for them.
    """
    n = len(a)
    k = max(2, int(np.ceil(n / (CHUNK_SEGMENTS / 2))))
    mid2 = a[:, 0] + b[:, 0]  # twice the midpoint's x
    order = np.argsort(mid2, kind="stable")
    cuts = np.arange(k + 1) * n // k  # strip s owns the segments of ranks cuts[s]:cuts[s + 1]
    owner = np.empty(n, dtype=np.int64)
    owner[order] = np.repeat(np.arange(k), np.diff(cuts))
    # a strip's input: the segments whose boxes come within 6 grid pixels of the box of one
    # it owns (a superset of those within 6 pixels of it; not an x-range:
    # a long line owned by a strip would bring in everything). 6 > the attribution
    # tolerance (4) + a hot pixel's reach (0.71): a piece kept as lying along an owned
    # segment lies within 4 pixels of it, so every crossing or vertex that can node or
    # snap that piece comes from segments in the input
    lines = shapely.linestrings(np.stack([a, b], axis=1) * g)
    index = shapely.STRtree(lines)
    outs: list[np.ndarray] = []
    for s in range(k):
        own = order[cuts[s] : cuts[s + 1]]
        if not len(own):
            continue
        lo_, hi_ = np.minimum(a[own], b[own]) * g - 6.0 * g, np.maximum(a[own], b[own]) * g + 6.0 * g
        sel = np.unique(np.r_[own, index.query(shapely.box(lo_[:, 0], lo_[:, 1], hi_[:, 0], hi_[:, 1]))[1]])
        del lo_, hi_
        sa = a[sel] * g
        # consecutive segments of one curve go to GEOS as one polyline (as in the global
        # noding: the same vertices, and GEOS nodes polylines much faster than their segments)
        brk = np.r_[True, (np.diff(sel) != 1) | (curve[sel][1:] != curve[sel][:-1])]
        gid = np.cumsum(brk) - 1
        ends = np.flatnonzero(np.r_[brk[1:], True])
        pts = np.insert(sa, ends + 1, b[sel[ends]] * g, axis=0)
        noded = shapely.union_all(shapely.linestrings(pts, indices=np.insert(gid, ends + 1, gid[ends])), grid_size=g)
        del brk, gid, ends, pts, sa, sel
        na, nb = _noded_segments(noded, g)
        del noded
        if len(na):
            seg = np.c_[na, nb, np.full(len(na), s, dtype=np.int64)]
            swap = (seg[:, 0] > seg[:, 2]) | ((seg[:, 0] == seg[:, 2]) & (seg[:, 1] > seg[:, 3]))
            seg[swap, :4] = seg[swap][:, [2, 3, 0, 1]]
            outs.append(seg)
    if not outs:
        del index, lines
        z = np.zeros((0, 2), np.int64)
        return z, z, np.zeros(0, np.int64), np.zeros(0, np.int64)
    rows = np.concatenate(outs)
    del outs
    # every strip's pieces against every source segment, in batches (memory); a strip keeps
    # a piece lying along one of its own segments (or nearest one, when it lies along none)
    sa, sb = a * g, b * g
    tol = 4.0 * g
    tree = index  # the tree of every source segment
    keep = np.zeros(len(rows), dtype=bool)
    qis, qjs = [], []
    for c0 in range(0, len(rows), CHUNK_SEGMENTS):
        c = rows[c0 : c0 + CHUNK_SEGMENTS]
        qi, qj = _pieces_along(c[:, :2] * g, c[:, 2:4] * g, tree, sa, sb, tol)
        keep[c0 + qi[owner[qj] == c[qi, 4]]] = True
        qis.append(qi + c0)
        qjs.append(qj)
    del tree, index, lines, sa, sb
    qi, qj = np.concatenate(qis), np.concatenate(qjs)
    del qis, qjs
    # the kept pieces, each once; a piece's pairs depend on its geometry only, so those of
    # its first kept row stand for it
    kept = np.flatnonzero(keep)
    seg, first, inv = np.unique(rows[kept, :4], axis=0, return_index=True, return_inverse=True)
    uid = np.full(len(rows), -1, dtype=np.int64)
    uid[kept[first]] = np.arange(len(seg))
    del rows, keep, kept, first, inv
    ok = uid[qi] >= 0
    qi, qj = uid[qi[ok]], qj[ok]
    return np.ascontiguousarray(seg[:, :2]), np.ascontiguousarray(seg[:, 2:]), qi, qj


def _ring_edges(source: np.ndarray, target: np.ndarray, n_v: int) -> np.ndarray:
    """Indices of the edges left after pruning dangles again and again (an edge with an end
    of degree one cannot bound a face), in increasing order."""
    deg = np.bincount(source, minlength=n_v) + np.bincount(target, minlength=n_v)
    alive = np.ones(len(source), dtype=bool)
    inc_off = np.r_[0, np.cumsum(deg)]
    inc = np.argsort(np.concatenate([source, target]), kind="stable") % max(len(source), 1)
    stack = np.flatnonzero(deg == 1).tolist()
    deg_l = deg.tolist()
    src_l, tgt_l = source.tolist(), target.tolist()
    while stack:
        v = stack.pop()
        if deg_l[v] != 1:
            continue
        for e in inc[inc_off[v] : inc_off[v + 1]].tolist():
            if alive[e]:
                alive[e] = False
                for w in (src_l[e], tgt_l[e]):
                    deg_l[w] -= 1
                    if deg_l[w] == 1:
                        stack.append(w)
                break
    return np.flatnonzero(alive)


def _induce(curves: Curves, grid: float) -> _Topology:
    g = grid
    # 1. source segments, one row per segment of every curve
    polylines = [c.polyline for c in curves.curves]
    if not polylines:
        return _empty_topology(g)
    lens = np.fromiter((len(p) for p in polylines), dtype=np.int64, count=len(polylines))
    allp = np.concatenate(polylines) if lens.sum() else np.zeros((0, 2))
    # round every input point onto the grid first, so that copies of one curve that
    # differ by less than the grid (a curve and its own snapped outline) are identical
    # before snap rounding, and are noded identically (no sliver between them)
    allp = np.rint(allp / g) * g
    cid = np.repeat(np.arange(len(polylines)), lens)
    # drop repeated consecutive points, then curves left with fewer than two points
    keep = np.ones(len(allp), dtype=bool)
    if len(allp) > 1:
        keep[1:] = (cid[1:] != cid[:-1]) | np.any(allp[1:] != allp[:-1], axis=1)
    allp, cid = allp[keep], cid[keep]
    cnt = np.bincount(cid, minlength=len(polylines))
    ok = cnt[cid] >= 2
    allp, cid = allp[ok], cid[ok]
    if len(allp) == 0:
        return _empty_topology(g)
    same_next = cid[1:] == cid[:-1]
    sa, sb, scurve = allp[:-1][same_next], allp[1:][same_next], cid[:-1][same_next]
    first_pt = np.r_[True, ~same_next]
    last_pt = np.r_[~same_next, True]
    breaks = [allp[first_pt], allp[last_pt]]
    src_lines = shapely.linestrings(allp, indices=np.unique(cid, return_inverse=True)[1].reshape(-1))
    # (intermediates are dropped as soon as they are used: peak memory per segment, 19.6)
    del allp, cid, keep, cnt, ok, same_next, first_pt, last_pt

    # 2. snap rounding + noding + merging of overlaps (GEOS OverlayNG, fixed precision)
    # GEOS nodes the curves faster when neighbours come together (about 30% at 40k random
    # segments, issue 19.6): curves in the order of the cells of a coarse grid that their
    # centres fall in (row by row, snaking). The map does not depend on this order: every
    # cell is numbered from its grid coordinates below.
    if len(src_lines) > 256:
        b = shapely.bounds(src_lines)
        c = 0.5 * (b[:, :2] + b[:, 2:])
        k = max(1, int(np.sqrt(len(src_lines) / 64)))
        lo, span = c.min(axis=0), np.maximum(np.ptp(c, axis=0), 1e-300)
        cx = np.minimum((k * (c[:, 0] - lo[0]) / span[0]).astype(np.int64), k - 1)
        cy = np.minimum((k * (c[:, 1] - lo[1]) / span[1]).astype(np.int64), k - 1)
        src_lines = src_lines[np.lexsort((np.where(cy % 2 == 1, -cx, cx), cy))]
        del b, c, cx, cy
    if len(sa) > CHUNK_SEGMENTS:
        del src_lines
        # the strips also attribute the pieces (step 3)
        na_ij, nb_ij, qi, qj = _node_in_strips(np.rint(sa / g).astype(np.int64), np.rint(sb / g).astype(np.int64), scurve, g)
    else:
        noded = shapely.union_all(src_lines, grid_size=g)
        del src_lines
        na_ij, nb_ij = _noded_segments(noded, g)
        del noded
        qi = None
    if len(na_ij) == 0:
        return _empty_topology(g)
    na, nb = na_ij * g, nb_ij * g
    n_seg = len(na)
    if n_seg == 0:
        return _empty_topology(g)

    # 3. attribute each noded segment to the source segments it lies along
    if qi is None:
        tol = 4.0 * g
        tree = shapely.STRtree(shapely.linestrings(np.stack([sa, sb], axis=1)))
        # in batches of midpoints: a shapely point costs about 100 bytes (issue 19.6, memory)
        qis, qjs = [], []
        for c0 in range(0, n_seg, CHUNK_SEGMENTS):
            ca, cb = na[c0 : c0 + CHUNK_SEGMENTS], nb[c0 : c0 + CHUNK_SEGMENTS]
            qi, qj = _pieces_along(ca, cb, tree, sa, sb, tol)
            qis.append(qi + c0)
            qjs.append(qj)
        qi, qj = np.concatenate(qis), np.concatenate(qjs)
        del qis, qjs, ca, cb, tree
    ndir = nb - na
    sdir = sb[qj] - sa[qj]
    orient = np.where((ndir[qi] * sdir).sum(axis=1) >= 0, 1, -1)
    cur = scurve[qj]
    del ndir, sdir, sa, sb, scurve, qj, na, nb
    # one (curve, orientation) per noded segment and curve
    order = np.lexsort((orient, cur, qi))
    qi, cur, orient = qi[order], cur[order], orient[order]
    first = np.r_[True, (qi[1:] != qi[:-1]) | (cur[1:] != cur[:-1])]
    qi, cur, orient = qi[first], cur[first], orient[first]
    starts = np.flatnonzero(np.r_[True, qi[1:] != qi[:-1]])
    ends = np.r_[starts[1:], len(qi)]
    # attribution key per noded segment: the source curve when there is one (most
    # segments), else an id for the tuple of (curve, orientation relative to the primary)
    n_curves = len(curves.curves)
    flip = np.zeros(n_seg, dtype=bool)
    flip[qi[starts]] = orient[starts] < 0  # primary = lowest curve index
    key_id = np.full(n_seg, -1, dtype=np.int64)
    single = (ends - starts) == 1
    key_id[qi[starts[single]]] = cur[starts[single]]
    key_tuples: dict[tuple[tuple[int, int], ...], int] = {}
    for s0, s1 in zip(starts[~single].tolist(), ends[~single].tolist()):
        o0 = int(orient[s0])
        kt = tuple((int(cur[k]), int(orient[k]) * o0) for k in range(s0, s1))
        key_id[qi[s0]] = key_tuples.setdefault(kt, n_curves + len(key_tuples))
    key_of_id = {v: k for k, v in key_tuples.items()}
    # orient every noded segment along its primary curve
    a_ij = np.where(flip[:, None], nb_ij, na_ij)
    b_ij = np.where(flip[:, None], na_ij, nb_ij)
    del na_ij, nb_ij, flip, qi, cur, orient, order, first, starts, ends, single

    # 4. raw vertices (every noded point)
    allij = np.concatenate([a_ij, b_ij])
    uniq, inv = _unique_rows(allij)
    su, sv = inv[:n_seg], inv[n_seg:]
    del allij, a_ij, b_ij
    n_raw = len(uniq)
    out_cnt = np.bincount(su, minlength=n_raw)
    in_cnt = np.bincount(sv, minlength=n_raw)
    is_break = (out_cnt != 1) | (in_cnt != 1)
    bij = np.rint(np.concatenate(breaks) / g).astype(np.int64)
    is_break[_match_rows(uniq, bij)[0]] = True
    out_seg = np.full(n_raw, -1)
    out_seg[su] = np.arange(n_seg)
    in_seg = np.full(n_raw, -1)
    in_seg[sv] = np.arange(n_seg)
    # a pass-through vertex joins two segments of the same attribution
    cand = np.flatnonzero(~is_break)
    is_break[cand[key_id[in_seg[cand]] != key_id[out_seg[cand]]]] = True
    del out_cnt, in_cnt, bij, breaks, cand, in_seg

    # 5. chain segments into maximal edges: chain k is cseg[coff[k]:coff[k + 1]] (flat
    # 8-byte arrays, not a list per chain: issue 19.6, memory per segment)
    from array import array

    nxt = np.where(is_break[sv], -1, out_seg[sv])
    visited = np.zeros(n_seg, dtype=bool)
    cseg_a = array("q")
    clen_a = array("q")
    nxt_l = nxt.tolist()
    del nxt, out_seg
    starts_l = np.flatnonzero(is_break[su]).tolist()
    for s in starts_l:
        n0 = len(cseg_a)
        cseg_a.append(s)
        visited[s] = True
        t = nxt_l[s]
        while t >= 0 and not visited[t]:
            cseg_a.append(t)
            visited[t] = True
            t = nxt_l[t]
        clen_a.append(len(cseg_a) - n0)
    for s in np.flatnonzero(~visited).tolist():  # closed loops with no vertex yet
        if visited[s]:
            continue
        is_break[su[s]] = True
        n0 = len(cseg_a)
        cseg_a.append(s)
        visited[s] = True
        t = nxt_l[s]
        while t >= 0 and not visited[t]:
            cseg_a.append(t)
            visited[t] = True
            t = nxt_l[t]
        clen_a.append(len(cseg_a) - n0)
    del nxt_l, visited

    # map vertices: break vertices only, numbered in grid order
    vmap = np.full(n_raw, -1)
    vb = np.flatnonzero(is_break)
    vmap[vb] = np.arange(len(vb))
    vertex_ij = uniq[vb]

    label_cache: dict[int, tuple[frozenset[str], frozenset[str], frozenset[str]]] = {}
    interned: dict[frozenset[str], frozenset[str]] = {}

    def labels_of(kid: int) -> tuple[frozenset[str], frozenset[str], frozenset[str]]:
        got = label_cache.get(kid)
        if got is None:
            key = ((kid, 1),) if kid < n_curves else key_of_id[kid]
            labs, left, right = set(), set(), set()
            for ci, o in key:
                c: Curve = curves.curves[ci]
                labs |= c.labels
                if o > 0:
                    left |= c.left
                    right |= c.right
                else:
                    left |= c.right
                    right |= c.left
            # equal label sets share one object
            got = tuple(interned.setdefault(fs, fs) for fs in (frozenset(labs), frozenset(left), frozenset(right)))  # type: ignore[assignment]
            label_cache[kid] = got
        return got

    # order edges deterministically by their grid coordinates (independent of input order)
    clen = np.frombuffer(clen_a, dtype=np.int64) if len(clen_a) else np.zeros(0, np.int64)
    cseg = np.frombuffer(cseg_a, dtype=np.int64) if len(cseg_a) else np.zeros(0, np.int64)
    n_e = len(clen)
    coff = np.r_[0, np.cumsum(clen)]
    chain_of_seg = np.repeat(np.arange(n_e), clen)
    ev = np.empty(len(cseg) + n_e, dtype=np.int64)
    ev[np.arange(len(cseg)) + chain_of_seg] = su[cseg]
    ev[coff[1:] + np.arange(n_e)] = sv[cseg[coff[1:] - 1]]
    del chain_of_seg
    voff = coff + np.arange(n_e + 1)
    first_ij, second_ij, last_ij = uniq[ev[voff[:-1]]], uniq[ev[voff[:-1] + 1]], uniq[ev[voff[1:] - 1]]
    eorder = np.lexsort((last_ij[:, 1], last_ij[:, 0], clen, second_ij[:, 1], second_ij[:, 0], first_ij[:, 1], first_ij[:, 0]))
    del first_ij, second_ij, last_ij
    # the vertex sequences of the edges in that order, flat, with their offsets
    ev_len = clen[eorder] + 1
    eoff = np.r_[0, np.cumsum(ev_len)].astype(np.int64)
    gather = np.repeat(voff[:-1][eorder] - eoff[:-1], ev_len) + np.arange(int(eoff[-1]))
    ev_sorted = ev[gather]
    del gather, ev
    edge_ij = _Ragged(uniq[ev_sorted], eoff)
    edge_points = _Ragged(edge_ij.flat, eoff, g)
    edge_source = vmap[ev_sorted[eoff[:-1]]] if n_e else np.zeros(0, np.int64)
    edge_target = vmap[ev_sorted[eoff[1:] - 1]] if n_e else np.zeros(0, np.int64)
    first_seg = cseg[coff[:-1][eorder]].tolist()
    del ev_sorted, voff, coff, cseg, cseg_a, clen, clen_a, ev_len, eorder, inv, su, sv, uniq, vmap
    e_labels, e_left_l, e_right_l = [], [], []
    for kid in key_id[first_seg].tolist():
        labs, left_l, right_l = labels_of(kid)
        e_labels.append(labs)
        e_left_l.append(left_l)
        e_right_l.append(right_l)

    # 6. faces: polygonize the edges; a probe point just off each side of an edge's first
    # segment finds its left and right faces (a point in no bounded face is in face 0)
    polys: list[Any] = []
    if n_e:
        # GEOS' polygonizer holds about 800 bytes per edge it is given, and drops the
        # dangles (edges with an end of degree one) itself: they are pruned here first, so
        # that it gets only the edges that bound faces (the same polygons; issue 19.6)
        ring = _ring_edges(edge_source, edge_target, len(vertex_ij))
        rows = edge_points.lengths()[ring]
        sel = np.repeat(eoff[:-1][ring], rows) + (np.arange(int(rows.sum())) - np.repeat(np.cumsum(rows) - rows, rows))
        lines = shapely.linestrings(edge_points.flat[sel] * g, indices=np.repeat(np.arange(len(ring)), rows))
        del rows, sel, ring
        polys = [p for p in shapely.get_parts(shapely.polygonize(lines)) if p.area > 0]
        del lines
    left = np.zeros(n_e, dtype=np.int64)
    right = np.zeros(n_e, dtype=np.int64)
    if polys:
        parr = np.array(polys, dtype=object)
        b4 = shapely.bounds(parr)
        cxy = shapely.get_coordinates(shapely.centroid(parr))
        areas = shapely.area(parr)
        porder = np.lexsort((-areas, cxy[:, 1], cxy[:, 0], b4[:, 1], b4[:, 0]))
        parr = parr[porder]
        polys = list(parr)
        areas = areas[porder]
        p0 = edge_ij.flat[eoff[:-1]] * g
        p1 = edge_ij.flat[eoff[:-1] + 1] * g
        d = p1 - p0
        d = d / np.sqrt((d**2).sum(axis=1))[:, None]
        mid = (p0 + p1) / 2
        off = 0.25 * g
        # screen-left of direction d in y-down coordinates is (d_y, -d_x)
        nl = np.c_[d[:, 1], -d[:, 0]]
        probes = np.concatenate([mid + off * nl, mid - off * nl])
        ptree = shapely.STRtree(parr)
        del p0, p1, d, mid, nl, b4, cxy, parr
        owner = np.zeros(len(probes), dtype=np.int64)
        # probes in batches: a shapely point costs about 100 bytes (issue 19.6, memory)
        for c0 in range(0, len(probes), CHUNK_SEGMENTS):
            qi, qf = ptree.query(shapely.points(probes[c0 : c0 + CHUNK_SEGMENTS]), predicate="within")
            # nested faces cannot both contain a probe (holes), but keep the smallest anyway
            order = np.argsort(-areas[qf], kind="stable")
            owner[c0 + qi[order]] = qf[order] + 1
        del ptree
        left, right = owner[:n_e], owner[n_e:]

    # 7. face labels from side labels; transparent edges join faces (union-find)
    n_f = len(polys) + 1
    parent = list(range(n_f))

    def find(a: int) -> int:
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for e in range(n_e):
        lf, rf = int(left[e]), int(right[e])
        if lf != rf and lf and rf and not e_left_l[e] and not e_right_l[e]:
            ra, rb = find(lf), find(rf)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    comp_labels: dict[int, set[str]] = {}
    for e in range(n_e):
        for f, labs in ((int(left[e]), e_left_l[e]), (int(right[e]), e_right_l[e])):
            if f and labs:
                comp_labels.setdefault(find(f), set()).update(labs)
    face_labels = [EMPTY] + [frozenset(comp_labels.get(find(f), ())) for f in range(1, n_f)]

    # 8. vertex labels: marks and named points lying on a vertex
    # only the labelled vertices get a set (an empty set per vertex cost 216 bytes, 19.6)
    vlabels: dict[int, set[str]] = {}
    named = [(x, y, frozenset([name])) for name, (x, y) in curves.points.items()] + list(curves.marks)
    if named and len(vertex_ij):
        mij = np.rint(np.array([(x, y) for x, y, _ in named]) / g).astype(np.int64)
        vk, mk = _match_rows(vertex_ij, mij)
        for k, m in zip(vk.tolist(), mk.tolist()):
            vlabels.setdefault(k, set()).update(named[m][2])

    return _Topology(
        g,
        vertex_ij,
        tuple(frozenset(vlabels[k]) if k in vlabels else EMPTY for k in range(len(vertex_ij))),
        edge_points,
        edge_ij,
        edge_source,
        edge_target,
        left,
        right,
        tuple(e_labels),
        (None, *polys),
        tuple(face_labels),
    )

"""Analysis of the reference arrangement (Ijiri et al. 2008, §4).

Connectivity comes from a Delaunay triangulation of the element centres; skewed
triangles (an angle above 2π/3) are dropped and only edges of the remaining triangles
are kept. Elements on the boundary of the connectivity are excluded from the reference
set, and each interior element records its 1-ring: the relative positions, symbol ids
(kinds) and unique sub-ids of its neighbours, in counter-clockwise order.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np

from .._errors import InputError
from ..arrangement import Arrangement

__all__ = ["Reference", "analyze", "delaunay_edges", "flip_edge", "SKEW_ANGLE"]

#: §4: triangles with an angle greater than 2/3 π are "skewed" and removed.
SKEW_ANGLE = 2.0 * np.pi / 3.0


def _validate_centres(xy: np.ndarray) -> None:
    n = len(xy)
    if n < 4:
        raise InputError(f"exemplar: needs at least four elements, got {n}")
    order = np.lexsort((xy[:, 1], xy[:, 0]))
    s = xy[order]
    span = float(np.ptp(xy, axis=0).max())
    same = np.flatnonzero(np.all(np.abs(np.diff(s, axis=0)) <= 1e-9 * max(span, 1.0), axis=1))
    if len(same):
        i, j = sorted((int(order[same[0]]), int(order[same[0] + 1])))
        raise InputError(f"exemplar: duplicate positions: elements {i} and {j} are both at ({xy[i, 0]:g}, {xy[i, 1]:g})")
    c = xy - xy.mean(axis=0)
    sv = np.linalg.svd(c, compute_uv=False)
    if sv[1] <= 1e-9 * max(sv[0], 1e-300):
        raise InputError("exemplar: element centres are collinear; connectivity needs a 2D arrangement")


def _triangle_angles(p: np.ndarray, tri: np.ndarray) -> np.ndarray:
    """(m, 3) interior angles of triangles ``tri`` (m, 3) over points ``p`` (n, 2)."""
    a, b, c = p[tri[:, 0]], p[tri[:, 1]], p[tri[:, 2]]

    def ang(u: np.ndarray, v: np.ndarray) -> np.ndarray:
        cos = np.einsum("ij,ij->i", u, v) / np.maximum(np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1), 1e-300)
        return np.arccos(np.clip(cos, -1.0, 1.0))

    return np.c_[ang(b - a, c - a), ang(a - b, c - b), ang(a - c, b - c)]


def delaunay_edges(xy: np.ndarray, skew_angle: float = SKEW_ANGLE) -> np.ndarray:
    """Edges of the Delaunay triangulation of ``xy`` without skewed triangles (§4).

    Parameters
    ----------
    xy : (n, 2) float
        Element centres.
    skew_angle : float
        Triangles with any angle above this (radians) are dropped.

    Returns
    -------
    (m, 2) int
        Sorted unique edges ``i < j`` that belong to at least one kept triangle.
    """
    from scipy.spatial import Delaunay
    from scipy.spatial import QhullError

    xy = np.asarray(xy, dtype=float)
    _validate_centres(xy)
    try:
        tri = Delaunay(xy).simplices
    except QhullError:
        raise InputError("exemplar: element centres are collinear; connectivity needs a 2D arrangement") from None
    ang = _triangle_angles(xy, tri)
    # §4 removes triangles with an angle greater than 2/3 π. A triangle at exactly 2/3 π
    # (three collinear-ish boundary elements of a hexagonal lattice) is also dropped: the
    # tolerance absorbs rounding, which would otherwise keep or drop it at random.
    tri = tri[ang.max(axis=1) < skew_angle - 1e-6]
    if len(tri) == 0:
        raise InputError("exemplar: every Delaunay triangle is skewed (an angle above 120°); nothing to learn from")
    e = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    e.sort(axis=1)
    return np.unique(e, axis=0)


def _adjacency(n: int, edges: np.ndarray) -> list[set[int]]:
    adj: list[set[int]] = [set() for _ in range(n)]
    for i, j in edges.tolist():
        adj[i].add(j)
        adj[j].add(i)
    return adj


def _ccw(center: np.ndarray, xy: np.ndarray, nbrs: Sequence[int]) -> list[int]:
    """Neighbours sorted by angle (atan2 order, counter-clockwise in y-up axes)."""
    nb = np.asarray(list(nbrs), dtype=np.intp)
    d = xy[nb] - center
    return nb[np.argsort(np.arctan2(d[:, 1], d[:, 0]), kind="stable")].tolist()


def _is_interior(v: int, xy: np.ndarray, adj: list[set[int]]) -> bool:
    """True when the 1-ring of ``v`` is a closed fan: consecutive neighbours are joined
    by an edge and no angular gap reaches π (§4: boundary elements lack neighbours)."""
    nbrs = adj[v]
    if len(nbrs) < 3:
        return False
    ring = _ccw(xy[v], xy, nbrs)
    d = xy[ring] - xy[v]
    a = np.arctan2(d[:, 1], d[:, 0])
    gaps = np.diff(np.r_[a, a[0] + 2 * np.pi])
    if gaps.max() >= np.pi - 1e-9:
        return False
    return all(ring[(k + 1) % len(ring)] in adj[ring[k]] for k in range(len(ring)))


@dataclass(frozen=True, eq=False)
class Reference:
    """The analysed reference arrangement (§4).

    Attributes
    ----------
    exemplar : Arrangement
        The reference arrangement itself.
    edges : (m, 2) int
        Connectivity, sorted pairs ``i < j`` of element indices.
    interior : (n,) bool
        Elements used as references (boundary elements are excluded).
    rings : list of (k_i,) int arrays
        For every element, its neighbours in counter-clockwise order.
    mean_edge : float
        ``l``: the average edge length (§5.1 uses ``5 * l`` as the neighbouring area).
    shortest_edge : float
        Shortest edge length; ``l_short`` is half of it (§5.4).
    """

    exemplar: Arrangement
    edges: np.ndarray
    interior: np.ndarray = field(repr=False)
    rings: list[np.ndarray] = field(repr=False)
    mean_edge: float = 0.0
    shortest_edge: float = 0.0

    @property
    def xy(self) -> np.ndarray:
        """(n, 2) element centres of the exemplar."""
        return self.exemplar.xy

    @property
    def reference_ids(self) -> np.ndarray:
        """(r,) indices of the interior elements (the reference set)."""
        return np.flatnonzero(self.interior)

    def flip(self, i: int, j: int) -> Reference:
        """A copy with edge ``(i, j)`` flipped; see :func:`flip_edge`."""
        return flip_edge(self, i, j)

    def ring_arrays(self) -> dict[str, np.ndarray]:
        """Padded 1-ring arrays of the reference set, for matching (§5.2).

        Returns
        -------
        dict with
            ``ids`` (r,) exemplar index of each reference element;
            ``rel`` (r, K, 2) neighbour positions relative to the element;
            ``kind`` (r, K) neighbour symbol ids; ``sub`` (r, K) neighbour sub-ids;
            ``n`` (r,) ring sizes.
        """
        ids = self.reference_ids
        k_max = max((len(self.rings[i]) for i in ids), default=0)
        r = len(ids)
        rel = np.zeros((r, k_max, 2))
        kind = np.full((r, k_max), -1, dtype=np.int64)
        sub = np.full((r, k_max), -1, dtype=np.int64)
        n = np.zeros(r, dtype=np.int64)
        xy = self.xy
        kinds = self.exemplar.kind
        for a, i in enumerate(ids):
            ring = self.rings[i]
            n[a] = len(ring)
            rel[a, : len(ring)] = xy[ring] - xy[i]
            kind[a, : len(ring)] = kinds[ring]
            sub[a, : len(ring)] = ring
        return {"ids": ids.astype(np.int64), "rel": rel, "kind": kind, "sub": sub, "n": n}

    def to_dict(self) -> dict[str, list[list[int]]]:
        """JSON-ready connectivity: ``{"edges": [[i, j], ...]}``."""
        return {"edges": self.edges.tolist()}


def _build(exemplar: Arrangement, edges: np.ndarray) -> Reference:
    xy = exemplar.xy
    n = len(xy)
    edges = np.unique(np.sort(np.asarray(edges, dtype=np.int64).reshape(-1, 2), axis=1), axis=0)
    adj = _adjacency(n, edges)
    rings = [np.asarray(_ccw(xy[v], xy, adj[v]) if adj[v] else [], dtype=np.intp) for v in range(n)]
    interior = np.array([_is_interior(v, xy, adj) for v in range(n)], dtype=bool)
    if not interior.any():
        raise InputError(
            f"exemplar: no interior element: all {n} elements lie on the boundary of the connectivity; "
            "draw a larger exemplar (at least one element fully surrounded by neighbours)"
        )
    lengths = np.linalg.norm(xy[edges[:, 0]] - xy[edges[:, 1]], axis=1)
    return Reference(exemplar, edges, interior, rings, float(lengths.mean()), float(lengths.min()))


def _edges_from_extra(exemplar: Arrangement) -> np.ndarray | None:
    conn = exemplar.extra.get("connectivity")
    if conn is None:
        return None
    edges = conn.get("edges") if isinstance(conn, dict) else None
    if not isinstance(edges, list):
        raise InputError("connectivity.edges: missing or not a list of [i, j] pairs")
    count = conn.get("count")
    if count is not None and count != len(exemplar):
        raise InputError(
            f"connectivity: made for {count} elements but the document has {len(exemplar)} "
            "(elements were added or removed since); delete the connectivity entry to rebuild it"
        )
    return _check_edges(edges, len(exemplar), "connectivity.edges")


def _check_edges(edges: Iterable, n: int, where: str) -> np.ndarray:
    try:
        e = np.asarray(list(edges), dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{where}: must be a list of [i, j] index pairs") from None
    if e.size == 0:
        raise InputError(f"{where}: is empty")
    if e.ndim != 2 or e.shape[1] != 2 or not np.all(e == np.round(e)):
        raise InputError(f"{where}: must be a list of [i, j] integer index pairs")
    e = e.astype(np.int64)
    bad = np.flatnonzero((e < 0).any(axis=1) | (e >= n).any(axis=1))
    if len(bad):
        raise InputError(f"{where}[{bad[0]}]: index out of range for {n} elements: {e[bad[0]].tolist()}")
    loops = np.flatnonzero(e[:, 0] == e[:, 1])
    if len(loops):
        raise InputError(f"{where}[{loops[0]}]: an edge joins element {e[loops[0], 0]} to itself")
    return e


def analyze(
    exemplar: Arrangement,
    *,
    edges: np.ndarray | Sequence[Sequence[int]] | None = None,
    flips: Iterable[tuple[int, int]] = (),
) -> Reference:
    """Build the connectivity of a reference arrangement and its 1-ring reference set (§4).

    Parameters
    ----------
    exemplar : Arrangement
        The reference arrangement (at least four elements, not collinear, no two at the
        same position).
    edges : (m, 2) int, optional
        An explicit edge list; by default the document's ``connectivity.edges`` entry if
        it has one, else the Delaunay triangulation without skewed triangles.
    flips : iterable of (i, j)
        Edges to flip afterwards (Fig. 3: the user repairs the regularity).

    Returns
    -------
    Reference

    Examples
    --------
    >>> from strew.grow._exemplars import hex_exemplar
    >>> ref = analyze(hex_exemplar(5, 5))
    >>> int(ref.interior.sum()), round(ref.mean_edge, 6)
    (9, 10.0)
    """
    if not isinstance(exemplar, Arrangement):
        raise InputError(f"exemplar: must be an Arrangement, got {type(exemplar).__name__}")
    xy = exemplar.xy
    _validate_centres(xy)
    if edges is not None:
        e = _check_edges(np.asarray(edges).tolist(), len(xy), "edges")
    else:
        e = _edges_from_extra(exemplar)
        if e is None:
            e = delaunay_edges(xy)
    ref = _build(exemplar, e)
    for i, j in flips:
        ref = flip_edge(ref, int(i), int(j))
    return ref


def flip_edge(ref: Reference, i: int, j: int) -> Reference:
    """Flip edge ``(i, j)``: replace it by the other diagonal of its two triangles (§4, Fig. 3).

    The two triangles are ``(i, j, a)`` and ``(j, i, b)`` where ``a`` and ``b`` are common
    neighbours of ``i`` and ``j`` on either side of the edge, the nearest in angle.

    Raises
    ------
    InputError
        When ``(i, j)`` is not an edge, lacks a triangle on one side, or the
        quadrilateral ``i a j b`` is not convex (the flipped edge would cross others).
    """
    xy = ref.xy
    n = len(xy)
    for v in (i, j):
        if not 0 <= v < n:
            raise InputError(f"--flip {i},{j}: element {v} out of range (the exemplar has {n} elements)")
    a_, b_ = min(i, j), max(i, j)
    edges = ref.edges
    hit = np.flatnonzero((edges[:, 0] == a_) & (edges[:, 1] == b_))
    if len(hit) == 0:
        raise InputError(f"--flip {i},{j}: elements {i} and {j} are not joined by an edge")
    adj = _adjacency(n, edges)
    common = sorted(adj[i] & adj[j])
    d = xy[j] - xy[i]
    side = {1: [], -1: []}
    for c in common:
        v = xy[c] - xy[i]
        cr = d[0] * v[1] - d[1] * v[0]
        if abs(cr) > 0:
            # the triangle's apex is the common neighbour with the smallest angle at i
            ang = abs(np.arctan2(cr, d @ v))
            side[1 if cr > 0 else -1].append((ang, c))
    if not side[1] or not side[-1]:
        raise InputError(f"--flip {i},{j}: edge ({i}, {j}) lies on the boundary (a triangle on one side only)")
    a = min(side[1])[1]
    b = min(side[-1])[1]
    # Convexity: i and j must lie on opposite sides of the new edge (a, b).
    e = xy[b] - xy[a]

    def cross(p: np.ndarray) -> float:
        v = p - xy[a]
        return float(e[0] * v[1] - e[1] * v[0])

    if cross(xy[i]) * cross(xy[j]) >= 0 or b in adj[a]:
        raise InputError(f"--flip {i},{j}: cannot flip: quadrilateral {i}, {a}, {j}, {b} is not convex")
    new = np.delete(edges, hit[0], axis=0)
    new = np.vstack([new, [sorted((a, b))]])
    return _build(ref.exemplar, new)

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

__all__ = ["Reference", "analyze", "delaunay_edges", "flip_edge", "regularize_triangles", "several_priority", "size_levels", "size_priority", "SKEW_ANGLE", "SIZE_STEP", "SIZE_STEP_AREA", "SIZE_STEP_SEVERAL"]

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


def delaunay_edges(xy: np.ndarray, skew_angle: float = SKEW_ANGLE, *, regularize: bool = False, shorter: bool = False) -> np.ndarray:
    """Edges of the Delaunay triangulation of ``xy`` without skewed triangles (§4).

    Parameters
    ----------
    xy : (n, 2) float
        Element centres.
    skew_angle : float
        Triangles with any angle above this (radians) are dropped.
    regularize : bool
        Flip the ambiguous diagonals of a (near-)regular lattice to one direction
        (:func:`regularize_triangles`, the automatic form of Fig. 3's flips).
    shorter : bool
        Passed to :func:`regularize_triangles` [default: False, as :func:`analyze`'s
        ``lattice_repairs``; :func:`strew.grow.grow` turns it on outside flow mode].

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
    if regularize:
        tri = regularize_triangles(xy, tri, skew_angle, shorter=shorter)
    e = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    e.sort(axis=1)
    return np.unique(e, axis=0)


#: A Delaunay edge is ambiguous when the two angles opposite it sum to within this of π
#: (its four points are nearly cocircular: the other diagonal is as good).
AMBIGUOUS_ANGLE = np.deg2rad(30.0)
#: Directions of ambiguous diagonals within this of the common one count as agreeing.
DIRECTION_TOL = np.deg2rad(20.0)


def _angle_at(p: np.ndarray, a: int, b: int, c: int) -> float:
    """Angle at ``a`` of triangle ``a b c``."""
    u, v = p[b] - p[a], p[c] - p[a]
    cos = float(u @ v) / max(float(np.hypot(*u) * np.hypot(*v)), 1e-300)
    return float(np.arccos(min(1.0, max(-1.0, cos))))


def _direction_support(cands: np.ndarray, dirs: np.ndarray) -> np.ndarray:
    """For each candidate direction (m,), how many pairs of directions (p, 2) have one
    within ``DIRECTION_TOL`` (angles modulo pi), in blocks: a Python double loop took
    minutes on an exemplar of 9,174 elements (issue 17). Same arithmetic as the loop it
    replaced (``abs(c - p) % pi``, then the shorter way round), so the same counts."""
    out = np.zeros(len(cands), np.int64)
    step = max(1, 4_000_000 // max(2 * len(dirs), 1))
    for a in range(0, len(cands), step):
        c = cands[a : a + step, None, None]
        d = np.abs(c - dirs[None, :, :]) % np.pi
        d = np.minimum(d, np.pi - d)
        out[a : a + step] = np.count_nonzero(np.min(d, axis=2) < DIRECTION_TOL, axis=1)
    return out


#: A tied direction replaces the first one found only when its diagonals are shorter on
#: average by more than this many standard errors of the difference of the two means.
SHORTER_SE = 3.0


def _steadier_direction(xy: np.ndarray, amb: list[tuple[int, int, int, int]], star: float, top: int, dirs: np.ndarray) -> float:
    """The common direction, between two tied ones: the one with the shorter diagonals.

    In a centred lattice whose two cell diagonals are about as long (the scales of a
    staggered roof, cells near squares), every ambiguous quadrilateral has one diagonal
    along each of two directions, so both get the same support and the first found wins.
    Delaunay's own rule (the fatter triangles) picks a cell's shorter diagonal; this
    applies it to the lattice as a whole: the direction whose diagonals are shorter on
    average, when the difference is clear (:data:`SHORTER_SE`). Measured (issue 14,
    'scales' with width 16, length 7): rings with the longer diagonal leave the nearest
    pair outside the connectivity; growth compresses it below the exemplar's least
    distance and the regularity drops by 10-17 %; with the shorter one it is within 3 %.
    Not in the paper (§4, Fig. 3 leaves the choice of flips to the user). The other
    direction is the axial mean of each quadrilateral's diagonal not nearer ``star``,
    and only counts when it is tied with ``star`` in support.
    """

    def diff(p: float, q: float) -> float:
        d = abs(p - q) % np.pi
        return min(d, np.pi - d)

    near, far, far_dir = [], [], []
    for i, j, a, b in amb:
        d1 = float(np.mod(np.arctan2(xy[j, 1] - xy[i, 1], xy[j, 0] - xy[i, 0]), np.pi))
        d2 = float(np.mod(np.arctan2(xy[b, 1] - xy[a, 1], xy[b, 0] - xy[a, 0]), np.pi))
        l1, l2 = float(np.hypot(*(xy[j] - xy[i]))), float(np.hypot(*(xy[b] - xy[a])))
        if diff(d1, star) <= diff(d2, star):
            near.append(l1)
            far.append(l2)
            far_dir.append(d2)
        else:
            near.append(l2)
            far.append(l1)
            far_dir.append(d1)
    fd = np.array(far_dir)
    alt = float(np.mod(np.arctan2(np.sin(2 * fd).mean(), np.cos(2 * fd).mean()) / 2, np.pi))
    if diff(alt, star) < 2 * DIRECTION_TOL or int(_direction_support(np.array([alt]), dirs)[0]) < top:
        return star
    ln, lf = np.array(near), np.array(far)
    se = float(np.sqrt(ln.var() / len(ln) + lf.var() / len(lf)))
    if ln.mean() - lf.mean() > max(SHORTER_SE * se, 1e-9 * ln.mean()):
        return alt
    return star


def regularize_triangles(xy: np.ndarray, tri: np.ndarray, skew_angle: float = SKEW_ANGLE, *, shorter: bool = False) -> np.ndarray:
    """Flip the ambiguous diagonals of a near-regular lattice to one common direction.

    §4, Fig. 3: on regular and near-regular references Delaunay triangulation "often
    generates undesired connections": each cell of a (jittered) square lattice is split by
    whichever diagonal the noise favours, so rings of four to eight neighbours alternate
    at random, "and these connections often break the regular pattern" in growth. The
    paper lets the user flip edges. This does the same automatically: an edge whose two
    opposite angles sum to within :data:`AMBIGUOUS_ANGLE` of π is ambiguous; when most
    ambiguous quadrilaterals have one diagonal along a common direction (a lattice, not
    an irregular arrangement), every ambiguous edge is flipped to the diagonal nearer that
    direction, unless the flip would make a skewed triangle. Irregular references are
    left as they are.

    Parameters
    ----------
    xy : (n, 2) float
    tri : (m, 3) int
        Triangles (no skewed ones).
    skew_angle : float
    shorter : bool
        Break a tie between two directions by the shorter diagonals
        (``_steadier_direction``); False [default]: the first direction found.

    Returns
    -------
    (m, 3) int
        The triangles after the flips (as many as before).
    """
    tris = [tuple(int(v) for v in t) for t in np.asarray(tri).tolist()]
    alive = [True] * len(tris)
    by_edge: dict[tuple[int, int], list[int]] = {}

    def key(a: int, b: int) -> tuple[int, int]:
        return (a, b) if a < b else (b, a)

    def register(t: int) -> None:
        a, b, c = tris[t]
        for e in (key(a, b), key(b, c), key(a, c)):
            by_edge.setdefault(e, []).append(t)

    for t in range(len(tris)):
        register(t)

    def quad(e: tuple[int, int]) -> tuple[int, int, int, int] | None:
        ts = [t for t in by_edge.get(e, []) if alive[t]]
        if len(ts) != 2:
            return None
        i, j = e
        a = next(v for v in tris[ts[0]] if v not in e)
        b = next(v for v in tris[ts[1]] if v not in e)
        return i, j, a, b

    def deficiency(q: tuple[int, int, int, int]) -> float:
        i, j, a, b = q
        return float(np.pi - _angle_at(xy, a, i, j) - _angle_at(xy, b, i, j))

    def direction(u: int, v: int) -> float:
        d = xy[v] - xy[u]
        return float(np.mod(np.arctan2(d[1], d[0]), np.pi))

    def diff(p: float, q: float) -> float:
        d = abs(p - q) % np.pi
        return min(d, np.pi - d)

    amb = []
    for e in list(by_edge):
        q = quad(e)
        if q is not None and abs(deficiency(q)) < AMBIGUOUS_ANGLE:
            amb.append(q)
    if len(amb) < 3:
        return np.asarray(tri)
    dirs = [(direction(i, j), direction(a, b)) for i, j, a, b in amb]
    cands = [d for pair in dirs for d in pair]
    # the common direction: the candidate agreeing with the most quadrilaterals
    support = _direction_support(np.array(cands), np.array(dirs))
    best = int(np.argmax(support))
    if support[best] < 0.75 * len(amb):
        return np.asarray(tri)  # no common direction: an irregular reference
    star = _steadier_direction(xy, amb, cands[best], support[best], np.array(dirs)) if shorter else cands[best]
    for _ in range(3):
        flipped = False
        for e in list(by_edge):
            q = quad(e)
            if q is None or abs(deficiency(q)) >= AMBIGUOUS_ANGLE:
                continue
            i, j, a, b = q
            if diff(direction(a, b), star) >= diff(direction(i, j), star):
                continue
            # convex quadrilateral: i and j on opposite sides of a-b
            d = xy[b] - xy[a]
            ci = d[0] * (xy[i, 1] - xy[a, 1]) - d[1] * (xy[i, 0] - xy[a, 0])
            cj = d[0] * (xy[j, 1] - xy[a, 1]) - d[1] * (xy[j, 0] - xy[a, 0])
            if ci * cj >= 0 or quad(key(a, b)) is not None or key(a, b) in by_edge and any(alive[t] for t in by_edge[key(a, b)]):
                continue
            new = [(a, b, i), (a, b, j)]
            if any(max(_angle_at(xy, *t), _angle_at(xy, t[1], t[2], t[0]), _angle_at(xy, t[2], t[0], t[1])) >= skew_angle - 1e-6 for t in new):
                continue
            for t in by_edge[e]:
                alive[t] = False
            for t3 in new:
                tris.append(t3)
                alive.append(True)
                register(len(tris) - 1)
            flipped = True
        if not flipped:
            break
    return np.asarray([t for t, ok in zip(tris, alive) if ok], dtype=np.asarray(tri).dtype)


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


#: An interior ring whose widest angle between consecutive neighbours exceeds this many
#: times the median widest angle of the interior rings is left out of the reference set.
GAP_OUTLIER = 1.5
#: ... and exceeds the median by this many median absolute deviations of the widest
#: angles (rings of an irregular exemplar vary too much for any gap to stand out)
GAP_MADS = 6.0


def _gapped_rings(xy: np.ndarray, rings: list[np.ndarray], interior: np.ndarray) -> np.ndarray:
    """Interior rings with a gap far wider than the exemplar's rings have: boundary rings.

    §4 drops boundary elements; :func:`_is_interior` knows them by an open fan or a gap
    of π. At the edge of a noisy hexagonal lattice (every gap near π/3), an element whose
    outer neighbour is missing keeps a fan closed by a triangle just under §4's skew limit
    (a gap near 2π/3) and counts as interior. Matched in growth, its ring places the two
    elements beside the hole as if the hole belonged to the lattice, and rows shear
    (issue 14: 'scales' with 6 rows of 6 lost 10 % of its regularity, and its bearing
    histogram failed). Keyed on the exemplar's own rings, not a class: a ring is left out
    when its widest gap exceeds :data:`GAP_OUTLIER` times the median widest gap and the
    median by :data:`GAP_MADS` median absolute deviations. In an irregular exemplar the
    widest gaps spread widely (median near 85°, deviation near 10°, two_sizes and
    three_sizes have gaps of 130°) and nothing is left out. Never leaves the reference
    set empty.
    """
    out = np.zeros(len(xy), dtype=bool)
    ids = np.flatnonzero(interior)
    if len(ids) < 2:
        return out
    widest = np.empty(len(ids))
    for q, v in enumerate(ids):
        d = xy[rings[v]] - xy[v]
        a = np.arctan2(d[:, 1], d[:, 0])
        widest[q] = np.diff(np.r_[a, a[0] + 2 * np.pi]).max()
    med = float(np.median(widest))
    mad = float(np.median(np.abs(widest - med)))
    bad = widest > max(GAP_OUTLIER * med, med + GAP_MADS * mad)
    if bad.all():
        return out
    out[ids[bad]] = True
    return out


def _build(exemplar: Arrangement, edges: np.ndarray, gapped: bool = True) -> Reference:
    xy = exemplar.xy
    n = len(xy)
    edges = np.unique(np.sort(np.asarray(edges, dtype=np.int64).reshape(-1, 2), axis=1), axis=0)
    adj = _adjacency(n, edges)
    rings = [np.asarray(_ccw(xy[v], xy, adj[v]) if adj[v] else [], dtype=np.intp) for v in range(n)]
    interior = np.array([_is_interior(v, xy, adj) for v in range(n)], dtype=bool)
    if gapped:
        interior &= ~_gapped_rings(xy, rings, interior)
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
    regularize: bool = True,
    lattice_repairs: bool = False,
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
    regularize : bool
        Flip the ambiguous diagonals of a near-regular lattice to one direction first
        (:func:`regularize_triangles`); only for the triangulation built here.
    lattice_repairs : bool
        Between two tied lattice directions, flip to the shorter diagonals
        (``_steadier_direction``), and leave rings with a far wider gap than the
        exemplar's out of the reference set (``_gapped_rings``); both issue 14, not in
        the paper. :func:`strew.grow.grow` and the spray tool turn them on outside flow
        mode (flow mode's gap and hole repairs were measured without them); off by
        default, so the clusters' hub lattice (:mod:`strew.grow._clusters`: a sparse
        hub set whose edge rings the gap rule dropped, and density[hub] of 'rings'
        failed at 4x) and the other callers keep their reference sets.

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
            e = delaunay_edges(xy, regularize=regularize, shorter=lattice_repairs)
    ref = _build(exemplar, e, gapped=lattice_repairs)
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
            raise InputError(f"flips {i},{j}: element {v} out of range (the exemplar has {n} elements)")
    a_, b_ = min(i, j), max(i, j)
    edges = ref.edges
    hit = np.flatnonzero((edges[:, 0] == a_) & (edges[:, 1] == b_))
    if len(hit) == 0:
        raise InputError(f"flips {i},{j}: elements {i} and {j} are not joined by an edge")
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
        raise InputError(f"flips {i},{j}: edge ({i}, {j}) lies on the boundary (a triangle on one side only)")
    a = min(side[1])[1]
    b = min(side[-1])[1]
    # Convexity: i and j must lie on opposite sides of the new edge (a, b).
    e = xy[b] - xy[a]

    def cross(p: np.ndarray) -> float:
        v = p - xy[a]
        return float(e[0] * v[1] - e[1] * v[0])

    if cross(xy[i]) * cross(xy[j]) >= 0 or b in adj[a]:
        raise InputError(f"flips {i},{j}: cannot flip: quadrilateral {i}, {a}, {j}, {b} is not convex")
    new = np.delete(edges, hit[0], axis=0)
    new = np.vstack([new, [sorted((a, b))]])
    return _build(ref.exemplar, new)


#: Kinds whose bounding radii differ by this factor or more are of different sizes.
SIZE_STEP = 1.5
#: Fixed mode's default priorities, kinds of three or more sizes: kinds whose bounding
#: radii differ by this factor rank larger first (see :func:`several_priority`)
SIZE_STEP_SEVERAL = 1.3
#: For growth's size levels (:func:`size_levels`), their equal-area radii must also differ
#: by this factor: an elongated kind's bounding radius overstates its size.
SIZE_STEP_AREA = 1.3
#: Two kinds are segregated (bands, patches) when their Delaunay edges between them are
#: fewer than this share of what the same kinds drawn at random would give (see
#: :func:`default_priority`)
SEGREGATED = 0.8


def size_priority(exemplar: Arrangement) -> dict[str, float]:
    """Default priorities (§5.1): larger kinds first, when the exemplar's kinds differ in size.

    §5.1 follows Wong et al. in "placing the larger elements at first and filling spaces
    with the smaller elements later", with priorities the user gives. Without them, kinds
    that occur are ranked by size: sorted by bounding radius (times their median scale),
    a kind starts a new, higher level when it is at least :data:`SIZE_STEP` times the
    next smaller kind. One level (kinds of about one size) gives no priority.
    Not in the paper as a default: large elements otherwise lose their places to small
    ones grown first, are under-produced and leave the small ones in scatter.

    Returns
    -------
    dict of kind name to float
        Empty when every kind is of about one size.
    """
    return _levels(exemplar, 0.0)


def size_levels(exemplar: Arrangement) -> dict[str, float]:
    """The size levels growth's rules read (``_Grower.size_level``): as
    :func:`size_priority`, but a kind starts a higher level only when its equal-area
    radius (sqrt(area / pi)) is also at least :data:`SIZE_STEP_AREA` times the next
    smaller kind's.

    Not in the paper (helper gst18; synth's ``_larger_in_class`` has the same, §7 of
    Davison): a long thin kind is no larger a kind for the rules that let larger kinds
    take the places of smaller ones' seeds and keep smaller ones outside them (§5.1's
    "filling spaces with the smaller elements later"). Bands of dots (radius 2.5) and bars
    (12 x 2.5: bounding radius 6.1, equal-area radius 3.1, 1.25x the dots'; fresh
    held-out EDGE set stripes p2s10) put the bars a level above the dots, and growth
    over-produced them: bars 23.4 against 17.3 per 1e4, dots 13.7 against 14.9,
    density[bar] 0.338/0.224 and nn[bar>bar] 0.108/0.05 on seed 1 (faithful on 2 of
    seeds 1-6 at 091af61, fresh17_rows.py grow stripes:p2s10 1-6); with one level bars
    18.1, dots 15.4 on seed 1, faithful on 6/6. The bound 1.3 sits between those bars
    and the suite's discs SIZE_STEP apart (three sizes 1, 1.5, 3: equal-area radii just
    under 1.5x); of 476 audit exemplars only stripes p2 and rings p3 (six tiles of 11
    around hubs of 4) change (benchmarks/gst18_survey.py). Priorities (which kinds grow
    first) keep :func:`size_priority`.
    """
    return _levels(exemplar, SIZE_STEP_AREA)


def several_priority(exemplar: Arrangement) -> dict[str, float]:
    """Fixed mode's default priorities before :func:`_mixed_priority`: :func:`size_priority`,
    but where kinds come in three or more sizes, kinds whose bounding radii (times their
    median scale) differ by :data:`SIZE_STEP_SEVERAL` rank larger first too.

    §5.1 grows "the larger elements at first", after Wong et al.; which kinds count as
    larger is the user's choice there, and :func:`size_priority` takes one step of
    :data:`SIZE_STEP` for it. Three sizes at radius ratios 1:1.8:2.6 (``--harder`` h10)
    draw stone outlines whose bounding radii (times the median scales) put the large
    stones under 1.5 times the medium ones at every variant 7-14: the two shared a
    level, the medium stones grown beside them closed the large stones' seeds in
    (variant 12, seed 1: 46 % of the large stones' placements refused, against 24 % of
    the medium ones': the outline gap and the overlap test; benchmarks/grw17_refusals.py),
    and the large stones came out 11-13 % short (density 6.9-7.4 against 7.9-8.4 per 1e4 at
    variants 12-14, seed 1) with the medium stones' nearest large one too far at the upper
    deciles (nn[medium>large] 0.17/0.16 against a tolerance of 0.094 at variant 12, seeds
    1-2). Ranked, 7.6-8.5 against 7.9-8.4; variant 12 passes 3 of seeds 1-4 (none
    before; helper g3s, benchmarks/results/g3s_diagnosis.md). Only with three or more
    sizes: two kinds of close sizes (two sizes at ratios 0.7-0.85) keep one level, where
    the larger kind grown first took the smaller one's places
    (:mod:`strew.grow._lone_larger`). The audits' rows this changes:
    benchmarks/g3s_changed.py.
    """
    fine = _levels(exemplar, 0.0, SIZE_STEP_SEVERAL)
    if len(set(fine.values())) >= 3:
        return fine
    return size_priority(exemplar)


def _levels(exemplar: Arrangement, area_step: float, step: float | None = None) -> dict[str, float]:
    """Size levels by bounding radius (``step``, :data:`SIZE_STEP` by default) and
    equal-area radius (``area_step``; 0 for none); empty when every kind is of one level."""
    step = SIZE_STEP if step is None else step
    sizes = []
    for i, name in enumerate(exemplar.kinds):
        sel = exemplar.kind == i
        if sel.any():
            sc = float(np.median(np.abs(exemplar.scale[sel])))
            r, area = float(exemplar.shapes[name].radius), float(exemplar.shapes[name].area) if area_step > 0 else 0.0
            # an outline without filled area (strokes) is judged by its bounding radius
            sizes.append((r * sc, (float(np.sqrt(area / np.pi)) if area > 0 else r) * sc, name))
    sizes.sort()
    level, out, prev, prev_a = 0, {}, None, None
    for r, a, name in sizes:
        if prev is not None and r >= step * prev and a >= area_step * prev_a:
            level += 1
        prev, prev_a = r, a
        out[name] = float(level)
    return out if level > 0 else {}


def default_priority(ref: Reference, several: bool = False) -> dict[str, float]:
    """The priorities :func:`strew.grow.grow` uses when the user gives none (§5.1).

    :func:`size_priority` (larger kinds first), unless the kinds of different sizes lie
    apart from each other, in bands or patches, where none fills the gaps of another:
    then none (``{}``). §5.1 ranks kinds after Wong et al. for patterns whose small
    elements fill the spaces the larger ones leave; kinds are read as apart when, for
    every pair of kinds of different sizes, the Delaunay edges between the two (§4)
    are fewer than :data:`SEGREGATED` of what the same kinds drawn at random among the
    same positions would give (2 f_a f_b of the edges). Not in the paper. (Wide bands of
    dots and of long bars: the bars grew first and their rings ran into the dots' bands,
    which the 1-ring cannot see; the dots' share fell to 0.23-0.31 against 0.45-0.48.
    The suite's mixed kinds (pebbles among stones, three sizes) have 1.1 to 2.5 times
    the random share; such bands 0.54-0.64.) Kinds of void elements rank below the
    visible ones either way (:func:`_voids_last`).

    Parameters
    ----------
    ref : Reference
        The analysed exemplar (§4).
    several : bool
        Rank by :func:`several_priority` instead of :func:`size_priority` (fixed mode:
        kinds of three or more sizes ranked by the finer step :data:`SIZE_STEP_SEVERAL`).

    Returns
    -------
    dict of kind name to float
        Empty when no kind ranks above another.
    """
    return _voids_last(ref.exemplar, _mixed_priority(ref, several_priority(ref.exemplar) if several else size_priority(ref.exemplar)))


def _voids_last(ex: Arrangement, prio: dict[str, float]) -> dict[str, float]:
    """``prio`` with every kind of void elements (the ``void`` column, synth's §5.6
    convention) ranked below every visible kind.

    Not in the paper. Voids stand for the empty space a texture keeps between visible
    elements; ranked with the visible kinds by size, a void seed that came first took
    the place of an apple its ring proposed, and sparse apples among voids were
    under-produced (density[apple] 0.18 against a tolerance of 0.1). Size levels
    (:func:`size_priority`, and flow mode's priorities) are left as they are.
    """
    col = ex.columns.get("void")
    if col is None or len(ex) == 0:
        return prio
    void = np.asarray(col, dtype=bool)
    kinds_void = [name for i, name in enumerate(ex.kinds) if (ex.kind == i).any() and void[ex.kind == i].all()]
    visible = [name for i, name in enumerate(ex.kinds) if (ex.kind == i).any() and name not in kinds_void]
    if not kinds_void or not visible:
        return prio
    top = max((prio.get(name, 0.0) for name in kinds_void), default=0.0) + 1.0
    out = {name: prio.get(name, 0.0) for name in kinds_void}
    out.update({name: top + prio.get(name, 0.0) for name in visible})
    return out


def _mixed_priority(ref: Reference, prio: dict[str, float]) -> dict[str, float]:
    """``prio``, or none (``{}``) when the kinds of different sizes lie apart (see
    :func:`default_priority`)."""
    if not prio:
        return prio
    ex = ref.exemplar
    e = ref.edges
    if len(e) == 0:
        return prio
    ka, kb = ex.kind[e[:, 0]], ex.kind[e[:, 1]]
    frac = np.bincount(ex.kind, minlength=len(ex.kinds)) / len(ex)
    for a, na in enumerate(ex.kinds):
        for b in range(a + 1, len(ex.kinds)):
            nb = ex.kinds[b]
            if na not in prio or nb not in prio or prio[na] == prio[nb]:
                continue
            cross = float(np.count_nonzero(((ka == a) & (kb == b)) | ((ka == b) & (kb == a)))) / len(e)
            if cross >= SEGREGATED * 2.0 * frac[a] * frac[b]:
                return prio  # these two mix: larger first
    return {}

"""Analysis of the selection (§5.1): neighbourhoods, k-coherence sets, free-space vectors."""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from .._errors import InputError
from ..shape import Shape
from ..metrics import overlaps
from . import _kernels as K
from ._palette import Palette, Selection, _rename_conflicting_kinds

__all__ = ["Prepared", "prepare", "neighborhoods", "k_coherence", "cluster_free_space", "dbscan"]


@dataclass
class Prepared:
    """The selection S, analysed. Arrays have one row per exemplar element (n of them).

    Attributes
    ----------
    shapes : dict of str to Shape
        Merged shape library (kind names of different exemplars that clash are renamed).
    pos : (n, 2) float
    kind, rotation, scale : (n,) int32, float, float
    r, rbar : (n,) float
        Bounding and neighbourhood radii (§4.1).
    void : (n,) bool
    source : (n,) int
        Exemplar number (index into ``names``).
    nb_ptr, nb_idx, nb_off, nb_kind, nb_d : CSR neighbourhoods n(e) (self excluded),
        sorted by distance; ``nb_d = 2 r`` of each neighbour.
    co : (n, k) int
        k-coherence sets co(e) (§5.1), most similar first; ``co[e, 0] == e``.
    free_ptr, free_off, free_r, free_cover : CSR free-space vectors free(e) after
        clustering, with the bounding radius r_v of a free-space point and its cover
        radius (3/4 of the exemplar spacing around the elements it stands for): an output
        element closer than that covers it.
    skind : (n,) int
        Class of each element: its kind within its exemplar.
    min_dist : (S, S) float
        0.95 times the closest approach of two classes in the exemplar (0 across
        exemplars): no new element comes closer than that to an element (spacing learned
        from the exemplar, on top of the bounding discs).
    overlap_free : bool
        No two exemplar elements overlap (their shapes, not their discs).
    size_class : (n,) int
        Size class of each element (see :func:`size_classes`).
    parent : (n,) int
        The larger element each element leans on: its nearest Delaunay neighbour in its
        exemplar of a larger size class (-1 for none, and for voids; -3 where it may
        lie beyond the exemplar's edge). Generation copies an element only together
        with its parent, or beside the output element that stands for it (see
        ``grow``, ``_kernels.generate_proposals``).
    follow : (n,) bool
        Elements whose parent is their only larger Delaunay neighbour (a dot ringing
        its disc): copied at their offset from the output element paired with the
        parent.
    factor : float
        The exemplar's closest approach relative to ``r_p + r_q`` (0.95 of it, at most
        1), for reference: two elements intersect when ``|p - q| < rc_p + rc_q`` (or
        closer than ``min_dist``), and ``rc_p + rc_q >= factor (r_p + r_q)``.
    rc : (n,) float
        Collision radius of each element (see :func:`collision_radii`): r_e where the
        exemplar gives radii, else r_e shrunk per kind to the exemplar's spacing.
    frame_window : (exemplars,) bool
        The exemplar's frame (its region) is a window on a larger texture, not a wall
        that biases its kind shares (see :func:`frame_is_window`); False for an
        exemplar without a region.
    """

    names: tuple[str, ...]
    weights: np.ndarray
    shapes: dict[str, Shape]
    pos: np.ndarray
    kind: np.ndarray
    rotation: np.ndarray
    scale: np.ndarray
    r: np.ndarray
    rbar: np.ndarray
    void: np.ndarray
    source: np.ndarray
    columns: dict[str, np.ndarray]
    nb_ptr: np.ndarray
    nb_idx: np.ndarray
    nb_off: np.ndarray
    nb_kind: np.ndarray
    nb_d: np.ndarray
    co: np.ndarray
    free_ptr: np.ndarray
    free_off: np.ndarray
    free_r: np.ndarray
    free_cover: np.ndarray
    skind: np.ndarray
    min_dist: np.ndarray
    factor: float
    kind_cost: float
    density: np.ndarray
    center: np.ndarray
    palette: Palette
    selected: np.ndarray
    interior: list[np.ndarray] = field(default_factory=list)
    domains: list = field(default_factory=list)
    overlap_free: bool = False
    size_class: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    rc: np.ndarray = field(default_factory=lambda: np.zeros(0))
    parent: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    follow: np.ndarray = field(default_factory=lambda: np.zeros(0, bool))
    selection: Selection | None = None
    shape_clearance: np.ndarray | None = None  # (kinds, kinds), see _shapes.clearance
    frame_window: np.ndarray = field(default_factory=lambda: np.zeros(0, bool))

    def __len__(self) -> int:
        return len(self.kind)

    def set_selection(self, selection: Selection) -> None:
        """Select exemplars of the (whole) palette with weights; the others get weight 0."""
        self.selection = selection
        w = np.zeros(len(self.names))
        for name, wt in zip(selection.names, selection.weights):
            w[self.names.index(name)] = wt
        self.weights = w / w.sum()
        self.selected = w > 0

    @property
    def selected_elements(self) -> np.ndarray:
        """(n,) bool: exemplar elements of the selection."""
        return self.selected[self.source]


def neighborhoods(pos: np.ndarray, rbar: np.ndarray, group: np.ndarray | None = None, tree: cKDTree | None = None, query: np.ndarray | None = None):
    """CSR neighbourhoods n(i): elements within ``rbar[i]`` of ``p_i`` (k-d tree, §4).

    Parameters
    ----------
    pos : (n, 2) float
        Points searched.
    rbar : (m,) float
        Radius per query.
    group : (n,) int, optional
        Only elements of the same group are neighbours (exemplars of a palette).
    tree : cKDTree, optional
        Tree over ``pos``.
    query : (m,) int, optional
        Indices of the query elements in ``pos`` (default: all of them).

    Returns
    -------
    ptr : (m + 1,) int
    idx : (N,) int
    off : (N, 2) float
        ``p_j - p_i``, each segment sorted by length, the query itself excluded.
    """
    if tree is None:
        tree = cKDTree(pos)
    if query is None:
        query = np.arange(len(pos))
    lists = tree.query_ball_point(pos[query], r=rbar)
    lens = np.fromiter(map(len, lists), dtype=np.int64, count=len(lists))
    idx = np.fromiter(itertools.chain.from_iterable(lists), dtype=np.int64, count=int(lens.sum()))
    owner = np.repeat(query, lens)
    keep = idx != owner
    if group is not None:
        keep &= group[idx] == group[owner]
    idx = idx[keep]
    owner_row = np.repeat(np.arange(len(query)), lens)[keep]
    lens = np.bincount(owner_row, minlength=len(query))
    ptr = np.zeros(len(query) + 1, dtype=np.int64)
    np.cumsum(lens, out=ptr[1:])
    off = pos[idx] - pos[query][owner_row]
    K.sort_segments(ptr, idx, off)
    return ptr, idx, off


def k_coherence(ptr, off, pos, kind, nb_kind, nb_d, d_center, rbar, source, domains, interior, k: int, kind_cost: float,
                size_class: np.ndarray | None = None) -> np.ndarray:
    """k-coherence sets (§5.1): the k most similar exemplar elements to each one.

    Similarity is the neighbourhood distance of Eq. 1 between n(e) and n(c). Candidates
    are interior elements (whole neighbourhoods) of the same exemplar; an element near the edge of its
    exemplar is compared only inside its exemplar's domain, so that it points to interior
    elements that continue the texture beyond the edge. An interior element comes first
    in its own set (distance 0).

    With ``size_class`` (n,), candidates are of the element's own size class (when its
    exemplar has interior elements of that class). Extension of §5.1 for several sizes
    (§7): a candidate's neighbourhood is copied around the output element that stands
    for the candidate's centre, so a dot whose set held a disc (an edge dot of a cropped
    cluster looks like a disc's surroundings) grew a whole ring of dots around itself:
    clusters variant 1 had 0.27 of its dots without a disc and dots 1.7x too dense.

    Returns
    -------
    (n, k) int
        -1 pads rows when there are fewer than k candidates.
    """
    n = len(kind)
    k = int(k)
    out = np.full((n, k), -1, dtype=np.int64)
    cand_ids = np.flatnonzero(interior).astype(np.int64)
    if n == 0 or len(cand_ids) == 0:
        return out
    hp, hp_n = domains
    # query side: n(e) within r-bar only, as an output neighbourhood would be
    qptr, qrows = truncate(ptr, off, rbar)
    block = max(1, 2_000_000 // len(cand_ids))
    for a in range(0, n, block):
        b = min(n, a + block)
        cands = np.tile(cand_ids, (b - a, 1))
        # candidates come from the element's own exemplar: a texture of another scale
        # would pair nothing and look deceptively close
        same = source[cands] == source[a:b, None]
        if size_class is not None:
            own = same & (size_class[cands] == size_class[a:b, None])
            same = np.where(own.any(axis=1)[:, None], own, same)
        cands = np.where(same, cands, -1)
        rows = qrows[qptr[a] : qptr[b]]
        cost = K.candidate_costs_in_domain(
            qptr[a : b + 1] - qptr[a], off[rows], nb_kind[rows], nb_d[rows], rbar[a:b],
            kind[a:b], d_center[a:b], pos[a:b], source[a:b], hp, hp_n, cands, ptr, off, nb_kind, nb_d, kind, kind_cost,
        )
        rows = np.arange(b - a)
        selfcol = np.searchsorted(cand_ids, rows + a)
        is_self = (selfcol < len(cand_ids)) & (cand_ids[np.minimum(selfcol, len(cand_ids) - 1)] == rows + a)
        cost[rows[is_self], selfcol[is_self]] = -1.0  # the element itself first
        order = np.argsort(cost, axis=1, kind="stable")[:, :k]
        picked = np.where(np.isfinite(np.take_along_axis(cost, order, axis=1)), cand_ids[order], -1)
        out[a:b, : order.shape[1]] = picked
    return out


def truncate(ptr: np.ndarray, off: np.ndarray, radius: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rows of each CSR segment within ``radius[i]``: new pointers and the kept rows."""
    owner = np.repeat(np.arange(len(ptr) - 1), np.diff(ptr))
    keep = np.hypot(off[:, 0], off[:, 1]) <= radius[owner]
    rows = np.flatnonzero(keep)
    nptr = np.zeros(len(ptr), dtype=np.int64)
    np.cumsum(np.bincount(owner[keep], minlength=len(ptr) - 1), out=nptr[1:])
    return nptr, rows


def exemplar_domain(points: np.ndarray, spacing: float):
    """The exemplar's domain: convex hull of its elements grown by half the spacing.

    Returns
    -------
    polygon : shapely Polygon
    halfplanes : (m, 3) float
        Rows ``(a, b, c)`` with ``a x + b y <= c`` inside.
    """
    import shapely
    from shapely.geometry.polygon import orient

    hull = shapely.convex_hull(shapely.multipoints(points))
    poly = shapely.buffer(hull, max(0.5 * spacing, 1e-9), join_style="mitre")
    poly = orient(poly, sign=1.0)
    c = np.asarray(poly.exterior.coords)
    x1, y1, x2, y2 = c[:-1, 0], c[:-1, 1], c[1:, 0], c[1:, 1]
    # inside (counter-clockwise): (x2-x1)(y-y1) - (y2-y1)(x-x1) >= 0
    a = y2 - y1
    b = -(x2 - x1)
    cc = a * x1 + b * y1
    return poly, np.c_[a, b, cc]


def dbscan(points: np.ndarray, eps: float, min_samples: int) -> np.ndarray:
    """Density-based clustering (Ester et al.) with scipy: labels, -1 for noise.

    Core points have at least ``min_samples`` points (themselves included) within
    ``eps``; clusters are the connected components of core points over the radius
    graph, and border points join a neighbouring core point's cluster.

    Parameters
    ----------
    points : (n, 2) float

    Returns
    -------
    (n,) int
    """
    n = len(points)
    if n == 0:
        return np.zeros(0, dtype=np.int64)
    # helper s34v: the same labels from a grid in numba (a tenth of synth's CPU time on
    # grid went to the k-d tree's pairs); the pairs' order decides only a border point
    # between two clusters, and there the k-d tree's pairs below decide as before
    pts = np.ascontiguousarray(points, np.float64)
    if not (eps > 0 and np.isfinite(pts).all() and float(np.ptp(pts, axis=0).max()) < 2.0**40 * eps):
        return _dbscan_kdtree(points, eps, min_samples)  # no grid of side eps over these
    labels, ambiguous = K.dbscan_labels(pts, float(eps), int(min_samples))
    if not ambiguous:
        return labels
    return _dbscan_kdtree(points, eps, min_samples)


def _dbscan_kdtree(points: np.ndarray, eps: float, min_samples: int) -> np.ndarray:
    """:func:`dbscan` from the k-d tree's pairs (the border points between clusters join
    the cluster of their first core neighbour in the pairs' order)."""
    n = len(points)
    tree = cKDTree(points)
    pairs = tree.query_pairs(eps, output_type="ndarray")
    deg = np.ones(n, dtype=np.int64) + np.bincount(pairs[:, 0], minlength=n) + np.bincount(pairs[:, 1], minlength=n)
    core = deg >= min_samples
    cc = pairs[core[pairs[:, 0]] & core[pairs[:, 1]]]
    g = coo_matrix((np.ones(len(cc)), (cc[:, 0], cc[:, 1])), shape=(n, n))
    _, comp = connected_components(g, directed=False)
    labels = np.full(n, -1, dtype=np.int64)
    core_ids = np.flatnonzero(core)
    _, labels[core_ids] = np.unique(comp[core_ids], return_inverse=True)
    # border points: join the cluster of a core neighbour
    both = np.r_[pairs, pairs[:, ::-1]]
    link = both[(labels[both[:, 0]] < 0) & core[both[:, 1]]]
    if len(link):
        labels[link[::-1, 0]] = labels[link[::-1, 1]]  # first core neighbour wins
    return labels


def cluster_free_space(vectors: np.ndarray, radii: np.ndarray, eps: float, min_samples: int) -> tuple[np.ndarray, np.ndarray]:
    """Replace free-space vectors by the centroids of their DBSCAN clusters (§5.1).

    Parameters
    ----------
    vectors : (m, 2) float
    radii : (m, c) float
        Per-vector values averaged over each cluster (radii of the elements pointed to).

    Returns
    -------
    centroids : (q, 2) float
    values : (q, c) float
        Cluster means of ``radii``.
    """
    radii = np.asarray(radii, float).reshape(len(vectors), -1)
    labels = dbscan(vectors, eps, min_samples)
    keep = labels >= 0
    if not keep.any():
        return np.zeros((0, 2)), np.zeros((0, radii.shape[1]))
    lab = labels[keep]
    nc = lab.max() + 1
    cnt = np.bincount(lab, minlength=nc)
    cx = np.bincount(lab, vectors[keep, 0], nc) / cnt
    cy = np.bincount(lab, vectors[keep, 1], nc) / cnt
    vals = np.stack([np.bincount(lab, radii[keep, j], nc) / cnt for j in range(radii.shape[1])], axis=1)
    return np.c_[cx, cy], vals


FREE_SUPPORT = 0.0
"""Share of an element's k-coherence neighbourhoods that must put an element near a
free-space vector for it to make a free-space point: DBSCAN's ``min_samples`` is
ceil(FREE_SUPPORT k), at least 1 (§5.1). Off by default (0: every vector is kept, the
free space of an element is the union of its k neighbourhoods, as before).

§5.1 clusters free(e) = {p_c' - p_c | c' in n(c), c in co(e)} with DBSCAN (Ester et
al.) and keeps the clusters' centroids, so a vector in no cluster (noise) is not a
free-space point; with ``min_samples`` 1 every vector is a cluster, and the output fills
the exemplar's gaps the more the larger k. Measured (fidelity's density[small], three
sizes at 3.5x the frame, seed 1): variant 1 small stones 0.73 / 0.78 / 0.83 of the exemplar's density for k = 1 / 3 / 5, variant 2
0.91 / 1.11 / 1.19. With 0.6 (k = 5 -> 3 neighbourhoods) plus the best match's own
vectors (``prepare``): python benchmarks/synth_variants.py --only
three_sizes,two_sizes,stones,sparse_voids,clusters --varied (its version at a56124d)
46/62 -> 51/62 faithful (three sizes 6 -> 11 of 14, two sizes 12 -> 11, stones 6 -> 7),
but python benchmarks/fidelity.py --method synth --seeds 1-5 fell from 60/60 to 56/60
(three sizes' default exemplar: density 0.15-0.165 against 0.134 on seeds 1, 4, 5,
nn 0.129/0.127 on seed 3: its small stones fell further below the exemplar's share),
so it stays off. 0.4: 46/62; 0.8: 48/62. Without the best match's own vectors,
clusters (rings of dots far apart) stopped growing after the seed patch (0/6).

Again with the judge's kind shares minus-sampled beyond the exemplar frame's wall reach
(issue 13, ``strew._fidelity._wall_reach``), on the same outputs (python
benchmarks/judge_rescore.py score --sets suite-synth,var-synth [--free-support X]; the
variants are synth_variants.py --varied's 254 runs): 0 -> 0.6 -> 0.4, suite synth seeds
1-5 60/60 -> 60/60 -> 60/60 (the old judge: 60 -> 55 -> 55, three sizes 0/5), variants
210 -> 217 -> 214 of 254 (three sizes 10 -> 16 -> 15 of 26, two sizes 16 -> 17 -> 16,
stones 14 -> 15 -> 15, stripes 19 -> 20 -> 20, rings 21 -> 21 -> 22) but clusters
26 -> 24 -> 23 (edge set p2s8, far-apart full rings: synth stops after the seed patch,
g[disc,dot] 764 against 2.08) and, at 0.4, sparse voids 16 -> 15: a class loses runs,
so it stays off.
"""


def outer_voids(ex) -> np.ndarray:
    """(n,) bool: the void elements of ``ex`` outside the convex hull of its visible
    elements (none when fewer than 3 visible elements span an area).

    Departure from §5.6, where every void element the user placed is texture: voids
    stand for the empty space *between* visible elements, and a void beyond the last
    visible element stands for no gap the texture keeps, only for the margin of the
    exemplar's frame (sparse apples dart-thrown inside their frame leave a band half a
    spacing wide that only voids fill). Copied, such a band of voids is an apple-free
    strip inside the output: measured on sparse voids (default variant 2, seeds 1-2,
    3.5x the frame), the output's apple density was 0.916 / 0.892 of the exemplar's,
    0.906 / 0.942 without them; ``spacing=24, apple=4`` variant 7 seed 2, the empty
    circles' q95 1.110 -> 1.098 of the exemplar's.
    """
    void = np.asarray(ex["void"], dtype=bool) if "void" in ex.columns else np.zeros(len(ex), bool)
    if not void.any() or int((~void).sum()) < 3:
        return np.zeros(len(ex), bool)
    import shapely

    hull = shapely.convex_hull(shapely.multipoints(ex.xy[~void]))
    if hull.geom_type != "Polygon" or hull.area <= 0:
        return np.zeros(len(ex), bool)
    return void & ~shapely.intersects_xy(hull, ex.xy[:, 0], ex.xy[:, 1])


def _without_outer_voids(ex):
    """``ex`` without its :func:`outer_voids`."""
    out = outer_voids(ex)
    return ex.select(~out) if out.any() else ex


def prepare(selection: Selection, *, k: int = 5, kind_cost: float = 1.0) -> Prepared:
    """Analyse the palette of a selection: neighbourhoods, k-coherence and free-space
    points (§5.1), computed for every exemplar of the palette; the selection then picks
    which of them drive synthesis.
    """
    if k < 1:
        raise InputError(f"k: must be at least 1, got {k}")
    palette = selection.palette
    names = palette.names
    exemplars = [_without_outer_voids(palette[nm]) for nm in names]
    tagged = [ex.with_columns(exemplar=[name] * len(ex)) for name, ex in zip(names, exemplars)]
    tagged = _rename_conflicting_kinds(tagged)
    sources = np.concatenate([np.full(len(ex), i) for i, ex in enumerate(tagged)])
    from ..arrangement import concat

    arr = concat(tagged)
    from .._limits import check_kinds

    check_kinds(len(arr.kinds), "exemplar")  # the type-mismatch table and costs are per kind pair
    pos = arr.xy
    r = np.asarray(arr["radius"], dtype=float)
    rbar = np.asarray(arr["neighborhood_radius"], dtype=float)
    void = np.asarray(arr["void"], dtype=bool) if "void" in arr else np.zeros(len(arr), bool)
    kind = arr.kind.astype(np.int64)
    # n(e) reaches past r-bar by the largest pairing threshold of its exemplar, so that
    # output neighbours on the rim still find their pairs (see kernels.pair_cost).
    margin = np.array([2.0 * r[sources == i].max() for i in range(len(tagged))])[sources]
    reach, far = anchor_reach(pos, rbar + margin, kind, sources, void, size_classes(r, area_radii(arr), kind), area_radii(arr))
    ptr, idx, off = neighborhoods(pos, reach, group=sources)
    if far is not None:  # beyond r-bar + margin, n(e) holds the foreign anchors only (anchor_reach)
        owner = np.repeat(np.arange(len(pos)), np.diff(ptr))
        keep = (np.hypot(off[:, 0], off[:, 1]) <= (rbar + margin)[owner]) | far[idx]
        idx, off = idx[keep], off[keep]
        ptr = np.r_[0, np.cumsum(np.bincount(owner[keep], minlength=len(pos)))].astype(ptr.dtype)
    nb_kind = kind[idx]
    nb_d = 2.0 * r[idx]  # d_e = 2 r_e (§4)
    # Exemplar domains and interior elements (whole neighbourhoods inside the domain).
    import shapely

    nsrc = len(tagged)
    polys, planes = [], []
    density = np.zeros(nsrc)
    center = np.zeros(nsrc, dtype=np.int64)
    interior_mask = np.zeros(len(arr), bool)
    depth_all = np.zeros(len(arr))
    interior = []
    cls = size_classes(r, area_radii(arr), kind)
    for i in range(nsrc):
        ids = np.flatnonzero(sources == i)
        p = pos[ids]
        a = _spacing(p)
        poly, hp = exemplar_domain(p, a)
        polys.append(poly)
        planes.append(hp)
        density[i] = len(ids) / max(poly.area, 1e-12)
        depth = shapely.distance(poly.exterior, shapely.points(p))
        depth_all[ids] = depth
        inner = depth >= rbar[ids]
        if inner.sum() < max(k, 4):
            inner = np.zeros(len(ids), bool)
            inner[np.argsort(-depth, kind="stable")[: max(k, 4)]] = True
        _surround_steps(inner, ids, depth, rbar[ids], cls, ptr, idx, off, k)
        interior_mask[ids[inner]] = True
        interior.append(ids[inner])
        center[i] = ids[np.argmax(depth)]
    hp_n = np.array([len(h) for h in planes], dtype=np.int64)
    hp = np.zeros((nsrc, int(hp_n.max()), 3))
    for i, h in enumerate(planes):
        hp[i, : len(h)] = h
    co = k_coherence(ptr, off, pos, kind, nb_kind, nb_d, 2.0 * r, rbar, sources, (hp, hp_n), interior_mask, k, kind_cost, cls)
    # Free space (§5.1): free(e) = {p_c' - p_c | c' in n(c), c in co(e)}, clustered.
    free_ptr = np.zeros(len(arr) + 1, dtype=np.int64)
    # DBSCAN core points need vectors from about FREE_SUPPORT of the k neighbourhoods
    # (see FREE_SUPPORT): k = 5 -> 3, k = 1 -> 1 (every vector kept, as before)
    min_samples = max(1, int(np.ceil(FREE_SUPPORT * k)))
    # cover radius and DBSCAN eps: 3/4 of the nearest-neighbour distance of each element
    # in its exemplar, with the frame's stretch taken out (_uncut_nn: the cover bounded by
    # the kind's longest uncut distance, the eps set to its median)
    # (one size class only: with several, a long cut nn is the exemplar's own spacing
    # around larger elements; s46w)
    half_nn = np.zeros(len(arr))
    half_eps = np.zeros(len(arr))
    for i in range(len(tagged)):
        ids = np.flatnonzero(sources == i)
        d, _ = cKDTree(pos[ids]).query(pos[ids], k=2)
        uncut = UNCUT_NN and len(np.unique(cls[ids])) == 1
        half_nn[ids] = 0.75 * (_uncut_nn(d[:, 1], depth_all[ids], kind[ids], upper=True) if uncut else d[:, 1])
        half_eps[ids] = 0.75 * (_uncut_nn(d[:, 1], depth_all[ids], kind[ids]) if uncut else d[:, 1])
    # all elements at once: each element's vectors scaled by its eps and moved far apart,
    # so one DBSCAN pass clusters every free(e) separately
    n = len(arr)
    cs = co.ravel()
    own = np.repeat(np.arange(n), co.shape[1])
    rank = np.tile(np.arange(co.shape[1]), n)
    own, rank, cs = own[cs >= 0], rank[cs >= 0], cs[cs >= 0]
    seg = ptr[cs + 1] - ptr[cs]
    owner = np.repeat(own, seg)
    first = np.repeat(rank == 0, seg)
    rows = np.repeat(ptr[cs], seg) + (np.arange(int(seg.sum())) - np.repeat(np.cumsum(seg) - seg, seg))
    eps = 0.33 * half_eps[owner]
    pts = off[rows] / eps[:, None]
    span = float(np.abs(pts).max()) * 2 + 10.0 if len(pts) else 1.0
    pts[:, 0] += owner * span
    labels = dbscan(pts, 1.0, min_samples)
    # noise (vectors in no cluster) is dropped, as DBSCAN does (§5.1), except the vectors
    # of the best match co(e)[0] (e itself for an interior element), each its own point:
    # the exemplar's own neighbourhood always says where elements go
    lone = (labels < 0) & first
    if lone.any():
        labels[lone] = labels.max() + 1 + np.arange(int(lone.sum()))
    keep = labels >= 0
    labels, owner, rows = labels[keep], owner[keep], rows[keep]
    nb = idx[rows]
    uniq, inv = np.unique(labels, return_inverse=True)  # labels grow with owner order
    cnt = np.bincount(inv).astype(float)
    cent = np.c_[np.bincount(inv, off[rows, 0]) / cnt, np.bincount(inv, off[rows, 1]) / cnt]
    _, skind = np.unique(np.c_[sources, kind], axis=0, return_inverse=True)
    skind = skind.ravel().astype(np.int64)
    rc = collision_radii(arr, pos, r, skind, ptr, idx, off)
    vals = np.c_[np.bincount(inv, rc[nb]) / cnt, np.bincount(inv, half_nn[nb]) / cnt]
    lab_owner = np.zeros(len(uniq), np.int64)
    lab_owner[inv] = owner
    order = np.lexsort((np.arange(len(uniq)), lab_owner))
    free_off = cent[order]
    free_r, free_cover = vals[order, 0].copy(), vals[order, 1].copy()
    free_ptr[1:] = np.cumsum(np.bincount(lab_owner, minlength=n))
    # The exemplar's closest approach relative to r_p + r_q over all pairs, for
    # reference: collisions use the per-kind radii rc (Prepared.rc), and
    # rc_p + rc_q >= factor (r_p + r_q) for every pair.
    factor = 1.0
    if len(idx):
        owner = np.repeat(np.arange(len(arr)), np.diff(ptr))
        factor = float(min(1.0, 0.95 * (np.hypot(off[:, 0], off[:, 1]) / (r[owner] + r[idx])).min()))
    min_dist = closest_approach(pos, skind, sources)
    anchor = anchor_mask(skind, sources, cls, void, pos, area_radii(arr))
    if SCATTERED_FREE:
        _free_scattered(min_dist, skind, sources, cls, void, anchor)
    # classes of different exemplars, or a class with one element: no constraint beyond r
    min_dist = np.where(np.isfinite(min_dist), 0.95 * min_dist, 0.0)
    columns = {k_: np.asarray(v) for k_, v in arr.columns.items() if k_ not in ("radius", "neighborhood_radius", "void", "exemplar")}
    prep = Prepared(
        names=names,
        weights=np.zeros(len(names)),
        shapes=arr.shapes,
        pos=pos,
        kind=kind,
        rotation=np.asarray(arr.rotation, float),
        scale=np.asarray(arr.scale, float),
        r=r,
        rbar=rbar,
        void=void,
        source=sources,
        columns=columns,
        nb_ptr=ptr,
        nb_idx=idx,
        nb_off=off,
        nb_kind=nb_kind,
        nb_d=nb_d,
        co=co,
        free_ptr=free_ptr,
        free_off=free_off,
        free_r=free_r,
        free_cover=free_cover,
        skind=skind,
        min_dist=min_dist,
        factor=factor,
        rc=rc,
        kind_cost=float(kind_cost),
        density=density,
        center=center,
        palette=palette,
        selected=np.zeros(len(names), bool),
        interior=interior,
        domains=polys,
        overlap_free=all(len(overlaps(ex)[0]) == 0 for ex in exemplars),
        size_class=cls,
        parent=parents(pos, cls, sources, void, depth_all, kind, follow=(follow := np.zeros(len(arr), bool)),
                       anchor=anchor),
        follow=follow,
        frame_window=np.array([ex.region is not None and frame_is_window(pos[ids], kind[ids], r[ids], ex.region.geometry)
                               for ex, ids in ((ex, np.flatnonzero((sources == i) & ~void)) for i, ex in enumerate(exemplars))], bool),
    )
    prep._anchors = anchor  # _grow.anchors: the same mask, with the centres (_stand_around)
    # hubs that n(e) reaches across the gap in exemplars without anchors (_far_hubs):
    # _grow.hub_floors keeps their copies as far apart as the exemplar's hubs
    prep._far_hubs = np.zeros(len(arr), bool) if far is None else far & ~(anchor > 0)
    prep._area_r = area_radii(arr)  # _grow._larger_in_class: a kind's size by area as well
    prep.set_selection(selection)
    return prep


SURROUND_GAP = 0.5 * np.pi  # interior steps of a large class leave no sector this wide empty
SURROUND_DEPTH = 0.6  # ... using members at least this share of their r-bar inside the domain
SURROUND_K = True
"""... and, down to the same depth, until the class holds k interior members (see
:func:`_surround_steps`), in exemplars of fewer than :data:`SURROUND_K_CLASSES` size
classes."""
SURROUND_K_CLASSES = 3


UNCUT_NN = True
"""Take the frame's stretch out of the nearest-neighbour distances behind the free-space
cover radius and DBSCAN eps (:func:`_uncut_nn`), in exemplars of one size class only
(:func:`size_classes`; s46w, see there)."""


def _uncut_nn(nn: np.ndarray, depth: np.ndarray, kind: np.ndarray, upper: bool = False) -> np.ndarray:
    """Nearest-neighbour distances with the frame's stretch taken out, for the free-space
    cover radius and DBSCAN eps (departs from §5.1).

    §5.1 sets the cover radius of free space and the DBSCAN eps that clusters free(e)
    from each element's nearest-neighbour distance in its exemplar. An element the frame
    cut off from its nearest neighbour (its nn farther than its depth inside the domain,
    Hanisch's test, as the fidelity judge's own border correction) has a stretched nn:
    at 50x the area stripes failed nn[bar>bar] at seeds 3, 6, 11, 14, 16 of
    ``benchmarks/seam17_all50.py``.

    A cut element's observed nn is only an upper bound on its true one. Where it lies
    within the range its kind's uncut elements show, it is kept; only a distance beyond
    every uncut one of its kind, which the frame alone explains, is replaced (stripes: 6
    of 32 cut elements): by the kind's uncut median for the eps (the typical distance),
    by the kind's longest uncut distance for the cover (``upper``; the bound, no more).
    Unchanged where a kind has none uncut. Helper s44w: s42w set every cut nn above the
    kind's median to the median, for both (20 of 22 cut small stones of ``--harder``
    three sizes h6s29), and lost h6s29 (nn[medium>small], seeds 1-6 main 6/6) and
    ``--varied`` p4s29; with only the beyond-range elements, at the median, the cover
    still lost h6s29 seeds 2 and 6. The eps at the median and the cover at the longest
    uncut distance pass stripes 50x where the eps alone left s14 failing, and leave
    h6s29 seeds 2, 6 and p4s29 seed 4 as without the cap.

    Applied (by :func:`prepare`) only to an exemplar whose elements are all of one size
    class (:func:`size_classes`; stripes' dots and bars are one). Helper s46w: with
    several classes an element's nn is often to another class, and a long one is the
    exemplar's own spacing around larger elements, not the frame's: in three sizes
    (suite draw 3) the one large stone it changed (nn 18.43 to a small stone, depth
    17.99, longest uncut 17.87) took the median 16.37 for its eps, and the output's small
    fraction failed (``test_synth_free_support``, variant 3 at 3.5x, FREE_SUPPORT 0.6),
    as did ``--harder`` three sizes h7s28 at seed 1. Multi-class exemplars keep the raw
    nn, as before s44w.

    Parameters
    ----------
    nn : (n,) float array
        Each element's nearest-neighbour distance within its exemplar.
    depth : (n,) float array
        Each element's distance to the exemplar domain's boundary.
    kind : (n,) int array
        Each element's kind.
    upper : bool
        Replace by the kind's longest uncut distance (the cover) instead of its median
        (the eps).

    Returns
    -------
    (n,) float array
        ``nn`` with the cut distances beyond their kind's uncut range replaced.
    """
    out = np.asarray(nn, float).copy()
    cut = out > depth
    if not cut.any():
        return out
    for k in np.unique(kind[cut]):
        whole = (kind == k) & ~cut
        if whole.any():
            top = float(out[whole].max())
            sel = (kind == k) & cut & (out > top)
            out[sel] = top if upper else float(np.median(out[whole]))
    return out


def _surround_steps(inner: np.ndarray, ids: np.ndarray, depth: np.ndarray, rbar_c: np.ndarray, cls: np.ndarray, ptr: np.ndarray, idx: np.ndarray, off: np.ndarray,
                    k: int = 0) -> None:
    """Add the deepest members of a larger size class to the interior (``inner``, in
    place) until the steps its interior members show to members of their own class
    surround them: no sector of :data:`SURROUND_GAP` without a step. Only members at
    least :data:`SURROUND_DEPTH` of their r-bar inside the exemplar's domain are added,
    and only for classes with their own larger r-bar (``_palette.element_parameters``).

    Extension of §5.1 (candidates are interior elements, whole neighbourhoods): growth
    places a large element only by copying such a step from a candidate, so with steps
    all on one side it grows a one-sided lattice and never crosses the other way.
    Far-apart clusters in a small frame have one disc with a whole neighbourhood; on
    clusters EDGE p2s8 of benchmarks/synth_variants.py its three disc steps lay within
    a cone and the output filled a third of the region (434 elements; with the next
    two discs, 76.7 and 75.3 deep against r-bar 108.5: 754, faithful). The members
    added have neighbourhoods cut by the frame; added down to any depth, or until the
    steps merely leave no half-plane empty, growth stalled where the copies of
    different candidates disagree (p2s7: 4 discs, 220 elements; p2s8: 2 discs, 592).

    With :data:`SURROUND_K`, members down to the same depth are added also until the
    class holds ``k`` interior members, as §5.1's k-coherence set co(e) holds k
    candidates: with fewer, every member of the class draws its copies from the same
    few neighbourhoods, and their spacing to their own class is the output's. Clusters
    EDGE p4 at variant seed 22 (large discs with full rings, one interior disc) copied
    every cluster from that disc, the exemplar's sparsest (its nearest disc 1.22
    cluster spacings away, the exemplar's median 1.08): at 3.5x the discs' median
    nearest disc lay 1.16-1.20 spacings away (the generator's 1.03-1.04), no disc more
    fitted, and discs and dots were at 0.84-0.87 of the exemplar's density (seeds 1-2
    failed density[dot]). With the next two discs (depth 0.88 and 0.70 of r-bar) the
    median is 1.04-1.05 and the density 0.90-0.97 (``python benchmarks/s31c_where.py
    clusters:p4s22 1-4``). The depth limit is kept: a candidate's neighbourhood is still
    at least :data:`SURROUND_DEPTH` of its r-bar inside the frame. Only in exemplars
    of fewer than :data:`SURROUND_K_CLASSES` size classes (clusters, rings): it would
    change 22 rows of three sizes' large stones at variant seeds 17-24
    (``benchmarks/results/s31c_affected.txt``), which were not audited; they keep the
    surround rule alone.
    """
    sc = cls[ids]
    few = k if SURROUND_K and len(np.unique(sc)) < SURROUND_K_CLASSES else 0
    for c in range(1, int(sc.max()) + 1 if len(ids) else 0):
        mem = np.flatnonzero(sc == c)
        if not inner[mem].any() or rbar_c[mem].min() <= rbar_c.min():
            continue  # only classes with their own larger r-bar (see element_parameters)
        for m in mem[np.argsort(-depth[mem], kind="stable")]:
            if depth[m] < SURROUND_DEPTH * rbar_c[m]:
                break
            steps = []
            for e in ids[mem[inner[mem]]]:
                seg = slice(ptr[e], ptr[e + 1])
                steps.append(off[seg][cls[idx[seg]] == c])
            ang = np.sort(np.arctan2(*np.concatenate(steps)[:, ::-1].T))
            if len(ang) and np.diff(np.r_[ang, ang[0] + 2.0 * np.pi]).max() < SURROUND_GAP and np.count_nonzero(inner[mem]) >= few:
                break
            inner[m] = True


def collision_radii(arr, pos: np.ndarray, r: np.ndarray, cls: np.ndarray, ptr: np.ndarray, idx: np.ndarray, off: np.ndarray) -> np.ndarray:
    """Collision radius of each exemplar element: the bounding disc of §4.1.

    Where the exemplar gives an element's radius (column ``radius`` differing from the
    shape's bounding circle), that radius is the collision bound, exactly as §4.1 has
    it: two output elements are at least ``r_p + r_q`` apart. Where the radius is the
    default (the shape's bounding circle, which for an elongated shape is far larger
    than the room it takes), it is shrunk per kind so that the exemplar's own discs do
    not overlap: ``rc = f_k r`` with ``f_k = min(1, 0.95 min |p_i - p_j| / (r_i + r_j))``
    over pairs with an element of kind k, or ``(0.95 |p_i - p_j| - r_j) / r_i`` against
    an element j whose radius is given (then ``rc_i + rc_j <= 0.95 |p_i - p_j|`` for
    every exemplar pair but two given ones), then grown by the share of the exemplar's
    gap between discs (see the comment in the code). Earlier one factor for the whole exemplar let one elongated
    or overlapping kind shrink every other kind's bound (discs of radius 6 came 6.15
    apart).

    Parameters
    ----------
    arr : Arrangement
        The concatenated exemplars (shapes and scales give the default radii).
    pos : (n, 2) float
    r : (n,) float
    cls : (n,) int
        Kind within exemplar of each element.
    ptr, idx, off : CSR neighbourhoods (self excluded).

    Returns
    -------
    (n,) float
    """
    default = np.array([float(arr.shapes[k].radius) for k in arr.kinds])[arr.kind] * np.abs(np.asarray(arr.scale, float))
    given = ~np.isclose(r, default, rtol=1e-9, atol=1e-12)
    ns = int(cls.max()) + 1 if len(cls) else 0
    f = np.ones(ns)
    if len(idx):
        owner = np.repeat(np.arange(len(pos)), np.diff(ptr))
        dist = np.hypot(off[:, 0], off[:, 1])
        if (dist <= 0).any():
            raise InputError("exemplar: two elements share a position; cannot learn spacing")
        given_cls = np.ones(ns, bool)
        np.logical_and.at(given_cls, cls, given)
        gi, gj = given_cls[cls[owner]], given_cls[cls[idx]]
        # both default: each shrinks to its share; against a given radius, the default
        # one takes what the given one leaves
        ratio = np.where(gj, np.maximum(0.95 * dist - r[idx], 0.0) / r[owner], 0.95 * dist / (r[owner] + r[idx]))
        keep = ~gi
        np.minimum.at(f, cls[owner][keep], ratio[keep])
    else:
        given_cls = np.ones(ns, bool)
        np.logical_and.at(given_cls, cls, given)
    f = np.where(given_cls, 1.0, np.minimum(f, 1.0))
    rc = f[cls] * r
    if len(idx):
        # Extension of §4.1: the exemplar's gap between discs. Dart-thrown stones keep
        # their pebbles at least 1.2 from their discs; with the discs alone as the
        # bound, copies came to touch (the smallest decile of the stone-to-pebble gap
        # 1.26 in the exemplar, 0.02 in the output: nn[stone>pebble] failed). Each
        # default-radius kind's disc grows by 0.475 of the smallest gap its elements
        # leave to any neighbour, so two kinds keep 0.95 of the gap between them and no
        # exemplar pair is closer than the grown discs allow (two_sizes 0/5 -> 5/5).
        # Kinds whose discs are shrunk below 0.9 of their bounding radius, and kinds
        # that meet them, keep their discs: their spacing is the shape test's (see
        # _shapes; growing the hubs of ring tiles broke the rings: 4/5 seeds -> 0/5).
        shrunk = f < 0.9
        meets = shrunk.copy()
        np.logical_or.at(meets, cls[owner], shrunk[cls[idx]])
        # Only kinds that neighbour another size class (§7 extension, see size_classes):
        # in one-size textures the closest approach (min_dist) carries the spacing, and
        # 0.95 of the gap instead of 0.95 of the distance left no room for a jittered
        # grid to settle under optimisation.
        sc = size_classes(r, area_radii(arr), arr.kind)
        mixed = np.zeros(ns, bool)
        np.logical_or.at(mixed, cls[owner], sc[owner] != sc[idx])
        meets |= ~mixed
        gap = np.full(ns, np.inf)
        np.minimum.at(gap, cls[owner], dist - rc[owner] - rc[idx])
        gap = np.where(np.isfinite(gap) & ~given_cls & ~meets, np.maximum(gap, 0.0), 0.0)
        rc = rc + 0.475 * gap[cls]
    return rc


def closest_approach(pos: np.ndarray, cls: np.ndarray, source: np.ndarray) -> np.ndarray:
    """Closest approach of every two classes within one exemplar (k-d trees).

    Measured over the whole exemplar, not only within neighbourhoods: two classes that
    never come within a neighbourhood radius of each other (the large discs of
    separate clusters) keep at least that distance in the output as well, instead of
    being bound by their radii alone.

    Parameters
    ----------
    pos : (n, 2) float
    cls : (n,) int
        Class of each element (its kind within its exemplar), 0 .. S-1.
    source : (n,) int

    Returns
    -------
    (S, S) float
        inf for classes of different exemplars and for a class with one element paired
        with itself.
    """
    ns = int(cls.max()) + 1 if len(cls) else 0
    out = np.full((ns, ns), np.inf)
    members = [np.flatnonzero(cls == a) for a in range(ns)]
    trees = [cKDTree(pos[m]) if len(m) else None for m in members]
    for a in range(ns):
        for b in range(a, ns):
            ma, mb = members[a], members[b]
            if len(ma) == 0 or len(mb) == 0 or source[ma[0]] != source[mb[0]]:
                continue
            if a == b:
                if len(ma) < 2:
                    continue
                d, _ = trees[a].query(pos[ma], k=2)
                out[a, a] = float(d[:, 1].min())
            else:
                d, _ = trees[b].query(pos[ma], k=1)
                out[a, b] = out[b, a] = float(d.min())
    return out


SIZE_STEP = K.SIZE_STEP  # bounding radii this many times apart are of different sizes


AREA_STEP = 1.5
"""With the radii of equal-area discs given (:func:`size_classes`' ``area_r``), a new
size class also needs that radius at least this many times the class's first."""


def area_radii(arr) -> np.ndarray:
    """(n,) float: radius of the disc of each element's shape area (times its scale);
    the bounding radius (column ``radius``) where the shape has no area."""
    per_kind = np.array([float(arr.shapes[k].area) for k in arr.kinds])
    a = np.sqrt(np.maximum(per_kind[arr.kind], 0.0) / np.pi) * np.abs(np.asarray(arr.scale, float))
    r = np.asarray(arr["radius"], float) if "radius" in arr else a
    return np.where(a > 0, np.minimum(a, r), r)


def size_classes(r: np.ndarray, area_r: np.ndarray | None = None, kind: np.ndarray | None = None) -> np.ndarray:
    """Size classes of bounding radii: 0 for the smallest, a new class from the first
    radius at least :data:`SIZE_STEP` times the current class's smallest.

    With ``area_r`` (the radii of equal-area discs, :func:`area_radii`), a new class
    also needs its area radius at least :data:`AREA_STEP` times that of the class's
    first element. Extension of the §7 split below: an elongated kind's bounding radius
    overstates its size. Stripes of dots (radius 2.5) and bars (12 x 2.5, bounding
    radius 6.1, area radius 3.1) were two classes, so the bars were placed first,
    yielded nothing to the dots and the dots leant on them (``parents``): bar bands
    spread over the dot bands (``benchmarks/synth_variants.py`` stripes EDGE p2, dot
    share 0.27-0.31 against the exemplar's 0.45-0.48, 3 of 4 runs failing). Kinds of
    the same shape family are unchanged (area and bounding radius scale together).

    §7 names "significant differences in element size" within an exemplar as a
    limitation of the method; the extensions that address it (generation in order of
    size, yielding, parents; see ``grow``) act between size classes only, so that
    kinds of about one size (long and square tiles, 1.8 apart in bounding radius, far
    less in area) keep the paper's behaviour.

    Parameters
    ----------
    r : (n,) float
    area_r : (n,) float, optional
    kind : (n,) int, optional
        With several kinds, each kind lies wholly in one class (see below).

    Returns
    -------
    (n,) int
    """
    if kind is not None and len(r):
        # Extension of the §7 split (helper sizes13): with several kinds, a kind is one
        # size. Where the radius steps cut through a kind (its radii spread across a
        # SIZE_STEP boundary), the whole kind takes the largest class its members
        # reached, so it stays apart from the smaller kinds and is not split between
        # "placed first" and "yields" (see grow). Two sizes with stones 1.7x the
        # pebbles (benchmarks/_variants.py EDGE p3) had 12 or 25 of 36-40 stones in a
        # class of their own and the rest in the pebbles' class: stones 0.77-0.89x
        # their density, pebbles up to 1.18x, nn[stone>stone] 0.088-0.115 against
        # 0.063-0.075 on all 4 runs; with whole kinds all 4 pass. One kind keeps
        # per-element classes only where its sizes step (ONE_KIND_GAP); a continuum of
        # sizes is one class.
        cls = size_classes(r, area_r)
        kind = np.asarray(kind, np.int64)
        kinds, inv = np.unique(kind, return_inverse=True)
        if len(kinds) > 1:
            top = np.zeros(len(kinds), np.int64)
            np.maximum.at(top, inv, cls)
            if np.any(top[inv] != cls):
                _, cls = np.unique(top[inv], return_inverse=True)
            if len(kinds) >= KIND_SPLIT_MIN and area_r is not None:
                cls = _split_kinds(cls, inv, np.asarray(area_r, float))
        elif ONE_KIND_CONTINUUM and _continuum(r):
            # One kind whose sizes are a continuum: one class (see ONE_KIND_GAP)
            cls = np.zeros(len(r), np.int64)
        return cls
    if area_r is not None and len(r):
        r = np.asarray(r, float)
        area_r = np.asarray(area_r, float)
        order = np.lexsort((area_r, r))
        out = np.zeros(len(r), np.int64)
        c, base, base_a = 0, r[order[0]], area_r[order[0]]
        for i in order:
            if r[i] >= SIZE_STEP * base * (1 - 1e-9) and area_r[i] >= AREA_STEP * base_a * (1 - 1e-9):
                c, base, base_a = c + 1, r[i], area_r[i]
            out[i] = c
        return out
    u = np.unique(np.asarray(r, float))
    cls_of = np.zeros(len(u), np.int64)
    base, c = (u[0] if len(u) else 0.0), 0
    for i, v in enumerate(u):
        if v >= SIZE_STEP * base * (1 - 1e-9):
            c += 1
            base = v
        cls_of[i] = c
    return cls_of[np.searchsorted(u, r)]


ONE_KIND_CONTINUUM = True
"""One kind whose sorted bounding radii never step by :data:`ONE_KIND_GAP` is one size class."""

ONE_KIND_GAP = 1.25
"""Step between consecutive sorted bounding radii of one kind that marks two sizes, not a continuum.

Extension of the §7 split (helper s26o, issue 13 point 1). The split (:data:`SIZE_STEP`, 2x
from the smallest) cuts a continuum of sizes at an arbitrary radius: stones of one outline
scaled 0.65-1.35 (``--harder`` stones h2) put the 1-9 largest of 74-108 stones in a class of
their own, whichever happened to reach twice the smallest. Placed first and leant on
(``parents``), a lone large stone stalled growth: h2s17 (one stone in class 1) grew 326
stones at 3.5x where its generator gives 1095-1291 (``benchmarks/syn18_oracle.py``), seeds
1-3 all failing, density 0.46-0.56 off. Consecutive steps of the audits' one-kind continua
stay under 1.12 (``benchmarks/s26o_size_class_survey.py``); two sizes of one kind step by
about their ratio, and keep the split.
"""


KIND_SPLIT_MIN = 3
"""Exemplars of at least this many kinds split a class by kind (:func:`_split_kinds`)."""

KIND_AREA_STEP = 1.4
"""Step of the kinds' median area radii that starts a new class in :func:`_split_kinds`.

Below :data:`AREA_STEP` (helper ssz, issue 13 point 1). A kind's stones are one outline
scaled 0.9-1.1, so kinds drawn 1.5 apart (``--harder`` three_sizes h11, ratios 1 : 3 :
4.5) have medians 1.44-1.64 apart, and a step of 1.5 split the ladder at some variant
seeds and not at others. Merged (h11s11: 1.46, h11s13: 1.445), the medium stones were
placed with the large ones rather than after them and took their places: at 3.5x,
seeds 1-6 of h11s11, large 0.83-0.86x their density, medium 1.24-1.31x, nn[medium>large]
failing at 4 of 6 seeds (0.084-0.119 against 0.0829). Split: large 0.94-0.95x, medium
0.91-0.95x, nn[medium>large] 0.057-0.095 (2 of 6 failing), as the generator's own draws
at that size (0.067-0.082). ``benchmarks/ssz_row.py``; ``benchmarks/ssz_scope.py`` lists
the exemplars of the audits it changes (6 of 148 three_sizes draws).
"""


def _continuum(r: np.ndarray) -> bool:
    """Whether the sorted radii ``r`` (n,) never step by :data:`ONE_KIND_GAP` or more."""
    r = np.sort(np.asarray(r, float))
    r = r[r > 0]
    return len(r) < 2 or bool(np.all(r[1:] < ONE_KIND_GAP * r[:-1]))


def _split_kinds(cls: np.ndarray, inv: np.ndarray, area_r: np.ndarray) -> np.ndarray:
    """Classes of kinds, with the kinds of one class split where their typical sizes step.

    Extension of the §7 split (helper sizes13b): in each class holding several kinds,
    the kinds in order of median area radius start a new class from the first whose
    median is at least :data:`KIND_AREA_STEP` times that of the class's first kind (a
    little below the equal-area step :func:`size_classes` needs, see there). The bounding-radius step
    (:data:`SIZE_STEP`, 2x) falls arbitrarily through a ladder of kinds each about 1.6x
    the last: three sizes 1 : 1.6 : 2.6 (``benchmarks/_variants.py`` three_sizes EDGE
    p2) had small and medium in one class at variant seed 7 and medium and large at
    seed 8. Merged with the small stones, the medium ones were placed with them rather
    than before them: medium 0.71x their density, large 1.31x, fraction[medium]
    0.124-0.127 against 0.106 and nn[small>medium] 0.24-0.25 against 0.126 (both
    seeds failing). Only exemplars of :data:`KIND_SPLIT_MIN` or more kinds: with two,
    kinds 1.5-2x apart (clusters EDGE p3, sparse apples and voids, ring hubs) keep one
    class.
    """
    out = cls.copy()
    key = np.zeros(len(cls), float)  # (class, rank of its split) -> renumbered below
    for c in np.unique(cls):
        ks = np.unique(inv[cls == c])
        if len(ks) < 2:
            continue
        med = np.array([float(np.median(area_r[inv == k])) for k in ks])
        order = np.argsort(med, kind="stable")
        base, step = med[order[0]], 0
        for j in order:
            if med[j] >= KIND_AREA_STEP * base * (1 - 1e-9):
                base, step = med[j], step + 1
            key[inv == ks[j]] = step
    if not np.any(key):
        return out
    _, out = np.unique(np.stack([cls, key], 1), axis=0, return_inverse=True)
    return out.reshape(-1).astype(np.int64)


ANCHOR_RATIO = 3.0
"""A kind is an anchor when the most numerous kind of its size class (in its exemplar)
has at least this many times its count (see :func:`anchor_mask`)."""


def _class_kinds(skind: np.ndarray, source: np.ndarray, cls: np.ndarray, void: np.ndarray):
    """The visible elements of each size class of each exemplar (``source``): yields
    ``(ids, c, sub, kinds, counts)``, ``ids`` the visible elements of the exemplar,
    int (n,), ``c`` the class, ``sub`` its elements, int (m,), and the kinds in it with
    their counts, int (k,) each."""
    vis = ~np.asarray(void, bool)
    for s_ in np.unique(source):
        ids = np.flatnonzero((source == s_) & vis)
        for c in np.unique(cls[ids]):
            sub = ids[cls[ids] == c]
            kinds, cnt = np.unique(skind[sub], return_counts=True)
            yield ids, c, sub, kinds, cnt


def anchor_mask(skind: np.ndarray, source: np.ndarray, cls: np.ndarray, void: np.ndarray, pos: np.ndarray | None = None,
                size: np.ndarray | None = None) -> np.ndarray:
    """(n,) int: 1 for exemplar elements of an anchor kind, else 0.

    Extension of §5.1 (§7's "structured" exemplars): within one size class, a kind
    that is rare beside the others (a ring's hub among its ten tiles: 16 against 161)
    is an anchor. Its copies are placed before the others' copies of the same iteration
    (``_grow.anchors``), and the other kinds of its class lean on it (:func:`parents`).
    Kinds of about equal counts (stripes' dots and bars, 66 and 68) are not anchors.

    Parameters
    ----------
    skind : (n,) int
        Kind-in-exemplar classes.
    source, cls : (n,) int
        Exemplar and size class of each element.
    void : (n,) bool
    pos, size : (n, 2) float and (n,) float, optional
        Element centres and sizes (area radii, :func:`area_radii`). With them a rare kind
        no larger than the class's most numerous kind (median size) is an anchor only
        where the others of its class stand around it (:func:`_stand_around`).
    """
    out = np.zeros(len(skind), np.int64)
    for _ids, _c, sub, kinds, cnt in _class_kinds(skind, source, cls, void):
        rare = kinds[cnt * ANCHOR_RATIO <= cnt.max()]
        if pos is not None and size is not None and len(rare):
            others = sub[~np.isin(skind[sub], rare)]
            top = np.median(size[sub[skind[sub] == kinds[np.argmax(cnt)]]])
            rare = np.array([k_ for k_ in rare if np.median(size[sub[skind[sub] == k_]]) > top
                             or _stand_around(pos[sub[skind[sub] == k_]], pos[others])], np.int64)
        out[sub[np.isin(skind[sub], rare)]] = 1
    return out


SCATTERED_FREE = True
"""A scattered kind keeps to itself at most the closest approach of its size class's
most numerous kind (:func:`_free_scattered`); False: its own, as every other pair."""


def _free_scattered(min_dist: np.ndarray, skind: np.ndarray, source: np.ndarray, cls: np.ndarray, void: np.ndarray,
                    anchor: np.ndarray) -> None:
    """Cap, in place, the closest approach of a scattered kind to itself at that of its
    size class's most numerous kind to itself (raw exemplar distances).

    A kind is scattered when it lies wholly within one size class, is rare there (the
    class's most numerous kind has at least :data:`ANCHOR_RATIO` times its count) and is
    no anchor (:func:`anchor_mask`: nothing stands around it). Its elements lie apart
    among the common kind's, so its nearest same-kind distances are few and far, and
    their minimum is a sample minimum, not a spacing the texture keeps; how close two
    elements of that size come is shown by the class's common kind.

    Extension of §5.1 (the closest approach learned over the whole exemplar, see
    :func:`closest_approach`; §4.1's radii give the collision bound): two sizes with
    pebbles 0.85 of the stones (``synth_variants.py --harder`` two_sizes h9s24) has 5
    pebbles among 40 stones; their closest approach, 81 (collision bound 22, stones'
    26), made every two output pebbles keep 77 apart, and growth, near jamming at that
    spacing, placed 0.56 of the exemplar's pebbles per stone (nn[stone>pebble] failing
    on seeds 1-3, 0.58-0.65 against 0.53). Dropping the pebbles' self spacing down to
    their radii instead (no cap) over-produced them on h9s19 (density[pebble] 0.93 and
    1.07 against 0.93 at seeds 1 and 3, main 0.63-0.73). Every pair of two kinds keeps
    the exemplar's closest approach.
    """
    for ids, c, _sub, kinds, cnt in _class_kinds(skind, source, cls, void):
        top = kinds[np.argmax(cnt)]
        for k_, n_ in zip(kinds, cnt):
            if n_ * ANCHOR_RATIO > cnt.max():
                continue
            mine = ids[skind[ids] == k_]
            if np.any(cls[mine] != c) or np.any(anchor[mine] > 0):
                continue
            min_dist[k_, k_] = min(min_dist[k_, k_], min_dist[top, top])


ANCHOR_AROUND = 0.15
"""Largest interquartile range of the others' distance to their nearest anchor, relative
to its median, of an anchor kind (see :func:`_stand_around`)."""


def _stand_around(anchor_pos: np.ndarray, other_pos: np.ndarray) -> bool:
    """Whether the other kinds of a class stand around the rare kind's elements at one
    distance (interquartile range of their distance to the nearest rare element at most
    :data:`ANCHOR_AROUND` times its median), as a ring's tiles around their hub (0) and
    a cluster's dots around their disc (0.97-1.05 of one radius).

    Extension of §5.1 (helper anchor13k, issue 13 point 1): an anchor is a hub or a
    cluster centre, an element the others are arranged around. Rarity alone also took
    the 9-12 pebbles squeezed between 38-45 stones of two sizes at ratio 0.8 and 0.4
    (one size class, area radius 0.66-0.79 times the stones'; ``benchmarks/
    synth_variants.py --harder`` two_sizes h4, h8; interquartile range 0.70-0.93 of the
    median, against 0-0.045 for every ring's hubs and clusters' discs) for anchors.
    The stones then leant on them (``parents``), were copied only with a pebble, and
    synthesis stalled: h4s7 seed 1 stopped at 304 elements (others about 900) with a
    third of the region empty. Hubs may be no larger than their tiles (rings of five or
    six tiles: area radius 0.94-0.99 times the tiles'), so size alone does not tell them
    apart; the spread of the distance does (``benchmarks/anchor13k_census.py``). A rare
    kind larger than the class's common one stays an anchor whatever the spread: the
    large stones among medium ones of three sizes (``--harder`` three_sizes h10s8, area
    radius 1.49 times, spread 0.50) pass as anchors and failed nn[small>small] on both
    seeds without.
    """
    if len(anchor_pos) == 0 or len(other_pos) < 4:
        return True
    d, _ = cKDTree(anchor_pos).query(other_pos)
    q1, med, q3 = np.percentile(d, [25, 50, 75])
    return bool(q3 - q1 <= ANCHOR_AROUND * med)


ANCHOR_CROSS = 1.1
"""An anchor that must reach the next anchor sees this many times its distance (see
:func:`anchor_reach`)."""


def anchor_reach(pos: np.ndarray, reach: np.ndarray, kind: np.ndarray, source: np.ndarray, void: np.ndarray, cls: np.ndarray,
                 size: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray | None]:
    """``reach`` (the distance each exemplar neighbourhood n(e) is stored to) with each
    element of an anchor's size class seeing its nearest foreign anchor (the nearest
    anchor but its own, :func:`anchor_mask`) times :data:`ANCHOR_CROSS`, in exemplars
    where no element sees a foreign anchor; and the (n,) bool mask of the anchors that
    n(e) holds beyond the old reach (None where nothing changed).

    Extension of §5.1 for structured exemplars (§7). Growth reaches a new ring only by
    copying a neighbourhood that holds its hub: a ring's tiles lean on their hub
    (:func:`parents`) and are never copied without it. Far-apart rings (rings of ten,
    radius 15, hubs 60 apart, ``benchmarks/synth_variants.py --harder`` rings h3: r-bar
    29.4, reach 40.2; a tile's nearest foreign hub is 45 away, a hub's 60) held no
    such neighbourhood, and synthesis stopped after the first ring (11 elements against
    about 1,900, 4 of 4 runs failing). Only where no element's n(e) holds a foreign
    anchor is the reach of the anchors alone extended; r-bar, and with it matching
    (Eq. 1 counts partial pairs within r-bar only), seed spacing and the free-space
    rules are unchanged: the extra neighbours only add the copies of a candidate (the
    next hub) and their free space. Beyond the old reach n(e) holds the foreign
    anchors only: with the foreign tiles too, tiles were copied at their offset from
    the seed beside a hub paired up to 2 r away, and 37 % of the tiles stood off any
    hub's ring (doubled, shifted rings; h3s7 seed 1). The hub's own ring is copied
    from the hub once it is placed. With ``size`` (area radii), the anchors are those of
    :func:`anchor_mask` given the centres and sizes. An exemplar without two anchors
    has its largest size class for hubs where most of them see no other (far-apart
    clusters' discs, :func:`_far_hubs`), and every visible element sees them.
    """
    reach = np.asarray(reach, float)
    void = np.asarray(void, bool)
    skind = np.unique(np.c_[source, kind], axis=0, return_inverse=True)[1].ravel()
    anchor = anchor_mask(skind, source, cls, void, pos, size) > 0
    out, far = reach, None
    for s_ in np.unique(source):
        a = np.flatnonzero(anchor & (source == s_))
        members = np.flatnonzero((source == s_) & ~void & np.isin(cls, cls[a]))
        if len(a) >= 2:
            d, _ = cKDTree(pos[a]).query(pos[members], k=2)
            if np.any(d[:, 1] <= reach[members]):  # some neighbourhood already holds a foreign anchor
                continue
        else:
            a, members = _far_hubs(pos, reach, cls, (source == s_) & ~void)
            if len(a) < 2:
                continue
            d, _ = cKDTree(pos[a]).query(pos[members], k=2)
        if out is reach:
            out, far = reach.copy(), np.zeros(len(reach), bool)
        out[members] = np.maximum(reach[members], ANCHOR_CROSS * d[:, 1])  # each member's nearest foreign anchor
        far[a] = True
    return out, far


def _far_hubs(pos: np.ndarray, reach: np.ndarray, cls: np.ndarray, own: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The hubs of one exemplar without anchors for :func:`anchor_reach` and the
    elements that must see them: the members of its largest size class (the elements
    the smaller classes lean on, :func:`parents`) and every element of ``own`` (its
    visible elements), where most hubs' neighbourhoods hold no other hub; else empty.

    Extension of §5.1, as :func:`anchor_reach` for anchors: far-apart clusters (discs
    90 apart in a 300 x 300 frame, ``synth_variants.py --varied`` clusters p2s27 and
    p2s28) get a disc r-bar capped at the depth of their deepest disc (56-74, see
    ``_palette.element_parameters``), so that one disc is interior, and a reach
    (r-bar + 2 r_max) below the next disc: no disc's n(e) held another (p2s28), or two
    of eight did (p2s27), and synthesis stopped after the seed patch (7 elements
    against about 600; 2 seeds an iteration, all dots, whose neighbourhoods hold their
    own ring only). Here every element sees its second nearest hub (a hub the nearest
    other one, a dot the next disc but its own) times :data:`ANCHOR_CROSS`, so that any
    seed, dot or disc, can copy the step to the next cluster. The test is on most hubs,
    not any: one close pair of discs (90.1 apart, reach 90.2) does not make growth cross.
    """
    ids = np.flatnonzero(own)
    if len(ids) < 3 or cls[ids].min() == cls[ids].max():
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    a = ids[cls[ids] == cls[ids].max()]
    if len(a) < 2:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    d, _ = cKDTree(pos[a]).query(pos[a], k=2)
    if np.mean(d[:, 1] <= reach[a]) >= 0.5:  # most hubs already see another
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    return a, ids


def parents(pos: np.ndarray, cls: np.ndarray, source: np.ndarray, void: np.ndarray, depth: np.ndarray | None = None,
            kind: np.ndarray | None = None, follow: np.ndarray | None = None, anchor: np.ndarray | None = None) -> np.ndarray:
    """The larger element each exemplar element leans on (-1 for none, -3 for one
    that may lie beyond the exemplar's edge).

    Extension of §5.1 (§7 names exemplars with elements of very different sizes a
    limitation): an element's parent is its nearest Delaunay neighbour, in its own
    exemplar, of a larger size class (voids neither have nor are parents).
    Small dots ringing a large disc have the disc as parent; pebbles in the gaps
    between stones have the nearest touching stone. Generation copies an element only
    with its parent, so that a neighbourhood's rim does not scatter small elements
    whose large element it cut off (clusters turned into dots everywhere).

    Parameters
    ----------
    pos : (n, 2) float
    cls : (n,) int
        Size classes (:func:`size_classes`).
    source : (n,) int
    void : (n,) bool
    depth : (n,) float, optional
        Distance of each element to its exemplar's domain edge. An element of a smaller
        class gets -3 when the element it leans on may have been cut off by the frame
        (a dot of a cropped cluster): its parent lies further away than the edge and
        more than 1.25 times its kind's median parent distance, or, with no parent,
        its nearest larger element lies further away than the edge. Generation never
        copies it beside a candidate (see ``_kernels.generate_proposals``). Copied with
        a neighbourhood, such dots stood alone between the clusters (clusters variant
        1: nn[dot>disc] failing, 0.11 against a tolerance of 0.05).
    kind : (n,) int, optional
        Kinds, for the median parent distance (default: size classes).
    follow : (n,) bool, optional, output
        Set True for elements whose parent is their only larger Delaunay neighbour.
    anchor : (n,) int, optional
        Anchor elements (:func:`anchor_mask`). An element with no larger Delaunay
        neighbour leans on its nearest Delaunay neighbour that is an anchor of its own
        class (a ring's tile on its hub), so that a ring is copied only with its hub, or
        around a hub already in the output (its tiles then placed from that hub:
        ``follow``). Without it, tiles copied without their hub stood a little inside
        the hub's closest approach and the hub never fitted: rings at 50x the
        exemplar's area had 12 interior hubless rings, whose empty centres failed 34 of
        143 local windows (issue 13 point 2).

    Returns
    -------
    (n,) int
    """
    from scipy.spatial import Delaunay, QhullError

    n = len(pos)
    out = np.full(n, -1, np.int64)
    for s in np.unique(source):
        ids = np.flatnonzero((source == s) & ~void)
        cc = cls[ids]
        an = np.zeros(len(ids), np.int64) if anchor is None else anchor[ids].copy()
        if an.any() and kind is not None:
            # only kinds wholly within one size class: a stone of a larger kind whose
            # scale puts it in the smaller class (three sizes 1:2:4 with +-10 % scales)
            # is rare there but anchors nothing
            kk = kind[ids]
            for k_ in np.unique(kk[an > 0]):
                if len(np.unique(cc[kk == k_])) > 1:
                    an[kk == k_] = 0
        if len(ids) < 3 or (cc.min() == cc.max() and not an.any()):
            continue
        try:
            tri = Delaunay(pos[ids])
        except QhullError:
            continue
        ip, nb = tri.vertex_neighbor_vertices
        for a in range(len(ids)):
            js0 = nb[ip[a] : ip[a + 1]]
            js = js0[cc[js0] > cc[a]]
            if len(js) == 0 and not an[a]:
                js = js0[(cc[js0] == cc[a]) & (an[js0] > 0)]
            if len(js):
                d = np.hypot(*(pos[ids[js]] - pos[ids[a]]).T)
                out[ids[a]] = ids[js[np.argmin(d)]]
                if follow is not None:
                    follow[ids[a]] = len(js) == 1
        if depth is not None:
            has = out[ids] >= 0
            pd = np.full(len(ids), np.inf)
            pd[has] = np.hypot(*(pos[out[ids[has]]] - pos[ids[has]]).T)
            kinds = kind[ids] if kind is not None else cc
            # elements that lean on something: smaller classes, and the non-anchors of a
            # class with anchors
            rank = 2 * cc + an
            leaning = (cc < cc.max()) | ((an == 0) & np.isin(cc, cc[an > 0]))
            for a in np.flatnonzero(leaning):
                if has[a]:
                    # a parent further than the edge and unusually far for its kind
                    same = has & (kinds == kinds[a])
                    cut = pd[a] > depth[ids[a]] and pd[a] > 1.25 * float(np.median(pd[same]))
                else:
                    larger = ids[rank > rank[a]]
                    cut = float(np.hypot(*(pos[larger] - pos[ids[a]]).T).min()) > depth[ids[a]]
                if cut:
                    out[ids[a]] = -3
            # an anchor with fewer children than the most of its kind, near enough to
            # the edge for the frame to have cut them off (a hub of a cropped ring):
            # never copied beside a candidate either, so that every anchor of the
            # output has the whole pattern of children that _grow snaps and completes
            # its ring to (rings at 50x the area: 32 of 324 hubs came from cut rings
            # with 7-8 of 10 tiles, and their rings kept a gap)
            if an.any():
                par_of = out[ids]
                nkids = np.bincount(par_of[par_of >= 0], minlength=len(pos))[ids]
                reach = np.zeros(len(ids))
                hasp = par_of >= 0
                np.maximum.at(reach, np.searchsorted(ids, par_of[hasp]), np.hypot(*(pos[par_of[hasp]] - pos[ids[hasp]]).T))
                kinds = kind[ids] if kind is not None else cc
                for kk in np.unique(kinds[an > 0]):
                    mine = (an > 0) & (kinds == kk)
                    most, far = nkids[mine].max(), reach[mine].max()
                    cut_anchor = mine & (nkids < most) & (depth[ids] < 1.25 * far)
                    out[ids[cut_anchor]] = -3
    return out


WALL_HELD = 0.75
"""A kind is held inside its exemplar's frame by its size where none of its centres
comes nearer the frame than this share of its largest bounding radius (see
:func:`frame_is_window`)."""

WALL_SPREAD = 1.25
"""Kinds keep off their exemplar's frame by different distances where the farthest
kept is at least this many times the nearest (see :func:`frame_is_window`)."""


def frame_is_window(pos: np.ndarray, kind: np.ndarray, r: np.ndarray, frame) -> bool:
    """Whether an exemplar's frame is a window on a larger texture rather than a wall
    that sorts its kinds by size along it.

    Extension of §5.1 (§7: mixes of sizes); the paper's exemplars have no frame of
    their own. A frame that keeps every element wholly inside it keeps each kind's
    centres off it by about the kind's radius: where the kinds differ in size, the band
    between the nearest approaches of the smaller and the larger kinds holds only the
    smaller ones, and the frame's inner part (shrunk by a margin, as
    ``_displace._inner_density`` counts) is the unbiased sample of the kind mix. Where
    the kinds keep off by about the same distance (sizes within a quarter of each
    other), or some kind crosses the frame as a crop's elements do, no band is sorted
    and the whole frame is the sample, and the bigger one.

    With ``m_k`` the least distance of kind k's centres to the frame's boundary (0 for a
    centre outside it) and ``r_k`` its largest bounding radius, the frame is a wall when
    there are two kinds or more, each is held inside by its size (``m_k >=``
    :data:`WALL_HELD` ``r_k``) and they keep off by different distances (``max m >=``
    :data:`WALL_SPREAD` ``min m``); otherwise a window. (The fidelity metric decides
    which of its exemplar's elements it counts kinds over by the same reading of a
    frame: helper s62d, ``benchmarks/results/s62d_notes.md``.)

    Parameters
    ----------
    pos : (n, 2) float
        Centres of the exemplar's visible elements.
    kind : (n,) int
    r : (n,) float
        Bounding radii.
    frame : shapely Polygon
        The exemplar's region.

    Returns
    -------
    bool
        True for a window (also for one kind, or none: no kind is kept off more than
        another), False for a wall.

    Examples
    --------
    Stones of radius 10 and pebbles of radius 4, each kept off the frame by its radius:
    a wall. Pebbles of radius 9 kept off by 9: a window.

    >>> import numpy as np, shapely
    >>> box = shapely.box(0, 0, 100, 100)
    >>> kind = np.array([0, 0, 1, 1])
    >>> pos = np.array([[10.0, 50], [50, 10], [4, 30], [30, 4]])
    >>> frame_is_window(pos, kind, np.array([10.0, 10, 4, 4]), box)
    False
    >>> pos = np.array([[10.0, 50], [50, 10], [9, 30], [30, 9]])
    >>> frame_is_window(pos, kind, np.array([10.0, 10, 9, 9]), box)
    True
    """
    import shapely

    kind = np.asarray(kind)
    kinds = np.unique(kind)
    if len(kinds) < 2:
        return True
    pts = shapely.points(np.asarray(pos, float))
    depth = np.where(shapely.contains(frame, pts), shapely.distance(frame.boundary, pts), 0.0)
    m = np.array([depth[kind == k].min() for k in kinds])
    rk = np.array([np.asarray(r, float)[kind == k].max() for k in kinds])
    wall = bool(np.all(m >= WALL_HELD * rk) and m.max() >= WALL_SPREAD * m.min())
    return not wall


def _spacing(p: np.ndarray) -> float:
    if len(p) < 2:
        return 0.0
    d, _ = cKDTree(p).query(p, k=2)
    return float(d[:, 1].mean())


OPEN_ROOM = 0.4
"""Several-size exemplars whose own room for more of their smallest elements
(:func:`open_room_share`) is at least this share of their smallest size class get the
neighbour limits of sparse exemplars (``_grow.neighbour_limits``)."""


def open_room_share(prep: Prepared) -> np.ndarray:
    """(exemplars,) float: how many more of its smallest elements each exemplar has room
    for, as a share of its smallest size class's count. Computed once per ``prep``.

    The room is the exemplar's open circles (Delaunay circumcircles of its centres,
    wholly inside its domain) at whose centre its smallest element would clear the
    three neighbours by ``max(rc_p + rc_q, min_dist)`` (the test of
    ``_grow.neighbour_limits``), counted greedily so that no two chosen centres are
    closer than twice that element's collision radius (they could hold one element
    each). Exemplars of one size class, or of one kind, get 0: a dart-thrown kind of
    widely spread sizes (stones EDGE, radius 9 with spread 0.45) splits into size
    classes whose smallest members fit most gaps (0.73), yet it passes unlimited.

    Extension of §5.1 for several sizes (§7): growth places a copy wherever a
    free-space point lies uncovered and the collision test passes, so a gap the
    exemplar leaves empty although its smallest element fits ends up filled. When the
    exemplar's smallest class is saturated (pebbles in every gap between stones) the
    share is small; when the smallest elements are a minority with room left between
    the larger ones, the output packs them. Measured (``benchmarks/synth_variants.py
    --varied``, the default two and three sizes and every VARIED / EDGE set): two sizes
    0.05-0.36 except its EDGE set with pebbles a minority (35 pebbles among 41-44
    stones: 0.49, 0.94; output pebbles 1.6-1.67x the exemplar's density), three sizes
    0.19-0.32 at default parameters except variant 2 (0.49; small stones 1.13x) and
    0.85 for EDGE 60/60/26 stones (small stones 1.5-1.64x); clusters 0.33-0.91, but
    they stay out through ``_grow.OPEN_SIZES``' upper bound.
    """
    got = getattr(prep, "_open_room", None)
    if got is not None and len(got) == len(prep.names):
        return got
    from ._grow import circles_within, circumcircles

    out = np.zeros(len(prep.names))
    for s, dom in enumerate(prep.domains):
        ids = np.flatnonzero(prep.source == s)
        cls = prep.size_class[ids]
        if len(ids) < 3 or len(np.unique(cls)) < 2 or len(np.unique(prep.kind[ids])) < 2:
            continue
        p = prep.pos[ids]
        cen, rad, tri = circumcircles(p)
        if len(rad) == 0:
            continue
        rc, sk = prep.rc[ids], prep.skind[ids]
        sm = int(np.argmin(rc))
        need = np.maximum(rc[sm] + rc[tri], prep.min_dist[sk[sm], sk[tri]]).max(axis=1)
        room = rad >= need
        room[room] = circles_within(dom, cen[room], rad[room])  # holes and parts too
        c = cen[room]
        if len(c) == 0:
            continue
        order = np.argsort(-(rad[room] - need[room]), kind="stable")  # widest first
        tree = cKDTree(c)
        taken = np.zeros(len(c), bool)
        blocked = np.zeros(len(c), bool)
        for i in order:
            if blocked[i]:
                continue
            taken[i] = True
            blocked[tree.query_ball_point(c[i], 2.0 * rc[sm] * (1 - 1e-9))] = True
        out[s] = float(taken.sum()) / float((cls == cls.min()).sum())
    prep._open_room = out
    return out


RING_CAP_CV = 0.05
"""Children keep one distance to their parent for :func:`ring_caps` when their exemplar
distances to parents of one kind vary by at most this share of their mean (std / mean).
Looser than ``_optimize.RING_CV`` (0.005), which also switches on ring projection and
ring completion; clusters' dots on their discs: 0.020-0.023."""


RING_CAP_SHARE = 0.5
"""... and when those children are at least this share of their kind in their exemplar
(see :func:`ring_caps`)."""


def ring_caps(prep: Prepared) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The data of ``_grow._ring_full``: which children growth caps on their parent's
    ring, how far from a parent they count, and how many each exemplar element holds.
    Computed once per ``prep``.

    Returns
    -------
    capped : (n,) bool
        Children of a larger size class (``Prepared.parent``, not voids) whose (kind,
        parent kind) pair has at least 3 members, at least :data:`RING_CAP_SHARE` of
        their kind, whose distances to their parents have std / mean at most
        :data:`RING_CAP_CV` (one distance), and whose parents hold rings: at least
        :data:`RING_CAP_HELD` of those the frame leaves whole hold two or more of them
        (:func:`ring_groups`).
    reach : (n,) float
        1.5 times a capped child's exemplar distance to its parent (0 elsewhere): an
        output element of the parent's kind within this of a copy is the copy's parent,
        and the children of the copy's kind within this of that parent are its ring.
    cap : (n, kinds) int
        Each exemplar element's count of children of each kind (its ring), or, where
        the exemplar's frame may cut its ring, the largest such count among the
        elements of its kind in its exemplar. A frame cuts the ring of an element
        nearer its domain's edge (holes too) than its farthest child plus that child's
        collision radius, or than 1.2 times its exemplar's median child distance
        (which covers an element without a child in the frame).

    Notes
    -----
    Helper s65c after s64c's counterfactual (``benchmarks/s64c_stages.py --ring-cap
    ownincv``, same semantics; the medians and the largest ring are taken per exemplar
    here, per palette there, and a ring counts children of the copy's kind only, all
    children there: the same for one exemplar with one child kind). The share is not
    s64c's: without it a few small stones touching a boulder (their contact distance
    keeps cv <= 0.05) were capped in ``--varied`` three sizes p0s30 (9 of 140 small
    stones), p4s20, p4s36 and p4s37 (6, 6, 5 of 60); clusters' dots are 0.82-0.97 of
    their kind (the rest: dots of rings the frame crops).
    """
    got = getattr(prep, "_ring_caps", None)
    if got is not None and len(got[0]) == len(prep.kind):
        return got
    n = len(prep.kind)
    kinds = int(prep.kind.max()) + 1 if n else 0
    capped = np.zeros(n, bool)
    reach = np.zeros(n)
    cap = np.zeros((n, kinds), np.int64)
    groups = ring_groups(prep)
    for g in groups:
        if g["gated"] and g["held"] >= RING_CAP_HELD:
            capped[g["members"]] = True
    if groups:
        has = np.concatenate([g["members"] for g in groups])
        d = np.hypot(*(prep.pos[has] - prep.pos[prep.parent[has]]).T)
        reach[has] = np.where(capped[has], 1.5 * d, 0.0)
    if capped.any():
        kids = np.flatnonzero(prep.parent >= 0)
        np.add.at(cap, (prep.parent[kids], prep.kind[kids]), 1)
        cut = frame_cut(prep)
        for s in range(len(prep.domains)):
            ids = np.flatnonzero(prep.source == s)
            c = ids[cut[ids]]
            for k in np.unique(prep.kind[c]):
                same = ids[prep.kind[ids] == k]
                cap[c[prep.kind[c] == k]] = cap[same].max(axis=0)
    prep._ring_caps = (capped, reach, cap)
    return prep._ring_caps


RING_CAP_HELD = 0.75
"""... and when at least this share of their parents whose ring the exemplar's frame leaves
whole hold two or more of them (:func:`ring_groups`' ``held``): a ring, not a contact."""


def frame_cut(prep: Prepared) -> np.ndarray:
    """(n,) bool: exemplar elements whose ring of children the exemplar's frame may cut:
    nearer their domain's edge (holes too) than their farthest child plus that child's
    collision radius, or than 1.2 times their exemplar's median child distance (which
    covers an element without a child in the frame). Computed once per ``prep``."""
    got = getattr(prep, "_frame_cut", None)
    if got is not None and len(got) == len(prep.kind):
        return got
    import shapely

    n = len(prep.kind)
    out = np.zeros(n, bool)
    kids = np.flatnonzero(prep.parent >= 0)
    dist = np.hypot(*(prep.pos[kids] - prep.pos[prep.parent[kids]]).T)
    far = np.zeros(n)
    np.maximum.at(far, prep.parent[kids], dist + prep.rc[kids])
    for s, dom in enumerate(prep.domains):
        ids = np.flatnonzero(prep.source == s)
        own = prep.source[kids] == s
        if len(ids) == 0 or dom is None:
            continue
        r = np.maximum(far[ids], 1.2 * np.median(dist[own]) if own.any() else 0.0)
        out[ids[shapely.distance(shapely.boundary(dom), shapely.points(prep.pos[ids])) < r]] = True
    prep._frame_cut = out
    return out


def ring_groups(prep: Prepared) -> list[dict]:
    """The groups :func:`ring_caps` may cap: children of a larger size class
    (``Prepared.parent``, not voids) per (kind, parent kind, exemplar), each a dict with
    ``members`` (element indices), ``share`` (of their kind in their exemplar), ``cv``
    (std / mean of their distances to their parents), ``gated`` (at least 3 members,
    share >= :data:`RING_CAP_SHARE`, cv <= :data:`RING_CAP_CV`), ``parents`` (how many
    elements hold them) and ``held``: the share of those parents that hold two or more
    of them, among the parents whose ring the frame leaves whole (:func:`frame_cut`;
    among all of them where the frame cuts every one); computed for gated groups only
    (nan elsewhere).

    Notes
    -----
    The guard ``held >= RING_CAP_HELD`` (helper s67c) keeps the cap to rings. Without
    it s65c's cap also took one-distance contacts: medium stones touching large ones in
    ``--harder`` three sizes h6 (size 150, counts 80:20:30; 8 of variant seeds 7-40,
    h6s19 among them: 12 of 14 medium stones, 8 large stones holding one and 2 holding
    two, which cost ``tests/synth/test_synth_s30h_far_top.py``), h11 (2 seeds),
    ``--varied`` three sizes p1s11 and two sizes p3 (3 seeds). A ring generator puts at
    least its smallest ring on every parent (clusters: ``ring_min`` dots, 2 to 7 in
    the audits' sets), so every parent with a whole ring holds two or more; a contact
    gives most large stones one. Measured on every exemplar s65c's gates pass (variant
    seeds 7-40): every clusters exemplar holds 1.00, the contacts 0.14-0.62
    (``benchmarks/results/s67c_notes.md``). Part of the departure from §5.1 described
    at ``_grow._ring_full`` (the paper's growth has no cap).
    """
    has = np.flatnonzero((prep.parent >= 0) & ~prep.void)
    has = has[prep.size_class[prep.parent[has]] != prep.size_class[has]]
    if not len(has):
        return []
    par = prep.parent[has]
    d = np.hypot(*(prep.pos[has] - prep.pos[par]).T)
    pair = np.c_[prep.skind[has], prep.skind[par], prep.source[has]]
    _, inv = np.unique(pair, axis=0, return_inverse=True)
    inv = inv.ravel()
    out = []
    for g in np.unique(inv):
        m = inv == g
        c0 = has[m][0]
        kin = np.sum((prep.kind == prep.kind[c0]) & (prep.source == prep.source[c0]) & ~prep.void)
        gated = bool(m.sum() >= 3 and m.sum() >= RING_CAP_SHARE * kin and d[m].std() <= RING_CAP_CV * d[m].mean())
        up, cnt = np.unique(par[m], return_counts=True)
        held = np.nan
        if gated:
            whole = ~frame_cut(prep)[up]
            held = float(np.mean(cnt[whole] >= 2)) if whole.any() else float(np.mean(cnt >= 2))
        out.append({"members": has[m], "share": float(m.sum() / kin), "cv": float(d[m].std() / d[m].mean()), "gated": gated,
                    "parents": len(up), "held": held})
    return out

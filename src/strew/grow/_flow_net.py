"""Flow mode: the bent lattice's bond network relaxed as a whole, last (issue 14 point 2).

Not in the paper. Grown along a bending field a hexagonal lattice keeps its topology
(about 93-100% of the interior sites have six Delaunay neighbours under 1.6 mean
edges, ``topo_six_share`` of ``benchmarks/grow.py --structure --flow-only``) but not
its metric: where the rows fan out, bands of bonds are stretched or sheared to
1.15-1.2 mean edges, so most failing sites have fewer than six neighbours at
0.85-1.15 mean edges (``ns_stretch``). §5.5's relaxation keeps each element's ring
as matched, in the field's frame; a lattice whose frame turns cannot keep all of
them (its rotation field is incompatible with zero strain: the geometrically
necessary dislocations, which the growth has already made, take the rest), and the
windowed relaxation sees too little of the band to spread the strain.

Here Eq. 5 is generalised to the whole network at once, as an as-rigid-as-possible
fit (local/global iterations): each round takes every Delaunay bond under
``1.4`` mean edges of the placed elements, wants it one mean edge long in its current
direction (the exemplar's bond, in the frame the bond has; a regular hexagonal
exemplar's bonds are all one mean edge), and solves the sparse least squares

    min_x  sum_(i,j) || x_j - x_i - l u_ij ||^2 + hold * sum_i || x_i - x_i' ||^2

(``x_i'`` the positions of the round before, ``hold``: ``flow_net_hold``) for all
elements together; held elements (Eq. 6) stay. A solved position within half a mean
edge of the region's edge is not taken (the element stays where it was that round).
After ``flow_net_rounds`` rounds the moves are made as
:func:`strew.grow._flow_shear._settle` makes them (a move whose outline would leave
the region is not made; elements that then overlap go back with those they overlap;
nothing turns, so each element keeps its frame, §5.3), and the result is kept only
where it leaves more interior sites with six elements at 0.85-1.15 mean edges and no
more interior points farther than 0.75 mean edges from every element
(:func:`strew.grow._flow_retry.interior_score`); else every element goes back.

Only for exemplars whose interior elements nearly all have six bonds of nearly one
length (a square lattice's diagonals are no bonds of one mean edge).

Departs from §5.5: the whole pattern at once after the growth (not windows during
it), bond lengths rather than the matched ring offsets as the targets, iterated.
"""

from __future__ import annotations

import numpy as np

from ._objects import ELEMENT

__all__ = ["relax_network", "hexagonal_reference"]


def hexagonal_reference(ref) -> bool:
    """Is the exemplar a regular hexagonal lattice: at least 90% of its interior
    elements with six Delaunay bonds, the bonds' lengths within 10% (coefficient of
    variation) of their mean?"""
    e = np.asarray(ref.edges)
    if len(e) == 0:
        return False
    xy = np.asarray(ref.xy, dtype=float)
    n = len(xy)
    deg = np.bincount(e.ravel(), minlength=n)
    inner = np.asarray(ref.interior, dtype=bool)
    if not inner.any():
        return False
    ln = np.hypot(*(xy[e[:, 1]] - xy[e[:, 0]]).T)
    touch = inner[e[:, 0]] | inner[e[:, 1]]
    ln = ln[touch] if touch.any() else ln
    return bool((deg[inner] == 6).mean() >= 0.9 and float(ln.std()) <= 0.1 * float(ln.mean()))


def _delaunay_bonds(pts: np.ndarray, cut: float) -> np.ndarray:
    from scipy.spatial import Delaunay

    s = Delaunay(pts).simplices
    e = np.unique(np.sort(np.r_[s[:, [0, 1]], s[:, [1, 2]], s[:, [0, 2]]], axis=1), axis=0)
    ln = np.hypot(*(pts[e[:, 1]] - pts[e[:, 0]]).T)
    return e[ln < cut]


def relax_network(g) -> int:
    """Relax the placed elements' bond network to one mean edge per bond (see the
    module), up to ``flow_net_passes`` times while each pass is kept; how many
    elements moved."""
    moved = 0
    for _ in range(int(g.p.flow_net_passes)):
        m = _relax_once(g)
        if m == 0:
            break
        moved += m
    return moved


def _relax_once(g) -> int:
    """One pass of :func:`relax_network`; how many elements moved (0 where the result
    was not kept)."""
    import scipy.sparse as sps
    from scipy.sparse.linalg import factorized

    p = g.p
    rounds = int(p.flow_net_rounds or 0)
    L = g.l
    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.intp)
    n = len(els)
    if rounds <= 0 or n < 7:
        return 0
    pts0 = g.pos[els].copy()
    held = np.asarray([bool(g.fixed[o]) for o in els.tolist()], dtype=bool)
    hold = float(p.flow_net_hold)
    rest = float(p.flow_net_rest)
    stiff = float(p.flow_net_stiff)
    contact = bool(p.flow_net_contact)
    touch: dict[int, float] = {}
    rg = g.region
    pts = pts0.copy()
    big = 1e6
    anchor = np.where(held, big, hold)
    for _ in range(rounds):
        e = _delaunay_bonds(pts, 1.4 * L)
        m = len(e)
        if m == 0:
            return 0
        dv = pts[e[:, 1]] - pts[e[:, 0]]
        ln = np.maximum(np.hypot(dv[:, 0], dv[:, 1]), 1e-12 * L)
        want = rest * L * np.ones(m)
        if contact:
            key = e[:, 0] * n + e[:, 1]
            miss = np.asarray([k not in touch for k in key.tolist()], dtype=bool)
            if miss.any():
                dm = _contact(g, els, e[miss], dv[miss] / ln[miss, None], L)
                touch.update(zip(key[miss].tolist(), dm.tolist()))
            want = np.maximum(want, 1.02 * np.asarray([touch[k] for k in key.tolist()]))
        t = want[:, None] * dv / ln[:, None]
        w = np.where(ln < want, stiff, 1.0)
        sw = np.sqrt(w)
        B = sps.csr_matrix((np.r_[-sw, sw], (np.r_[np.arange(m), np.arange(m)], np.r_[e[:, 0], e[:, 1]])), shape=(m, n))
        A = (B.T @ B + sps.diags(anchor)).tocsc()
        solve = factorized(A)
        rhs = B.T @ (sw[:, None] * t) + anchor[:, None] * pts
        new = np.c_[solve(np.ascontiguousarray(rhs[:, 0])), solve(np.ascontiguousarray(rhs[:, 1]))]
        new[held] = pts[held]
        if rg is not None:
            bad = ~rg.contains(new) | (rg.distance_to_boundary(new) < 0.5 * L)
            new[bad] = pts[bad]
        pts = new
    share0 = _six_share(g)
    gaps0 = _far_points(g)
    moves: dict[int, tuple[float, float]] = {}
    old: dict[int, tuple] = {}
    tiny = 1e-9 * L
    for q in range(n):
        o = int(els[q])
        nx, ny = float(pts[q, 0]), float(pts[q, 1])
        ox, oy = g.xy[o]
        if abs(nx - ox) + abs(ny - oy) > tiny:
            moves[o] = (nx, ny)
            old[o] = (ox, oy, g.geom[o], float(g.rot[o]))
    if not moves:
        return 0
    level = _settle_steps(g, moves, old)
    _undo_gaps(g, moves, old, level, gaps0, 1.5)
    share1 = _six_share(g)
    gaps1 = _far_points(g)
    if share1 > share0 and len(gaps1) <= len(gaps0):
        return sum(1 for o in moves if g.xy[o] != old[o][:2])
    for o, (x, y, geom, rot) in old.items():
        if g.xy[o] != (x, y):
            g._move(o, x, y)
        g.geom[o] = geom
        g.rot[o] = rot
    return 0


#: the shares of a move tried in turn where the whole move makes an overlap or leaves
#: the region (the last: no move)
_STEPS = (1.0, 0.5, 0.25, 0.0)


def _settle_steps(g, moves: dict, old: dict) -> dict:
    """Make the fitted ``moves`` (element -> position), each shortened along its way
    (:data:`_STEPS`) where its outline would leave the region or cross a boundary
    stroke, or overlap another; elements in an overlap both step back, until none is
    left (the positions before had none, so this ends). Nothing turns (§5.3). Returns
    each element's step (an index into :data:`_STEPS`)."""
    level = {o: 0 for o in moves}
    check = [o for o in moves if _place(g, o, moves, old, level)]
    _resolve(g, moves, old, level, check)
    return level


def _place(g, o: int, moves: dict, old: dict, level: dict) -> bool:
    """Put ``o`` at its current step, stepping back while it leaves the domain; True
    (it is placed)."""
    ox, oy, geom0, rot = old[o]
    tx, ty = moves[o]
    while True:
        f = _STEPS[level[o]]
        if f == 0.0:
            if g.xy[o] != (ox, oy):
                g._move(o, ox, oy)
            g.geom[o] = geom0
            return True
        x, y = ox + f * (tx - ox), oy + f * (ty - oy)
        if g.in_domain(x, y) and not (g.boundary is not None and g.crosses_boundary((ox, oy), (x, y))):
            geom = g.element_geometry(int(g.kind[o]), x, y, rot, float(g.scl[o]))
            if g.fits_domain(geom):
                g._move(o, x, y)
                g.geom[o] = geom
                return True
        level[o] += 1


def _resolve(g, moves: dict, old: dict, level: dict, check: list) -> None:
    """Step back the elements of ``check`` (and those near) in an overlap, both of
    each pair, until none is left."""
    while check:
        hits = g.overlapping_many(check)
        back: set[int] = set()
        for o, hs in hits.items():
            for j in [o, *(g.orig_of[h] for h in hs)]:
                if j in level and _STEPS[level[j]] > 0.0:
                    back.add(j)
        if not back:
            break
        for o in sorted(back):
            level[o] += 1
            _place(g, o, moves, old, level)
        check = sorted({j for o in back for j in g.near(*g.xy[o], 2.0 * g.l, (ELEMENT,)) if j in level} | back)


def _six_share(g) -> float:
    """The share of the placed elements over two mean edges inside the region with
    six elements at 0.85-1.15 mean edges and none nearer (``six_nbr_share`` of
    ``benchmarks/grow.py``)."""
    from scipy.spatial import cKDTree

    L = g.l
    els = [i for i in g.order if g.state[i] == ELEMENT]
    xy = g.pos[els]
    q = xy[g.region.distance_to_boundary(xy) > 2.0 * L] if g.region is not None else xy
    if not len(q):
        return 0.0
    tree = cKDTree(xy)
    hi = np.array([len(v) for v in tree.query_ball_point(q, 1.15 * L)], dtype=int) - 1
    lo = np.array([len(v) for v in tree.query_ball_point(q, 0.85 * L)], dtype=int) - 1
    return float(((hi == 6) & (lo == 0)).mean())


def _far_points(g) -> np.ndarray:
    """The points of :func:`strew.grow._flow_retry.interior_score`'s grid farther
    than 0.75 mean edges from every placed element, (k, 2)."""
    from scipy.spatial import cKDTree

    L = g.l
    els = [i for i in g.order if g.state[i] == ELEMENT]
    xy = g.pos[els]
    rg = g.region
    if rg is not None:
        x0, y0, x1, y1 = (float(v) for v in rg.bounds)
    else:
        (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
    grid = np.mgrid[x0 + 2 * L : x1 - 2 * L : 0.25 * L, y0 + 2 * L : y1 - 2 * L : 0.25 * L].reshape(2, -1).T
    if rg is not None and len(grid):
        # (on the band's inner edge too: benchmarks/grow.py's grid starts there)
        grid = grid[rg.contains(grid) & (rg.distance_to_boundary(grid) > 2.0 * L - 1e-9 * L)]
    if not len(grid):
        return grid
    return grid[cKDTree(xy).query(grid, distance_upper_bound=0.75 * L)[0] > 0.75 * L]


def _undo_gaps(g, moves: dict, old: dict, level: dict, far0: np.ndarray, reach: float) -> None:
    """Where the moves opened gaps (far points that were not far before), the elements
    within ``reach`` mean edges of them go back (and those then overlapping them step
    back), up to three times."""
    from scipy.spatial import cKDTree

    L = g.l
    last = len(_STEPS) - 1
    was = cKDTree(far0) if len(far0) else None
    for _ in range(3):
        far = _far_points(g)
        if was is not None and len(far):
            far = far[was.query(far)[0] > 1e-9 * L]
        if not len(far):
            return
        back = sorted({j for q in far.tolist() for j in g.near(q[0], q[1], reach * L, (ELEMENT,)) if j in level and level[j] != last})
        if not back:
            return
        for o in back:
            level[o] = last
            _place(g, o, moves, old, level)
        _resolve(g, moves, old, level, back)


def _contact(g, els, e, u, L: float, steps: int = 7) -> np.ndarray:
    """For each bond ``e`` (rows of indices into ``els``) with unit direction ``u``
    (from its first element to its second), the centre distance at which the two
    outlines, as they are turned, just touch when the second slides along ``u``
    (bisection over 0.5-1.2 mean edges, ``steps`` halvings; 0.5 mean edges where they
    do not touch there)."""
    import shapely

    a = np.asarray([g.geom[int(els[i])] for i in e[:, 0].tolist()], dtype=object)
    b = np.asarray([g.geom[int(els[j])] for j in e[:, 1].tolist()], dtype=object)
    pa = g.pos[els[e[:, 0]]]
    pb = g.pos[els[e[:, 1]]]
    coords, idx = shapely.get_coordinates(b, return_index=True)
    rel = coords - pb[idx]
    lo = np.full(len(e), 0.5 * L)
    hi = np.full(len(e), 1.2 * L)
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        at = pa + mid[:, None] * u
        moved = shapely.set_coordinates(shapely.from_wkb(shapely.to_wkb(b)), rel + at[idx])
        hit = shapely.intersects(a, moved)
        lo = np.where(hit, mid, lo)
        hi = np.where(hit, hi, mid)
    return hi

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
After ``flow_net_rounds`` rounds the moves are made, each shortened (a half, a
quarter, none) where its outline would leave the region or overlap another (both of
an overlapping pair step back, until none is left); nothing turns, so each element
keeps its frame (§5.3). Where a point of a quarter-edge grid over two mean edges
inside the region is then farther than 0.75 mean edges from every element and was
not before (a new gap), the elements within 1.5 mean edges of it go back. The result
is kept only where it leaves a larger share of the interior sites (over two mean edges
inside) with six elements at 0.85-1.15 mean edges and none nearer, no new gap, and the
lattice's turn from the field (the 90th percentile over the interior of its six-fold
bond direction less the field's angle, as ``benchmarks/grow.py`` measures it) at most
``flow_net_turn`` degrees over the grown lattice's: the fit lets the bonds turn
freely, and unshearing a band turns its star (with the whole moves, the 90 degree
field from the centre, without the retry of :mod:`strew.grow._flow_retry`: 0.899
six-neighbour sites, 0.832 before, but the turn's 90th percentile 17.7
-> 18.8 degrees). Else the moves are tried halved (``flow_net_steps``), else every
element goes back. Up to ``flow_net_passes`` passes, while one is kept.

Last, after :mod:`strew.grow._flow_densify`, the same passes once more with a band
(:data:`NET_BAND`, 0.9-1.12 mean edges) in place of the one-edge target. Measured
on the twelve flow cases of ``benchmarks/grow.py --structure --flow-only``: every
failing interior site there has too few neighbours within 1.15 mean edges (none is
pressed), and its sixth lies at 1.15-1.22 mean edges for 32 of 111 such sites (the
90 degree field from the corner (2, 18)) to 126 of 192 (45 x 30 spacings, centre);
and the fitted positions of the one-edge pass would pass 0.90 of the sites (that
corner case) where the moves made leave 0.74-0.76: about a hundred elements step back
whole to clear overlaps, and the pass is kept or dropped as a whole. So here each
bond is wanted at its own length clipped into the band (a bond within it pulls
nothing; the lattice around takes up a stretched bond's excess within the band,
where the one-edge target spreads it over every bond and leaves the stretched ones
over 1.15); only the elements within :data:`NET_WINDOW` mean edges of a site without
six neighbours move (the rest are held, Eq. 6); the bonds of the first round are kept
through the rounds (an elastic network: no bond flips to another neighbour while it
is fitted, which also raised the six share); and after the moves, where a site that
had six neighbours has lost them, the elements within 1.2 mean edges of it go back
(so the gains elsewhere are kept), and where an empty circle wider than 0.74 mean
edges in radius opened (found exactly, as Delaunay circumcircles, rather than on the
grid), the elements within 1.5 mean edges of it go back; then, as in the one-edge pass,
where a point of the quarter-edge grid is newly farther than 0.75 mean edges from every
element, those within 1.5 mean edges of it go back too (the acceptance below counts
the grid's points: on the quarter circles 45 x 45 spacings from the centre the band's
pass had reached 0.866 but was refused whole for one such point, a circle that was
already near 0.74 and grew, so 0.810 stayed; with these sent back it is kept, 0.883,
no hole: ``benchmarks/grow.py --structure --flow-only``). As before, a pass is kept
only where the six share rises with no new gap and the turn within its limit, so the
pass cannot lower the six share. Where the band's pass turns the lattice past
``flow_net_turn``, the elements around the sites it turned from the field (over the
limit, more than before) go back too, so the pass is refused for its turn only where
that is not enough (:func:`_undo_turn`; the one-edge pass keeps the whole-pass limit:
there the same lowered the corner (2, 18) 0.828 -> 0.805). The band's passes run
twice from the same positions, the second time clearing overlaps one element of a
pair at a time, and the run with the larger six share is kept (:func:`_band_passes`).
Departs from §5.5 as above, with a dead band in place of Eq. 5's exact offsets.

Only for exemplars whose interior elements nearly all have six bonds of nearly one
length (a square lattice's diagonals are no bonds of one mean edge).

Departs from §5.5: the whole pattern at once after the growth (not windows during
it), bond lengths rather than the matched ring offsets as the targets, iterated.
"""

from __future__ import annotations

import math
import weakref

import numpy as np

from ._flow_kernels import boundary_distance
from ._flow_memo import memo
from ._flow_shear import fitted_moves, saved_moves, undo_moves
from ._near_kernels import ball_counts, far_from
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


#: grower -> (the positions' bytes, their triangulation): the last Delaunay
#: triangulation made by :func:`triangulation` (kept outside the grower's state, so
#: :func:`strew.grow._flow_retry.snapshot` does not copy it)
_LAST_TRI: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()

#: grower -> [(the positions' bytes, their triangulation), ...]: the
#: :data:`TRI_KEEP` - 1 triangulations made before the last, the most recent first
_OLDER_TRI: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def triangulation(pts: np.ndarray, g=None):
    """``scipy.spatial.Delaunay(pts)``; with the grower ``g``, the one made for it
    where ``pts`` held the same values, if it is among the last :data:`TRI_KEEP`
    (compared by bytes: the same input, so the same triangulation).

    (Issue 14 point 5: a band pass triangulates the positions it starts from twice,
    for its bonds (:func:`_delaunay_bonds`) and for the empty circles
    (:func:`_far_circles`), and the next pass starts from the positions whose empty
    circles the last one measured; on the hexagonal lattice along the 90 degree field
    over 63 x 42 spacings, 418 triangulations of 2,980 elements made 12% of the
    growth's time under cProfile, ``benchmarks/results/g63v_profile_main_shares.txt``.)"""
    from scipy.spatial import Delaunay

    if g is None:
        return Delaunay(pts)
    key = (np.shape(pts), np.ascontiguousarray(pts, dtype=float).tobytes())
    try:
        got = _LAST_TRI.get(g)
    except TypeError:  # (a stand-in that takes no weak reference)
        return Delaunay(pts)
    if got is not None and got[0] == key:
        return got[1]
    older = _OLDER_TRI.get(g)
    if older is None:
        older = _OLDER_TRI[g] = []
    for q, (k, tri) in enumerate(older):
        if k == key:
            # (kept from a few triangulations before: the most recent again)
            older.pop(q)
            if got is not None:
                older.insert(0, got)
            _LAST_TRI[g] = (k, tri)
            return tri
    tri = Delaunay(pts)
    if got is not None:
        older.insert(0, got)
        del older[TRI_KEEP - 1 :]
    _LAST_TRI[g] = (key, tri)
    return tri


#: how many triangulations :func:`triangulation` keeps per grower, the most recent
#: first. (g70v, issue 14 point 5: the passes of :mod:`strew.grow._flow_gaps` and
#: :mod:`strew.grow._flow_densify` triangulate positions that a band pass or another
#: measure had triangulated a few calls before: 7 of the 38 triangulations of the
#: hexflow growth were of positions triangulated already, all found with 16 kept, one
#: missed with 8. The same input, so the same triangulation: byte-identical output. A
#: triangulation of n points holds some 130 n bytes: 16 of 3,000 elements, 6 MB.)
TRI_KEEP = 16


def _delaunay_bonds(pts: np.ndarray, cut: float, g=None) -> np.ndarray:
    # (the triangulation's neighbour lists, each pair once and in order: the same
    # bonds as the simplices' edges made unique, with no sort of all three sides)
    ip, ix = triangulation(pts, g).vertex_neighbor_vertices
    n = len(pts)
    i = np.repeat(np.arange(n, dtype=np.int64), np.diff(ip))
    j = ix.astype(np.int64)
    up = i < j
    k = np.sort(i[up] * n + j[up])
    e = np.c_[k // n, k % n]
    ln = np.hypot(*(pts[e[:, 1]] - pts[e[:, 0]]).T)
    return e[ln < cut]


def placed(g) -> np.ndarray:
    """The placed elements in ``g.order``'s order, (n,) intp: ``[i for i in g.order if
    g.state[i] == ELEMENT]`` as an array, with one comparison over all of them (the
    passes ask it at every measure, and the list's loop over each element's state cost
    some 6 ms at 3,000 elements; issue 14 point 5)."""
    order = np.fromiter(g.order, dtype=np.intp, count=len(g.order))
    return order[g.state[order] == ELEMENT]


def relax_network(g, band: tuple[float, float] | None = None) -> int:
    """Relax the placed elements' bond network to one mean edge per bond (see the
    module), up to ``flow_net_passes`` times while each pass is kept; how many
    elements moved. With ``band`` (shortest, longest, in mean edges; :data:`NET_BAND`)
    the module's last pass instead: each bond pulled only into the band, near the
    sites without six neighbours, up to :data:`NET_BAND_PASSES` passes."""
    moved = 0
    # (the limit holds against the lattice as grown: a later call, after the
    # insertions of :mod:`strew.grow._flow_densify`, keeps the first call's)
    turn0 = getattr(g, "flow_net_turn0", None)
    if turn0 is None:
        turn0 = _misalignment(g)
        g.flow_net_turn0 = turn0
    if band is not None:
        return _band_passes(g, turn0, band)
    for _ in range(int(g.p.flow_net_passes)):
        m = _relax_once(g, turn0, band)
        if m == 0:
            break
        moved += m
    return moved


def _band_passes(g, turn0: float, band: tuple[float, float]) -> int:
    """The band's passes (see :func:`relax_network`) made three times from the same
    positions (:data:`BAND_RUNS`): with the outlines' contacts (bonds no shorter than
    their outlines' contact, :func:`_contact_lengths`, and overlapping pairs pushed
    apart by their depth, :func:`_push_apart`), the overlaps left cleared first as in
    every pass (both of a pair step back), then with only the one of each pair that
    moved farther stepping back (:func:`_resolve`'s ``one_side``), and last that one
    side without the contacts; the run that leaves the largest six share is kept (the
    first where they tie); how many elements its passes moved.

    (Issue 14 point 2, not in the paper; departs from §5.5 as the module does. The
    band's fitted positions would pass 0.90-0.94 of the interior sites where the
    moves made left 0.81-0.89: stepping back both of each overlapping pair undid the
    fit around every contact (the corner (2, 18): 0.899 fitted, 0.808 made). Stepping
    back one at a time raised the corner to 0.849 and the quarter circles from (2, 2)
    to 0.929, but alone lowered the 90 degree field from the centre 0.938 -> 0.925
    and the scales' quarter circles 0.931 -> 0.911 (``benchmarks/flow14n_probe.py
    --only all``). With the contacts, the corner 0.849 -> 0.916 and the scales along
    the 90 degree field 0.859 -> 0.903 (both of a pair stepping back; one side: 0.916
    and 0.884), but on the quarter circles 45 x 45 spacings from the centre the run
    without them keeps more (0.907 against 0.890 and 0.900), so it stays the third
    run. The band's passes only move elements, so a run's moves are put back exactly.)"""
    start = saved_moves(g, placed(g).tolist())
    best = None
    for k, (one_side, contact) in enumerate(BAND_RUNS):
        if k:
            undo_moves(g, start)
        g.flow_net_one_side = one_side
        g.flow_net_contact = contact
        moved = 0
        try:
            for _ in range(NET_BAND_PASSES):
                m = _relax_once(g, turn0, band)
                if m == 0:
                    break
                moved += m
        finally:
            g.flow_net_one_side = False
            g.flow_net_contact = False
        share = _six_share(g)
        if best is None or share > best[0]:
            best = (share, moved, saved_moves(g, start) if k < len(BAND_RUNS) - 1 else None)
    if best[2] is not None:
        undo_moves(g, best[2])
    return best[1]


#: the band's runs (:func:`_band_passes`): (one side of an overlapping pair steps
#: back, the outlines' contacts), in order
BAND_RUNS = ((False, True), (True, True), (True, False))


def _relax_once(g, turn0: float, band: tuple[float, float] | None = None) -> int:
    """One pass of :func:`relax_network`; how many elements moved (0 where the result
    was not kept: its six share not higher, a new gap, or the lattice's turn from the
    field, :func:`_misalignment`, over ``turn0`` by more than ``flow_net_turn``)."""
    import scipy.sparse as sps
    from scipy.sparse.linalg import factorized

    p = g.p
    rounds = int(p.flow_net_rounds or 0)
    L = g.l
    els = placed(g)
    n = len(els)
    if rounds <= 0 or n < 7:
        return 0
    pts0 = g.pos[els].copy()
    held = g.fixed[els].astype(bool)
    hold = float(p.flow_net_hold)
    rg = g.region
    pts = pts0.copy()
    big = 1e6
    if band is not None:
        # (the band's pass: only the elements within NET_WINDOW mean edges of a site
        # without six neighbours move; the rest of the lattice is held)
        from scipy.spatial import cKDTree

        ok = _six_sites(g, np.ones(n, dtype=bool), pts0)
        if ok.all():
            return 0
        held = held | (cKDTree(pts0[~ok]).query(pts0)[0] > NET_WINDOW * L)
    anchor = np.where(held, big, hold)
    solve = None
    e_was = None
    lo = None
    for _ in range(rounds):
        if band is None or solve is None:
            # (the band's pass keeps the bonds of its first round: an elastic network,
            # no bond flips to a new neighbour while it is fitted)
            e = memo(g, "bonds", (pts, 1.4 * L), lambda pts=pts: _delaunay_bonds(pts, 1.4 * L, g))  # (the same bonds: _flow_memo)
            m = len(e)
            if m == 0:
                return 0
        if e_was is None or not np.array_equal(e, e_was):
            # (the matrix depends on the bonds alone: factorized again only where they changed)
            e_was = e
            B = sps.csr_matrix((np.r_[-np.ones(m), np.ones(m)], (np.r_[np.arange(m), np.arange(m)], np.r_[e[:, 0], e[:, 1]])), shape=(m, n))
            A = (B.T @ B + sps.diags(anchor)).tocsc()
            solve = factorized(A)
        dv = pts[e[:, 1]] - pts[e[:, 0]]
        ln = np.maximum(np.hypot(dv[:, 0], dv[:, 1]), 1e-12 * L)
        if band is not None and lo is None and getattr(g, "flow_net_contact", False):
            # (the band's shortest bond: no shorter than its two outlines' contact
            # along it, see _contact_lengths)
            lo = _contact_lengths(g, els, e, pts0, held, band[0] * L / (1.0 + CONTACT_MARGIN)) * (1.0 + CONTACT_MARGIN)
        # (each bond one mean edge long; in the band's pass, its length clipped into the
        # band: a bond inside it pulls nothing, one outside is pulled to its edge)
        t = (L if band is None else np.clip(ln, band[0] * L if lo is None else lo, band[1] * L if lo is None else np.maximum(lo, band[1] * L))[:, None]) * dv / ln[:, None]
        rhs = B.T @ t + anchor[:, None] * pts
        new = np.c_[solve(np.ascontiguousarray(rhs[:, 0])), solve(np.ascontiguousarray(rhs[:, 1]))]
        new[held] = pts[held]
        if rg is not None:
            bad = ~rg.contains(new) | (boundary_distance(rg, new) < 0.5 * L)
            new[bad] = pts[bad]
        pts = new
    share0 = _six_share(g)
    grid = _grid(g)
    gaps0 = _far_points(g, grid)
    moves, old = fitted_moves(g, els, pts, range(n))
    if not moves:
        return 0
    limit = None if p.flow_net_turn is None else turn0 + float(p.flow_net_turn)
    best = None
    for first in range(int(p.flow_net_steps)):
        # the whole fit first, then (where it is not kept) each move shortened; a step
        # is not made where its fitted positions alone (before the outlines' checks,
        # which step some moves back and so turn the lattice less) leave no more six
        # sites or turn the lattice over _TURN_SLACK degrees past the limit (a
        # shortcut: the checks cost more than the fit)
        cand = pts0 + _STEPS[first] * (pts - pts0)
        if _six_share(g, cand) <= share0 or (limit is not None and _misalignment(g, cand) > limit + _TURN_SLACK):
            continue
        level = _settle_steps(g, moves, old, first)
        if band is None:
            _undo_gaps(g, moves, old, level, grid, gaps0, 1.5)
        else:
            # (the band's pass: where a site lost its six neighbours the elements around
            # it go back, so the gains elsewhere are kept; then where an empty circle
            # opened, found exactly rather than on the grid)
            _undo_worse(g, els, pts0, moves, old, level)
            if _undo_circles(g, els, pts0, moves, old, level):
                undo_moves(g, old)
                continue
            # (and the grid's new far points, as the one-edge pass: the acceptance
            # below counts them, and a circle already near 0.74 that grew is no new circle)
            _undo_gaps(g, moves, old, level, grid, gaps0, 1.5)
        turned = False
        if limit is not None and band is not None:
            # (the band's pass: where the lattice turned past the limit, the elements
            # around the sites it turned from the field go back, so the pass is not
            # refused whole for them: quarter circles 45 x 45 spacings from the centre
            # 0.887 -> 0.903, its last pass had turned the lattice 17.521 degrees
            # against a limit of 17.517; departs from §5.5 as the module does, and
            # keeps §5.3's frame as the whole-pass limit did)
            turned = _undo_turn(g, els, pts0, moves, old, level, limit)
        share1 = _six_share(g)
        gaps1 = _far_points(g, grid)
        turn1 = _misalignment(g)
        if share1 > share0 and len(gaps1) <= len(gaps0) and (limit is None or turn1 <= limit):
            if not turned and best is None:
                return sum(1 for o in moves if g.xy[o] != old[o][:2])
            # (a step kept only by sending elements back for the turn is weighed
            # against the shorter step, as the whole-pass limit would have tried it:
            # the better is kept)
            if best is None or share1 > best[0]:
                best = (share1, saved_moves(g, moves))
        undo_moves(g, old)
    if best is not None:
        undo_moves(g, best[1])
        return sum(1 for o in moves if g.xy[o] != old[o][:2])
    return 0


#: the last pass's band of bond lengths (mean edges): inside the six-neighbour test's
#: 0.85-1.15, with room on each side (0.88-1.12 and 0.87-1.13 raised the flow cases
#: less: see the module)
NET_BAND = (0.9, 1.12)

#: the band's pass runs up to this many times while each is kept (``flow_net_passes``,
#: 3, for the one-edge pass): each pass sends some moves back (overlaps, lost six sites,
#: new gaps), and the next fits the rest again; on the 19 flow cases of
#: ``benchmarks/flow14n_probe.py --only all`` 8 and 20 gave the same (every case stops
#: earlier), 3 left the 90 degree field from the centre at 0.921 against 0.938
NET_BAND_PASSES = 8

#: the last pass moves the elements within this many mean edges of a site without six
#: neighbours (4 kept a little more in two of four flow cases, at twice the time)
NET_WINDOW = 2.5

#: how far past ``flow_net_turn`` the fitted positions alone may turn the lattice
#: before a step is tried (see ``_relax_once``)
_TURN_SLACK = 1.0

#: the shares of a move tried in turn where the whole move makes an overlap or leaves
#: the region (the last: no move)
_STEPS = (1.0, 0.5, 0.25, 0.0)


def _touching(g, a: np.ndarray, b: np.ndarray, pa: np.ndarray, pb: np.ndarray, lo: np.ndarray, hi: np.ndarray, steps: int) -> np.ndarray:
    """For each pair of elements ``a``, ``b`` (their outlines as they are, centred at
    ``pa``, ``pb``, (m, 2)): the least distance of ``b``'s centre from ``a``'s along
    the line between them, within ``lo``-``hi`` (m,), at which the two outlines do not
    intersect, by bisection (``steps`` halvings of ``hi - lo``); ``lo`` where they do
    not at ``lo``, ``inf`` where they still do at ``hi``."""
    import shapely
    from shapely import get_coordinates, intersects, set_coordinates

    L = g.l
    d = pb - pa
    u = d / np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-12 * L)[:, None]
    A = np.array([g.geom[o] for o in a.tolist()], dtype=object)
    B = np.array([g.geom[o] for o in b.tolist()], dtype=object)
    cb, ib = get_coordinates(B, return_index=True)
    rel = cb - pb[ib]  # (each outline about its own centre)

    def shapely_hits(t: np.ndarray, k: np.ndarray) -> np.ndarray:
        # (the outlines of the pairs ``k``, ``b``'s centre ``t`` from ``a``'s along the line)
        at = np.full(len(a), -1, dtype=np.intp)
        at[k] = np.arange(len(k))
        sel = at[ib] >= 0
        moved = set_coordinates(B[k].copy(), rel[sel] + (pa[k] + t[:, None] * u[k])[at[ib[sel]]])
        return intersects(A[k], moved)

    hits = shapely_hits
    if len(a) and _simple_polygons(A) and _simple_polygons(B):
        # (the pairs decided in one compiled call, intersect_certain, with room far
        # above the coordinates' rounding: shapely's answers; the few it cannot decide,
        # a vertex within 1e-9 mean edges of the other's boundary, go to shapely as
        # before. Issue 14 point 5: the bisection's shapely calls were 4 % of the
        # hexflow growth, benchmarks/results/g70v_profile_main_spy.txt)
        from ._overlap_kernels import intersect_certain

        ca = get_coordinates(A)
        oa = np.zeros(len(a) + 1, dtype=np.int64)
        np.cumsum(shapely.get_num_coordinates(A), out=oa[1:])
        ob = np.zeros(len(b) + 1, dtype=np.int64)
        np.cumsum(shapely.get_num_coordinates(B), out=ob[1:])
        rel_c = np.ascontiguousarray(rel)
        tol = 1e-9 * L

        def hits(t: np.ndarray, k: np.ndarray) -> np.ndarray:
            k = np.ascontiguousarray(k, dtype=np.int64)
            got = np.empty(len(k), dtype=np.int8)
            intersect_certain(ca, oa, rel_c, ob, k, np.ascontiguousarray(pa[k] + t[:, None] * u[k]), tol, got)
            out = got > 0
            unsure = np.flatnonzero(got < 0)
            if len(unsure):
                out[unsure] = shapely_hits(t[unsure], k[unsure])
            return out

    lo = np.asarray(lo, dtype=float).copy()
    hi = np.asarray(hi, dtype=float).copy()
    out = lo.copy()
    k = np.flatnonzero(hits(lo, np.arange(len(a))))  # (the pairs that touch at lo)
    if not len(k):
        return out
    far = hits(hi[k], k)
    out[k[far]] = np.inf
    k = k[~far]
    for _ in range(steps):
        if not len(k):
            break
        t = 0.5 * (lo[k] + hi[k])
        h = hits(t, k)
        lo[k] = np.where(h, t, lo[k])
        hi[k] = np.where(h, hi[k], t)
    out[k] = hi[k]
    return out


def _simple_polygons(gs: np.ndarray) -> bool:
    """Are all of ``gs`` polygons without holes (each one closed ring of coordinates)?"""
    import shapely

    return bool(((shapely.get_type_id(gs) == 3) & (shapely.get_num_interior_rings(gs) == 0)).all())


def _contact_lengths(g, els: np.ndarray, e: np.ndarray, pts: np.ndarray, held: np.ndarray, shortest: float) -> np.ndarray:
    """For each bond ``e`` (pairs of indices into ``els``, at ``pts``) the larger of
    ``shortest`` and the distance between the two centres, along the bond's direction,
    at which their outlines (as they are turned now) touch (to 1/512 of a mean edge),
    (m,); ``shortest`` where both ends are held (no fit moves them).

    (Issue 14 point 2, not in the paper; departs from §5.5 as the module does, which
    wants the exemplar's ring offsets, and those never overlap. The outlines are not
    discs: a hexagon of the suite's lattice, 0.86 spacings across its flats, touches
    its neighbour at 0.86 spacings flat to flat but at 0.99 corner to corner, so where
    the lattice's bonds turned from the elements' frame the band's 0.9 mean edges
    pressed pairs into each other: over the band's passes of the 90 degree field from
    the corner (2, 18), 45-63 pairs overlapped, by a median of 0.021-0.028 mean edges,
    and stepping them back sent back 108-136 elements.)"""
    L = g.l
    out = np.full(len(e), shortest)
    live = np.flatnonzero(~(held[e[:, 0]] & held[e[:, 1]]))
    if not len(live):
        return out
    ee = e[live]
    m = len(ee)
    got = _touching(g, els[ee[:, 0]], els[ee[:, 1]], pts[ee[:, 0]], pts[ee[:, 1]], np.full(m, shortest), np.full(m, 1.5 * L), 10)
    out[live] = np.where(np.isfinite(got), got, 1.5 * L)
    return out


#: how much longer than the outlines' contact (a share of it) the band wants a bond
CONTACT_MARGIN = 0.005


def _settle_steps(g, moves: dict, old: dict, first: int = 0) -> dict:
    """Make the fitted ``moves`` (element -> position), each shortened along its way
    (:data:`_STEPS`) where its outline would leave the region or cross a boundary
    stroke, or overlap another; elements in an overlap both step back, until none is
    left (the positions before had none, so this ends). Nothing turns (§5.3). Returns
    each element's step (an index into :data:`_STEPS`; all from ``first``)."""
    level = {o: first for o in moves}
    check = _place_all(g, moves, old, level)
    if getattr(g, "flow_net_contact", False):
        check = _push_apart(g, moves, old, level, check)
    _resolve(g, moves, old, level, check)
    return level


def _push_apart(g, moves: dict, old: dict, level: dict, check: list) -> list:
    """Before :func:`_resolve` steps elements back: each pair that the moves left
    overlapping by at most :data:`PUSH_MOST` mean edges is moved apart along the line
    between their centres by the overlap's depth (:func:`_touching`, and
    :data:`PUSH_MARGIN` more), each by half where both moved, the whole by the one
    that moved where one did (its target shifted so that at its step it lands there),
    up to :data:`PUSH_ROUNDS` times; what :func:`_resolve` then checks (those pushed,
    those near them, and ``check``).

    (Issue 14 point 2, not in the paper; departs from §5.5 as the module does. The
    band's fitted positions overlap only slightly: over the band's passes of the 90
    degree field from the corner (2, 18), 45-63 pairs overlap by a median of
    0.021-0.028 and at most 0.096-0.115 mean edges, and stepping both of each back
    sent back 108-136 elements (as many again as the pairs' members: each step back
    makes new contacts), so the pass made 0.786-0.819 of the 0.862-0.899 six share
    it had fitted. A pair moved apart by its depth keeps its bond inside the
    six-neighbour test's 0.85-1.15 spacings. The overlaps a push makes with others, or
    leaves, are stepped back as before.)"""
    L = g.l
    if len(g.pair_gap_max) and float(g.pair_gap_max.max()) > 0:
        return check  # (a kept gap is no overlap's depth: stepped back as before)
    pushed: set[int] = set()
    for _ in range(PUSH_ROUNDS):
        hits = g.overlapping_many(check)
        pairs = sorted({(min(o, h), max(o, h)) for o, hs in hits.items() for h in hs if g.state[h] == ELEMENT and g.orig_of[h] == h})
        pairs = [(a, b) for a, b in pairs if (a in level and _STEPS[level[a]] > 0.0) or (b in level and _STEPS[level[b]] > 0.0)]
        if not pairs:
            break
        pa_ = np.asarray([a for a, _ in pairs], dtype=np.intp)
        pb_ = np.asarray([b for _, b in pairs], dtype=np.intp)
        xa, xb = g.pos[pa_], g.pos[pb_]
        dist = np.hypot(*(xb - xa).T)
        far = _touching(g, pa_, pb_, xa, xb, dist, dist + PUSH_MOST * L, 12)
        shift: dict[int, list] = {}
        for q, (a, b) in enumerate(pairs):
            if not math.isfinite(far[q]) or dist[q] <= 1e-12 * L:
                continue
            depth = far[q] - dist[q] + PUSH_MARGIN * L
            ux, uy = (xb[q] - xa[q]) / dist[q]
            ma = a in level and _STEPS[level[a]] > 0.0
            mb = b in level and _STEPS[level[b]] > 0.0
            wa = 0.5 if ma and mb else float(ma)
            for o, w, sgn in ((a, wa, -1.0), (b, 1.0 - wa, 1.0)):
                if w > 0.0:
                    s = shift.setdefault(o, [0.0, 0.0])
                    s[0] += sgn * w * depth * ux
                    s[1] += sgn * w * depth * uy
        if not shift:
            break
        for o in sorted(shift):
            f = _STEPS[level[o]]
            tx, ty = moves[o]
            moves[o] = (tx + shift[o][0] / f, ty + shift[o][1] / f)
            _place(g, o, moves, old, level)
        pushed.update(shift)
        check = sorted({j for o in shift for j in g.near(*g.xy[o], 2.0 * L, (ELEMENT,)) if j in level} | set(shift))
    return sorted(set(check) | pushed | {j for o in pushed for j in g.near(*g.xy[o], 2.0 * L, (ELEMENT,)) if j in level})


#: the deepest overlap (mean edges) :func:`_push_apart` moves a pair apart by (the
#: band's passes on the corner (2, 18): at most 0.115)
PUSH_MOST = 0.25

#: how much farther (mean edges) than the overlap's depth a pushed pair moves apart
PUSH_MARGIN = 0.002

#: how many times :func:`_push_apart` pushes the pairs still overlapping
PUSH_ROUNDS = 8


def _place_all(g, moves: dict, old: dict, level: dict, turns: dict | None = None) -> list:
    """:func:`_place` of every element of ``moves`` in turn; the elements (all placed).

    The same placements, with the outlines at each element's first step made in one
    shapely call per kind and tested against the domain in one more (issue 14 point 5):
    an outline, the region and the boundary strokes do not depend on the other
    elements, so only the moves are made one by one (an element whose outline at that
    step does not fit, or that has no simple outline, is placed by :func:`_place`;
    g60v's batching of stop 60, its patch not landed then: the share of these outlines
    grows with the count, benchmarks/g63v_flow_scaling.py)."""
    import shapely

    pre: dict = {}
    if g.boundary is None:  # (crosses_boundary is then False)
        groups: dict = {}
        scl, kinds, local_ring = g.scl, g.kind, g.local_ring
        for o, (tx, ty) in moves.items():
            f = _STEPS[level[o]]
            if f == 0.0:
                continue
            ox, oy, _, rot0 = old[o]
            turn = turns.get(o) if turns else None
            x, y = ox + f * (tx - ox), oy + f * (ty - oy)
            rot = rot0 + f * (turn - rot0) if turn is not None else rot0
            kind = int(kinds[o])
            if local_ring[kind] is None or not g.in_domain(x, y):
                continue
            base = g.turned_ring(kind, rot, float(scl[o]))
            groups.setdefault((kind, base.shape[0]), []).append((o, x, y, rot, base))
        for items in groups.values():
            # (the same sums as element_geometry's ``turned_ring + np.array([x, y])``)
            coords = np.stack([it[4] for it in items]) + np.array([(it[1], it[2]) for it in items])[:, None, :]
            gs = shapely.polygons(coords)
            for it, gg, ok in zip(items, gs, g.fits_domain_many(gs).tolist()):
                if ok:
                    pre[it[0]] = (it[1], it[2], it[3], gg)
    for o in moves:
        got = pre.get(o)
        if got is None:
            _place(g, o, moves, old, level, turns)
            continue
        x, y, rot, gg = got
        g._move(o, x, y)
        g.geom[o] = gg
        if turns is not None:
            g.rot[o] = rot
    return list(moves)


def _place(g, o: int, moves: dict, old: dict, level: dict, turns: dict | None = None) -> bool:
    """Put ``o`` at its current step, stepping back while it leaves the domain; True
    (it is placed). With ``turns``, an element in it also turns to that rotation by the
    same step (:mod:`strew.grow._flow_densify`)."""
    ox, oy, geom0, rot0 = old[o]
    tx, ty = moves[o]
    turn = turns.get(o) if turns else None
    while True:
        f = _STEPS[level[o]]
        if f == 0.0:
            if g.xy[o] != (ox, oy):
                g._move(o, ox, oy)
            g.geom[o] = geom0
            if turns is not None:
                g.rot[o] = rot0
            return True
        x, y = ox + f * (tx - ox), oy + f * (ty - oy)
        rot = rot0 + f * (turn - rot0) if turn is not None else rot0
        if g.in_domain(x, y) and not (g.boundary is not None and g.crosses_boundary((ox, oy), (x, y))):
            geom = g.element_geometry(int(g.kind[o]), x, y, rot, float(g.scl[o]))
            if g.fits_domain(geom):
                g._move(o, x, y)
                g.geom[o] = geom
                if turns is not None:
                    g.rot[o] = rot
                return True
        level[o] += 1


def _resolve(g, moves: dict, old: dict, level: dict, check: list, turns: dict | None = None) -> None:
    """Step back the elements of ``check`` (and those near) in an overlap, both of
    each pair, until none is left (each put at its step by :func:`_place`, ``turns``
    as there). Where ``g.flow_net_one_side`` (the band's second run, see
    :func:`_band_passes`) only the one of each pair whose move at its step is longer
    (the lower index where they tie) steps back; the other, if still in an overlap,
    at the next round (at the last step every element is where it was, with no
    overlap, so this ends too)."""
    one_side = bool(getattr(g, "flow_net_one_side", False))
    while check:
        hits = g.overlapping_many(check)
        back: set[int] = set()
        for o, hs in hits.items():
            if one_side:
                for h in hs:
                    pair = [j for j in (o, g.orig_of[h]) if j in level and _STEPS[level[j]] > 0.0]
                    if pair:
                        back.add(max(pair, key=lambda j: (_STEPS[level[j]] * math.hypot(moves[j][0] - old[j][0], moves[j][1] - old[j][1]), -j)))
                continue
            for j in [o, *(g.orig_of[h] for h in hs)]:
                if j in level and _STEPS[level[j]] > 0.0:
                    back.add(j)
        if not back:
            break
        for o in sorted(back):
            level[o] += 1
            _place(g, o, moves, old, level, turns)
        check = sorted({j for o in back for j in g.near(*g.xy[o], 2.0 * g.l, (ELEMENT,)) if j in level} | back)


def six_spacing(g) -> float:
    """The spacing of the six-neighbour test (0.85-1.15 of it): the exemplar's median
    distance from an element to its six nearest (``benchmarks/grow.py``'s spacing),
    made once per growth; the mean edge where the exemplar has under seven elements.

    (Issue 14 point 2, not in the paper. The mean Delaunay edge, ``g.l``, counts an
    irregular exemplar's longer bonds too: the scales' is 13.254 against a median
    six-nearest distance of 13.172, 0.6% over, so the passes kept sites whose sixth
    neighbour lay at 1.15 mean edges but past 1.15 spacings: scales along the 90
    degree field 0.856 by the mean edge, 0.829 by the spacing. Measured at the spacing,
    0.845; on the quarter circles 0.926 -> 0.931. A regular lattice's two are the
    same, 12.0 for the suite's hexagons, and its growth does not change. The band's
    bond targets stay in mean edges: in spacings they lowered both, 0.839 and 0.913.)"""
    got = getattr(g, "flow_six_spacing", None)
    if got is None:
        from scipy.spatial import cKDTree

        ex = np.asarray(g.ref.xy, dtype=float)
        got = float(np.median(cKDTree(ex).query(ex, 7)[0][:, 1:])) if len(ex) >= 7 else float(g.l)
        g.flow_six_spacing = got
    return got


def _six_share(g, xy: np.ndarray | None = None) -> float:
    """The share of the placed elements (at ``xy``, None: where they are) over two
    mean edges inside the region with six elements at 0.85-1.15 spacings
    (:func:`six_spacing`) and none nearer (``six_nbr_share`` of ``benchmarks/grow.py``)."""
    if xy is None:
        xy = g.pos[placed(g)]
    return memo(g, "six_share", (xy,), lambda: _six_share_at(g, xy))  # (measured once: _flow_memo)


def _six_share_at(g, xy: np.ndarray) -> float:
    """:func:`_six_share` of the elements at ``xy``, measured."""
    L = g.l
    q = xy[boundary_distance(g.region, xy) > 2.0 * L] if g.region is not None else xy
    if not len(q):
        return 0.0
    S = six_spacing(g)
    hi, lo = ball_counts(xy, q, 1.15 * S, 0.85 * S)  # (cKDTree's counts, compiled: _near_kernels)
    hi, lo = hi - 1, lo - 1
    return float(((hi == 6) & (lo == 0)).mean())


def _phases(pts: np.ndarray, q: np.ndarray, r: float) -> np.ndarray:
    """The six-fold bond direction of each point ``q`` of ``pts``: the angle of the sum
    of ``exp(6 i theta)`` over its neighbours within ``r``, divided by 6."""
    from scipy.spatial import cKDTree

    t = cKDTree(pts)
    pairs = t.query_pairs(r, output_type="ndarray")
    where = np.full(len(pts), -1, dtype=np.intp)
    where[q] = np.arange(len(q))
    out = np.zeros(len(q), dtype=complex)
    d = pts[pairs[:, 1]] - pts[pairs[:, 0]]
    z = np.exp(6j * np.arctan2(d[:, 1], d[:, 0]))  # (the same both ways: 6 (theta + pi))
    for a in (pairs[:, 0], pairs[:, 1]):
        k = where[a]
        np.add.at(out, k[k >= 0], z[k >= 0])
    return np.angle(out) / 6


def _misalignment(g, xy: np.ndarray | None = None) -> float:
    """The 90th percentile over the placed elements (at ``xy``, None: where they are)
    over two mean edges inside the region of the turn (degrees, wrapped to +-30) of
    the lattice's six-fold bond direction from the exemplar's, less the field's angle
    there (``misalign_deg_p90`` of ``benchmarks/grow.py``)."""
    a = _turns(g, xy)
    a = a[np.isfinite(a)]
    return float(np.quantile(a, 0.9)) if len(a) else 0.0


def _turns(g, xy: np.ndarray | None = None) -> np.ndarray:
    """Each placed element's (at ``xy``, None: where they are, in ``g.order``) turn of
    :func:`_misalignment` (degrees, absolute), NaN for those within two mean edges of
    the region's edge, (n,); empty where no element or no exemplar site is inside."""
    if xy is None:
        xy = g.pos[placed(g)]
    return memo(g, "turns", (xy,), lambda: _turns_at(g, xy))  # (measured once: _flow_memo)


def _turns_at(g, xy: np.ndarray) -> np.ndarray:
    """:func:`_turns` of the elements at ``xy``, measured."""
    L = g.l
    q = np.flatnonzero(boundary_distance(g.region, xy) > 2.0 * L) if g.region is not None else np.arange(len(xy))
    ex = np.asarray(g.ref.xy, dtype=float)
    er = getattr(g.ref.exemplar, "region", None)
    eq = np.flatnonzero(boundary_distance(er, ex) > 1.5 * L) if er is not None else np.arange(len(ex))
    if not len(q) or not len(eq):
        return np.zeros(0)
    phi0 = float(np.angle(np.exp(6j * _phases(ex, eq, 1.15 * L)).sum()) / 6)
    v = np.asarray(g.p.flow(xy[q]), dtype=float)
    d = _phases(xy, q, 1.15 * L) - phi0 - np.arctan2(v[:, 1], v[:, 0])
    out = np.full(len(xy), np.nan)
    out[q] = np.abs(np.degrees((d + np.pi / 6) % (np.pi / 3) - np.pi / 6))
    return out


def _grid(g) -> np.ndarray:
    """The points of a quarter-edge grid over two mean edges inside the region (as
    :func:`strew.grow._flow_retry.interior_score`'s, and on the band's inner edge too:
    ``benchmarks/grow.py``'s grid starts there), (k, 2)."""
    L = g.l
    rg = g.region
    if rg is not None:
        # (a region's grid is the same at every call: made once per growth)
        got = getattr(g, "flow_net_grid", None)
        if got is not None:
            return got
        x0, y0, x1, y1 = (float(v) for v in rg.bounds)
    else:
        xy = g.pos[placed(g)]
        (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
    grid = np.mgrid[x0 + 2 * L : x1 - 2 * L : 0.25 * L, y0 + 2 * L : y1 - 2 * L : 0.25 * L].reshape(2, -1).T
    if rg is not None and len(grid):
        # (the distance only for the points inside: the same points as both tests on all)
        grid = grid[rg.contains(grid)]
        grid = grid[boundary_distance(rg, grid) > 2.0 * L - 1e-9 * L]
    if rg is not None:
        g.flow_net_grid = grid
    return grid


def _far_points(g, grid: np.ndarray) -> np.ndarray:
    """The points of ``grid`` farther than 0.75 mean edges from every placed element."""
    if not len(grid):
        return grid
    xy = g.pos[placed(g)]
    return memo(g, "far_points", (xy, grid), lambda: _far_points_at(g, xy, grid))  # (measured once: _flow_memo)


def _far_points_at(g, xy: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """:func:`_far_points` of the elements at ``xy``, measured."""
    L = g.l
    return grid[far_from(xy, grid, 0.75 * L)]  # (cKDTree's query, compiled: _near_kernels)


def _undo_gaps(g, moves: dict, old: dict, level: dict, grid: np.ndarray, far0: np.ndarray, reach: float) -> None:
    """Where the moves opened gaps (far points that were not far before), the elements
    within ``reach`` mean edges of them go back (and those then overlapping them step
    back), up to three times."""
    from scipy.spatial import cKDTree

    L = g.l
    last = len(_STEPS) - 1
    was = cKDTree(far0) if len(far0) else None
    for _ in range(3):
        far = _far_points(g, grid)
        if was is not None and len(far):
            far = far[was.query(far)[0] > 1e-9 * L]
        if not len(far):
            return
        back = sorted({j for q in far.tolist() for j in g.near(q[0], q[1], reach * L, (ELEMENT,)) if j in level and level[j] != last})
        if not _send_back(g, back, moves, old, level):
            return


def _send_back(g, back: list, moves: dict, old: dict, level: dict) -> bool:
    """Put the elements ``back`` at their last step's place (level ``len(_STEPS) - 1``)
    and resolve the overlaps that makes; False where ``back`` is empty."""
    if not back:
        return False
    last = len(_STEPS) - 1
    for o in back:
        level[o] = last
        _place(g, o, moves, old, level)
    _resolve(g, moves, old, level, back)
    return True


def _six_sites(g, q: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """Which of the elements at ``xy`` lie in ``q`` (the interior) with six elements
    at 0.85-1.15 spacings (:func:`six_spacing`) and none nearer, (n,) bool."""
    return memo(g, "six_sites", (q, xy), lambda: _six_sites_at(g, q, xy))  # (measured once: _flow_memo)


def _six_sites_at(g, q: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """:func:`_six_sites`, measured."""
    S = six_spacing(g)
    hi, lo = ball_counts(xy, xy, 1.15 * S, 0.85 * S)  # (cKDTree's counts, compiled: _near_kernels)
    return q & (hi - 1 == 6) & (lo - 1 == 0)


def _undo_worse(g, els: np.ndarray, pts0: np.ndarray, moves: dict, old: dict, level: dict) -> None:
    """Where the moves turned an interior six site into one without, the elements
    within 1.2 mean edges of it go back (and those then overlapping them step back),
    up to three times."""
    L = g.l
    last = len(_STEPS) - 1
    inner = boundary_distance(g.region, pts0) > 2.0 * L if g.region is not None else np.ones(len(pts0), dtype=bool)
    ok0 = _six_sites(g, inner, pts0)
    for _ in range(3):
        now = g.pos[els]
        worse = np.flatnonzero(ok0 & ~_six_sites(g, inner, now))
        if not len(worse):
            return
        back = sorted({j for w in worse.tolist() for j in g.near(now[w, 0], now[w, 1], 1.2 * L, (ELEMENT,)) if j in level and level[j] != last})
        if not _send_back(g, back, moves, old, level):
            return


def _undo_turn(g, els: np.ndarray, pts0: np.ndarray, moves: dict, old: dict, level: dict, limit: float) -> bool:
    """While the lattice's turn from the field (:func:`_misalignment`) is over ``limit``,
    the elements within 1.2 mean edges of each interior site whose turn the moves
    raised and left over ``limit`` go back (and those then overlapping them step
    back), up to four times: the pass is then refused for its turn only where sending
    these back is not enough (see :func:`_relax_once`); True where any went back."""
    L = g.l
    last = len(_STEPS) - 1
    a0 = _turns(g, pts0)
    sent = False
    for _ in range(4):
        now = g.pos[els]
        a1 = _turns(g, now)
        ok = np.isfinite(a1)
        if not ok.any() or float(np.quantile(a1[ok], 0.9)) <= limit:
            return sent
        worse = np.flatnonzero(ok & (a1 > limit) & (a1 > a0))
        back = sorted({j for w in worse.tolist() for j in g.near(now[w, 0], now[w, 1], 1.2 * L, (ELEMENT,)) if j in level and level[j] != last})
        if not _send_back(g, back, moves, old, level):
            return sent
        sent = True
    return sent


def _circumcentres(a: np.ndarray, b: np.ndarray, c: np.ndarray, L: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The circumcircles of the triangles with corners ``a``, ``b``, ``c`` (each (m, 2)):
    centres (m, 2), radii (m,) and (m,) bool, False where a triangle is degenerate (its
    centre and radius then meaningless); ``L`` the mean edge."""
    d = 2.0 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    ok = np.abs(d) > 1e-12 * L * L
    d = np.where(ok, d, 1.0)
    sa, sb, sc = (a**2).sum(1), (b**2).sum(1), (c**2).sum(1)
    ux = (sa * (b[:, 1] - c[:, 1]) + sb * (c[:, 1] - a[:, 1]) + sc * (a[:, 1] - b[:, 1])) / d
    uy = (sa * (c[:, 0] - b[:, 0]) + sb * (a[:, 0] - c[:, 0]) + sc * (b[:, 0] - a[:, 0])) / d
    cc = np.c_[ux, uy]
    return cc, np.hypot(*(cc - a).T), ok


def _far_circles(g, xy: np.ndarray) -> np.ndarray:
    """The centres of the empty circles (Delaunay circumcircles of the elements at
    ``xy``) wider than 0.74 mean edges in radius, over 1.5 mean edges inside the
    region, (k, 2): exact where a grid samples."""
    return memo(g, "far_circles", (xy,), lambda: _far_circles_at(g, xy))  # (measured once: _flow_memo)


def _far_circles_at(g, xy: np.ndarray) -> np.ndarray:
    """:func:`_far_circles`, measured."""
    L = g.l
    s = triangulation(xy, g).simplices
    a, b, c = xy[s[:, 0]], xy[s[:, 1]], xy[s[:, 2]]
    cc, r, ok = _circumcentres(a, b, c, L)
    cc = cc[ok & (r > 0.74 * L)]
    if g.region is not None and len(cc):
        cc = cc[g.region.contains(cc)]
        cc = cc[boundary_distance(g.region, cc) > 1.5 * L]
    return cc


def _undo_circles(g, els: np.ndarray, pts0: np.ndarray, moves: dict, old: dict, level: dict) -> bool:
    """Where the moves opened an empty circle (:func:`_far_circles`) none was within a
    quarter edge of before, the elements within 1.5 mean edges of it go back, up to
    three times; True where one is left."""
    from scipy.spatial import cKDTree

    L = g.l
    last = len(_STEPS) - 1
    c0 = _far_circles(g, pts0)
    was = cKDTree(c0) if len(c0) else None
    for k in range(4):
        now = _far_circles(g, g.pos[els])
        if was is not None and len(now):
            now = now[was.query(now)[0] > 0.25 * L]
        if not len(now):
            return False
        if k == 3:
            return True
        back = sorted({j for q in now.tolist() for j in g.near(q[0], q[1], 1.5 * L, (ELEMENT,)) if j in level and level[j] != last})
        if not _send_back(g, back, moves, old, level):
            return True
    return True

"""Flow mode: the missing elements of the stretched band put in one at a time, the
network fitted around each (issue 14 point 2).

Not in the paper. After :func:`strew.grow._flow_net.relax_network` a hexagonal lattice
grown along a bending field keeps a band of stretched bonds (1.15-1.3 mean edges)
where its growth fronts met, with the 5s and 7s of the geometrically necessary
dislocations strung along it: the dislocations' extra half-rows are missing there (the
corner (2, 18) case of ``benchmarks/grow.py --structure --flow-only``: its interior
Delaunay triangles hold about 17 elements' area more than a perfect lattice's, 28
before the network's relaxation; ``benchmarks/flow14k_render.py`` draws it). The
local insertions of :mod:`strew.grow._flow_stretch` cannot make the room there (18
of 20 tries fail in that case: their window is relaxed to the present offsets),
and the hexagons touch at 0.86 mean edges across their flat sides, so a bond pressed
or turned against its elements ends in an overlap.

Each round takes the widest interior Delaunay triangle (under 1.4 mean edges a
side, its circumcentre inside it, over ``flow_stretch_edge`` edges inside the region,
not one tried before) whose circumradius is over ``flow_densify_min`` mean edges (a
perfect lattice's: 0.577). A free point is put at its circumcentre, and the elements
within ``flow_densify_window`` mean edges of it with the point are fitted as
:mod:`strew.grow._flow_net` fits the network (each Delaunay bond under 1.4 mean edges
one mean edge long in its own direction, ``flow_densify_fit_rounds`` rounds, held to
the round before with ``flow_densify_hold``; those up to two edges farther held), the
point's bonds pulled ``flow_densify_weight`` times as hard and bonds under
``flow_densify_stiff`` mean edges four times: the stretch around gives the new
element its room without pressing the hexagons together. A fit that leaves two
elements nearer than ``flow_densify_close`` mean edges is not tried. Else the
elements are moved, each turned towards the six-fold bond direction of the fitted
lattice around it but held within ``flow_max_turn`` of the field (§5.3's frame), each
step shortened where it would overlap or leave the region (as ``_flow_net``); then an
element is matched (§5.2) and placed (§5.4) at the point if no element is within
``flow_stretch_room`` mean edges, else the moves are undone. After a placement the
network is relaxed again (one pass of :func:`~strew.grow._flow_net.relax_network`,
its turn limit held against the lattice as grown), and the round is kept only where
it leaves more interior sites with six neighbours at 0.85-1.15 mean edges (none
nearer) and no more gap points (:func:`strew.grow._flow_retry.interior_score`); else
the state before it is put back exactly. Up to ``flow_densify_rounds`` rounds; after
``flow_densify_fails`` refused rounds in a row the pass stops.

Departs from §5.5 as ``_flow_net`` does (the network relaxed after the growth, here
with a free point for an element to come) and from §5.2-5.4 as ``_flow_holes`` does
(elements put after the growth; moved elements turn, within the flow's limit).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ._flow_holes import close_ring, open_ring
from ._flow_kernels import boundary_distance
from ._flow_net import (
    _circumcentres,
    _delaunay_bonds,
    _phases,
    _place,
    _resolve,
    placed,
    relax_network,
    six_spacing,
    triangulation,
)
from ._flow_retry import _region_grid, interior_score, restore, snapshot
from ._flow_shear import fitted_moves, undo_moves
from ._near_kernels import ball_counts
from ._objects import ELEMENT

__all__ = ["densify"]


def densify(g, target: int) -> int:
    """Put elements into the widest gaps of the stretched band one at a time, the
    network fitted around each (see the module); how many were put."""
    p = g.p
    grid = _region_grid(g)
    best = _score(g, grid)
    made = 0
    skip: list[np.ndarray] = []
    fails = 0
    before = None
    for _ in range(int(p.flow_densify_rounds or 0)):
        if len(g.order) >= target:
            break
        # (a round that puts nothing undoes its own moves: the state kept before it
        # serves the next round too; it is taken only when a round moves anything)
        box = [] if before is None else [before]
        k, tried = _round(g, target, skip, box)
        before = box[0] if box else None
        if k:
            # (one pass of the network's relaxation, not ``flow_net_passes``: the time)
            g.p = replace(p, flow_net_passes=1)
            try:
                relax_network(g)
            finally:
                g.p = p
            now = _score(g, grid)
            if now[0] > best[0] and now[1] >= best[1] and now[2] <= best[2]:
                best = now
                made += k
                fails = 0
                before = None
                continue
            restore(g, before)
            before = None
        if not len(tried):
            break
        skip.extend(tried)
        fails += 1
        if fails >= int(p.flow_densify_fails):
            break
    return made


def _score(g, grid: np.ndarray | None) -> tuple[float, float, int]:
    """(the share of the interior sites, over two mean edges inside the region, with six
    elements at 0.85-1.15 spacings (``_flow_net.six_spacing``) and none nearer; the share of the interior sites
    failing it that lie in groups, linked within 1.15 mean edges, of at most two: the
    isolated dislocations, 1 where none fails; the gap points of
    :func:`strew.grow._flow_retry.interior_score`), as ``benchmarks/grow.py`` measures
    ``six_nbr_share`` and ``isolated_defect_share``."""
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    L = g.l
    xy = g.pos[placed(g)]
    q = xy[boundary_distance(g.region, xy) > 2.0 * L] if g.region is not None else xy
    if not len(q):
        return 0.0, 1.0, 0
    S = six_spacing(g)
    hi, lo = ball_counts(xy, q, 1.15 * S, 0.85 * S)  # (cKDTree's counts, compiled: _near_kernels)
    hi, lo = hi - 1, lo - 1
    ok = (hi == 6) & (lo == 0)
    bad = q[~ok]
    iso = 1.0
    if len(bad):
        t = cKDTree(bad)
        lab = connected_components(t.sparse_distance_matrix(t, 1.15 * L), directed=False)[1]
        iso = float((np.bincount(lab)[lab] <= 2).mean())
    return float(ok.mean()), iso, interior_score(g, grid)[1]


def _centre(g, pts: np.ndarray, skip) -> np.ndarray:
    """The circumcentre of the widest interior Delaunay triangle not tried before (see
    the module), (1, 2), or (0, 2) where none is left."""
    from scipy.spatial import cKDTree

    p = g.p
    L = g.l
    s = triangulation(pts, g).simplices  # (the one kept where these positions were triangulated: the same)
    a, b, c = pts[s[:, 0]], pts[s[:, 1]], pts[s[:, 2]]
    la, lb, lc = (np.hypot(*(u - v).T) for u, v in ((b, c), (c, a), (a, b)))
    ok = np.maximum(np.maximum(la, lb), lc) < 1.4 * L
    cc, r, ok_d = _circumcentres(a, b, c, L)
    ok &= ok_d
    ok &= r > float(p.flow_densify_min) * L
    # (the centre inside its triangle: an obtuse one's lies beyond a bond)
    ok &= np.hypot(*(cc - (a + b + c) / 3.0).T) < 0.25 * L
    w = np.flatnonzero(ok)
    if g.region is not None and len(w):
        w = w[g.region.contains(cc[w])]
        w = w[boundary_distance(g.region, cc[w]) > float(p.flow_stretch_edge) * L]
    if len(skip) and len(w):
        w = w[cKDTree(np.asarray(skip)).query(cc[w])[0] > 0.5 * L]
    if not len(w):
        return np.zeros((0, 2))
    return cc[w[np.argsort(-r[w], kind="stable")[:1]]]


def _round(g, target: int, skip, box: list) -> tuple[int, np.ndarray]:
    """One round: the network around the widest gap fitted with a free point there,
    the moves made and an element put at the point where it has room; how many were
    put (0 or 1) and the gap tried. ``box``: the state before, taken (appended) when
    anything moves."""
    from scipy.spatial import cKDTree

    p = g.p
    L = g.l
    els = placed(g)
    if len(els) < 7 or len(g.order) >= target:
        return 0, np.zeros((0, 2))
    pts0 = g.pos[els].copy()
    cs = _centre(g, pts0, skip)
    if len(cs) == 0:
        return 0, cs
    # (only the elements within ``flow_densify_window`` mean edges of the new point
    # move, those up to two edges beyond held: held loosely, the whole lattice would
    # drift; the fit is made over these alone)
    dist = cKDTree(cs).query(pts0)[0]
    win = float(p.flow_densify_window) * L
    near = dist <= win + 2.0 * L
    els, pts0, dist = els[near], pts0[near], dist[near]
    n = len(els)
    held = np.asarray([bool(g.fixed[o]) for o in els.tolist()], dtype=bool) | (dist > win)
    pts = _fit(g, pts0, cs, held)
    free = ~held
    if free.sum() >= 2 and float(cKDTree(pts[:n]).query(pts[:n][free], 2)[0][:, 1].min()) < float(p.flow_densify_close) * L:
        # (a fit that brings two elements nearer than ``flow_densify_close`` mean edges,
        # where the suite's hexagons touch, steps back there: not tried)
        return 0, cs
    if not box:
        box.append(snapshot(g))
    moves, old = fitted_moves(g, els, pts[:n], range(n))
    if moves:
        _settle(g, moves, old, _frame_turns(g, els, pts[:n], moves, _ref_phase(g)))
    if _put(g, float(pts[n, 0]), float(pts[n, 1])):
        return 1, cs
    undo_moves(g, old)
    return 0, cs


def _fit(g, pts0: np.ndarray, cs: np.ndarray, held: np.ndarray) -> np.ndarray:
    """The elements at ``pts0`` and the free points ``cs`` fitted to one mean edge per
    bond (see the module); the fitted positions, (n + k, 2)."""
    import scipy.sparse as sps
    from scipy.sparse.linalg import factorized

    p = g.p
    L = g.l
    n, k = len(pts0), len(cs)
    anchor = np.r_[np.where(held, 1e6, float(p.flow_densify_hold)), np.zeros(k)]
    hh = np.r_[held, np.zeros(k, dtype=bool)]
    pts = np.r_[pts0, cs]
    rg = g.region
    for _ in range(int(p.flow_densify_fit_rounds)):
        e = _delaunay_bonds(pts, 1.4 * L, g)
        m = len(e)
        dv = pts[e[:, 1]] - pts[e[:, 0]]
        ln = np.maximum(np.hypot(dv[:, 0], dv[:, 1]), 1e-12 * L)
        t = L * dv / ln[:, None]
        # (the new point's bonds pulled ``flow_densify_weight`` times as hard, bonds
        # pressed under ``flow_densify_stiff`` mean edges four times)
        wt = np.where(e[:, 1] >= n, float(p.flow_densify_weight), 1.0)
        wt = np.where((e[:, 1] < n) & (ln < float(p.flow_densify_stiff) * L), 4.0, wt)
        B = sps.csr_matrix((np.r_[-wt, wt], (np.r_[np.arange(m), np.arange(m)], np.r_[e[:, 0], e[:, 1]])), shape=(m, n + k))
        A = (B.T @ B + sps.diags(anchor + 1e-9)).tocsc()
        solve = factorized(A)
        rhs = B.T @ (t * wt[:, None]) + anchor[:, None] * pts
        new = np.c_[solve(np.ascontiguousarray(rhs[:, 0])), solve(np.ascontiguousarray(rhs[:, 1]))]
        new[hh] = pts[hh]
        if rg is not None:
            bad = ~rg.contains(new) | (boundary_distance(rg, new) < 0.5 * L)
            bad[n:] = False
            new[bad] = pts[bad]
        pts = new
    return pts


def _frame_turns(g, els: np.ndarray, pts: np.ndarray, moves: dict, phi0: float) -> dict:
    """Each moved element's rotation turned to the six-fold bond direction of the
    fitted lattice around it, held within ``flow_max_turn`` of the field (§5.3's
    frame; modulo 60 degrees): element -> rotation."""
    L = g.l
    idx = {int(o): q for q, o in enumerate(els.tolist())}
    mv = sorted(moves)
    q = np.asarray([idx[o] for o in mv], dtype=np.intp)
    ph = _phases(pts, q, 1.15 * L)
    ex0 = float(np.median(np.asarray(g.ex_rot, dtype=float))) if len(g.ex_rot) else 0.0
    v = np.asarray(g.p.flow(pts[q]), dtype=float)
    fa = np.arctan2(v[:, 1], v[:, 0])
    lim = float(g.p.flow_max_turn)
    sixty = np.pi / 3
    out = {}
    for k, o in enumerate(mv):
        r0 = float(g.rot[o])
        cur = r0 - ex0  # the element's lattice frame
        want = ph[k] - phi0
        d = (want - cur + sixty / 2) % sixty - sixty / 2
        new = cur + d
        off = (new - fa[k] + sixty / 2) % sixty - sixty / 2
        new -= off - float(np.clip(off, -lim, lim))
        if abs(new - cur) > 1e-12:
            out[o] = ex0 + new
    return out


def _settle(g, moves: dict, old: dict, turns: dict) -> dict:
    """As :func:`strew.grow._flow_net._settle_steps`, each element at a step over
    none also turned to ``turns``' rotation (where it has one)."""
    level = {o: 0 for o in moves}
    check = [o for o in moves if _place(g, o, moves, old, level, turns)]
    _resolve(g, moves, old, level, check, turns)
    return level


def _ref_phase(g) -> float:
    """The exemplar's six-fold bond direction (radians) in its own frame."""
    from ._flow_net import _phases

    L = g.l
    ex = np.asarray(g.ref.xy, dtype=float)
    er = getattr(g.ref.exemplar, "region", None)
    eq = np.flatnonzero(boundary_distance(er, ex) > 1.5 * L) if er is not None else np.arange(len(ex))
    if not len(eq):
        eq = np.arange(len(ex))
    return float(np.angle(np.exp(6j * _phases(ex, eq, 1.15 * L)).sum()) / 6)


def _put(g, sx: float, sy: float) -> bool:
    """An element matched (§5.2) and placed (§5.4) at (sx, sy), joined to the elements
    around, unturned, if one within ``flow_stretch_room`` mean edges leaves it room;
    True when placed (else nothing changes)."""
    L = g.l
    p = g.p
    if not g.in_domain(sx, sy) or g.near(sx, sy, float(p.flow_stretch_room) * L, (ELEMENT,)):
        return False
    ring = sorted(o for o in g.near(sx, sy, 1.5 * L, (ELEMENT,)) if g.orig_of[o] == o)
    if len(ring) < 4:
        return False
    if g.boundary is not None and any(g.crosses_boundary((sx, sy), g.xy[o]) for o in ring):
        return False
    t, removed = open_ring(g, sx, sy, ring)
    pick = g.choose(t)
    if pick is not None:
        a, kk, th = pick
        # (the chosen frame, then turned by a few degrees: within the 10 degrees of
        # the field that ``choose`` allows, the least that frees it)
        for d in (0.0, 0.035, -0.035, 0.07, -0.07):
            if g.xy[t] != (sx, sy):
                g._move(t, sx, sy)
            if g.place(t, a, kk, th + d, reach=1e-12 * L):
                return True
    close_ring(g, t, removed)
    return False

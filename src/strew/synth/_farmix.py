"""Medium stones for small ones far from the largest (extension of §5.1, §7).

:func:`trade_far_small` runs at the end of :func:`strew.synth._grow.grow`, after
``_shell.fill_beside_largest`` and before :func:`~strew.synth._grow.fill_room`.
"""

from __future__ import annotations

import numpy as np
import shapely
from scipy.spatial import cKDTree

from ._shapes import shape_test_needed
from ._state import SynthState

FAR_CLASSES = 3
"""Least size classes in an exemplar for :func:`trade_far_small` to act."""

FAR_Q = 0.7
"""Quantile of the exemplar's smallest-to-largest nearest distances beyond which a
smallest stone counts as far from the largest ones."""

FAR_TAKE = 3
"""Most far smallest stones one middle-class stone takes the place of."""


def _far_counts(pos: np.ndarray, cls: np.ndarray, top: int, mid: int, far: float) -> tuple[int, int]:
    """Smallest (class 0) and ``mid`` class elements farther than ``far`` from every
    element of class ``top``."""
    big = pos[cls == top]
    if len(big) == 0:
        return 0, 0
    d = cKDTree(big).query(pos)[0]
    ok = d > far
    return int(np.count_nonzero(ok & (cls == 0))), int(np.count_nonzero(ok & (cls == mid)))


def _trade_at(
    state: SynthState,
    tree: cKDTree,
    p: np.ndarray,
    wall_d: float,
    cand: np.ndarray,
    low: int,
    since: int,
    reach: float,
    par: np.ndarray,
    par_d: np.ndarray,
    rbar: float,
    take: int = FAR_TAKE,
) -> int:
    """Put the candidate (of ``cand``) whose neighbourhood matches best (Eq. 1,
    ``_grow._ranked_fits``) at ``p``, shape (2,), where it fits once at most
    ``take`` smallest (class ``low``) stones added since ``since`` and not fixed
    are gone, and remove those; returns how many were removed, or -1 where none fits
    (nothing changed). ``tree`` holds ``state.pos[:state.n]``."""
    from ._grow import _ranked_fits  # (lazy: _grow imports this module)

    prep = state.prep
    near = np.asarray(tree.query_ball_point(p, reach), np.int64)
    if len(near) == 0:
        return -1
    off = state.pos[near] - p
    dist = np.hypot(off[:, 0], off[:, 1])
    s_ = state.src[near]
    nc = prep.size_class[s_]
    rem = (nc == low) & ~prep.void[s_] & (near >= since) & ~state.fixed[near]
    lim = np.maximum(prep.rc[cand][:, None] + prep.rc[s_][None, :], prep.min_dist[prep.skind[cand][:, None], prep.skind[s_][None, :]])
    clash = (dist[None, :] < lim) & ~prep.void[s_][None, :]
    hard = clash & ~rem[None, :]
    ngone = (clash & rem[None, :]).sum(axis=1)
    fits = ~hard.any(axis=1) & (ngone <= take) & (prep.r[cand] <= wall_d)
    if not fits.any():
        return -1
    stay = ~(rem & clash[fits].any(axis=0))
    ids, rank = _ranked_fits(prep, cand, fits, par, par_d, near[stay], off[stay], dist[stay], s_[stay], rbar)
    if not len(rank):
        return -1
    b = int(np.flatnonzero(cand == ids[rank[0]])[0])
    gone = near[clash[b] & rem]
    mask = np.zeros(state.n, bool)
    mask[gone] = True
    state.remove(mask)
    state.add(ids[rank[0] : rank[0] + 1], p[None], horizon=False)
    return len(gone)


def _far_setup(state: SynthState):
    """What :func:`trade_far_small` and :func:`trade_far_top` both start from.

    Returns
    -------
    tuple or None
        ``(s, sel, top, mid, low, cand)``: the selected exemplar's index, its visible
        elements ``(n,)`` bool, its largest, middle and smallest size classes, and the saturated middle-class
        candidates ``(m,)`` that lean on something; ``None`` where the trades do not apply
        (fewer than three elements, no region, a shape test, several exemplars, fewer than
        :data:`FAR_CLASSES` size classes, or no candidate).
    """
    from ._grow import _saturated_candidates  # (lazy: _grow imports this module)

    prep = state.prep
    if state.n < 3 or state.region is None or shape_test_needed(prep) or np.count_nonzero(prep.selected) != 1:
        return None
    s = int(np.flatnonzero(prep.selected)[0])
    sel = prep.selected_elements & ~prep.void & (prep.source == s)
    ucls = np.unique(prep.size_class[sel])
    if len(ucls) < FAR_CLASSES:
        return None
    top, mid, low = int(ucls.max()), int(ucls[-2]), int(ucls.min())
    cand = _saturated_candidates(prep)
    cand = cand[(prep.size_class[cand] == mid) & (prep.parent[cand] != -3)]
    if len(cand) == 0:
        return None
    return s, sel, top, mid, low, cand


def trade_far_small(state: SynthState, room: int | None = None, since: int = 0) -> int:
    """Where a window of the output (a disc of the exemplar's area) holds more smallest
    stones per middle-class stone far from its largest stones than the exemplar does,
    put an exemplar stone of the middle size class in the place of a far smallest stone
    (in rng order), where it fits once at most :data:`FAR_TAKE` smallest stones added
    since ``since`` are gone; returns the net number added (in place).

    Extension of §5.1 for several sizes (§7). Measured first (helper syn13w; three sizes
    at 50x, ``/tmp/syn13w/win.py``): the failing windows (seed 1 (1,4), (2,4),
    nn[small>large] 1.071/1.059) hold 24-25 large stones, 153-162 small of which 64-65
    lie beyond 20 from every large one, 73-75 medium; the generator's windows with 25
    large hold 147.5 small, 35 far, 79.5 medium (26-30 large: synth 146.7 small, 38.3
    far, 63.1 medium against 143.9, 33.0, 74.7). Over the whole canvas synth's far
    small : far medium ratio (1335 : 1462) is below the exemplar's (51 : 47), and its
    medium density is the exemplar's (2960 against 2942 wanted), so a canvas-wide target
    never acts (tried: 0 trades); the excess is local, where growth left few large
    stones. Far: beyond the exemplar's :data:`FAR_Q` quantile of small-to-large nearest
    distances. The candidate whose neighbourhood matches best (Eq. 1,
    ``_grow._ranked_fits``, as ``fill_room``) among those that fit.
    """

    prep = state.prep
    far_setup = _far_setup(state)
    if far_setup is None:
        return 0
    s, sel, top, mid, low, cand = far_setup
    # the exemplar's far distance and its far smallest : middle ratio
    epos, ecls = prep.pos[sel], prep.size_class[sel]
    ebig = epos[ecls == top]
    esm = epos[ecls == low]
    if len(ebig) == 0 or len(esm) < 10:
        return 0
    far = float(np.quantile(cKDTree(ebig).query(esm)[0], FAR_Q))
    es, em = _far_counts(epos, np.where(ecls == low, 0, ecls), top, mid, far)
    if em == 0:
        return 0
    ratio = es / em
    c = np.where(~prep.void[state.src], prep.size_class[state.src], -1)
    dom = prep.domains[s]
    wr = float(np.sqrt(dom.area / np.pi))  # a disc of the exemplar's area (the local map's window)
    big = state.pos[:state.n][c == top]
    dl = cKDTree(big).query(state.pos[:state.n])[0]
    far_small = np.flatnonzero((c == low) & (dl > far) & (np.arange(state.n) >= since) & ~state.fixed[:state.n])
    sites = state.pos[far_small][state.rng.permutation(len(far_small))]
    wall = state.region.geometry.boundary
    wd = shapely.distance(wall, shapely.points(sites))
    par = prep.parent[cand]
    par_d = np.where(par >= 0, np.hypot(*(prep.pos[cand] - prep.pos[np.maximum(par, 0)]).T) + prep.r[cand], np.inf)
    rbar = float(prep.rbar[cand].max())
    reach = max(rbar, 2.0 * float(prep.rc.max()), float(prep.min_dist.max()))
    bigtree = cKDTree(big)
    tree = cKDTree(state.pos[:state.n])
    net = 0
    for h in range(len(sites)):
        if room is not None and net >= room:
            break
        p = sites[h]
        # the output's far smallest : middle ratio in a window around the site
        loc = np.asarray(tree.query_ball_point(p, wr), np.int64)
        lc = prep.size_class[state.src[loc]]
        lv = ~prep.void[state.src[loc]]
        lf = bigtree.query(state.pos[loc])[0] > far
        ls = int(np.count_nonzero(lv & lf & (lc == low)))
        lm = int(np.count_nonzero(lv & lf & (lc == mid)))
        if ls <= ratio * (lm + 1) + 1.5:
            continue
        if tree.query(p)[0] > 1e-9:
            continue  # (taken by an earlier trade)
        gone = _trade_at(state, tree, p, float(wd[h]), cand, low, since, reach, par, par_d, rbar)
        if gone < 0:
            continue
        net += 1 - gone
        tree = cKDTree(state.pos[:state.n])
    return net


TOP_TRADE = True
"""Trade smallest stones beside a largest stone far from every middle-class stone for a
middle-class stone (:func:`trade_far_top`; helper s30h; off: no such trade)."""

TOP_FAR_Q = 0.9
"""Quantile of the exemplar's largest-to-middle nearest distances beyond which an output
largest stone counts as far from the middle size class (as ``_shell.MID_FAR_Q``)."""

TOP_TAKE = FAR_TAKE
"""Most smallest stones one middle-class stone beside a far largest one takes the place of."""

TOP_STEPS = (1.0, 1.1, 1.2, 1.35, 1.5)
"""Distances of the sites from a far largest stone, as multiples of the bound (kept
where within the exemplar's far distance). Measured (h6s19 seeds 1-3, nn[large>medium]):
(1,) 0.305/0.191/0.250, (1, 1.15, 1.3) 0.271/0.177/0.229, these 0.258/0.177/0.212."""

TOP_FAR_BORDER = True
"""Measure the exemplar's far distance by the nearest-neighbour border method: over the
largest stones nearer a middle-class stone than the frame, as the fidelity metric's nn
counts them (helper s37h; off: over every largest stone). Measured (--harder three_sizes
h6s19, 80:20:30 at size 150): the raw q90 is 38.9, the border-method q90 20.3 (every
largest stone the metric sees touches a medium one); the stones along the frame whose
medium lies beyond it made the raw quantile twice the real one."""

TOP_BUDGET_SE = 1.0
""":func:`trade_far_top` may bring each middle kind up to its exemplar's count over the
whole frame plus this many Poisson standard errors of that count, per unit area (where
above the inner-density budget; 0: the inner-density budget alone). Helper s37h: with the
border-method far distance alone h6s19's nn[large>medium] went 0.287 / 0.184 / 0.222 ->
0.269 / 0.197 / 0.240 (seeds 1-3 at 3.5x), the inner-density budget (5.4 medium per 1e4,
the exemplar's 14 over its frame are 6.2, its generator drawn at the output's size 8.9)
spent; with this cap 0.051 / 0.039 / 0.073 (2.0: 0.041 / 0.027 / 0.050, but the varied
three_sizes v25 (65 medium stones) then failed density[medium] 0.254 against 0.238)."""

TOP_BUDGET_SHARE = 0.1
"""Least share of the exemplar's visible elements a middle kind holds for the
:data:`TOP_BUDGET_SE` cap (h6s19: 14 of 109; --harder h12 400:15:15: 15 of 430, kept to
its share by tests/synth/test_synth_sm_middle_share.py)."""

TOP_DRAW = True
"""Try a far largest stone's sites nearest first to a distance drawn (``state.rng``) from
the exemplar's largest-to-middle nearest distances within the far distance, instead of
nearest the bound first (see :func:`trade_far_top`; off: bound first). Only in an output
whose growth held its largest class back (``_grow._top_ahead`` found it ahead of its
density at least once, ``state.top_held``; helper s46t): elsewhere the bound first, as
before. Ungated, --harder three sizes 80:20:30 at size 150 (h6s29), whose large stones
stand at 0.85 of their density, lost seeds 1 and 4 (nn[medium>small] 0.0798 / 0.0635,
main 6/6)."""

TOP_ANGLES = 24
"""Sites laid out around a far largest stone, per collision radius level."""


def trade_far_top(state: SynthState, room: int | None = None, since: int = 0) -> int:
    """Where an output largest stone lies farther from every middle-class stone than the
    exemplar's :data:`TOP_FAR_Q` quantile of largest-to-middle nearest distances (by the
    border method, :data:`TOP_FAR_BORDER`), put a middle-class stone snug against it in
    the place of at most :data:`FAR_TAKE` smallest stones added since ``since``
    (:func:`_trade_at`), while the middle kinds stay below their exemplar density (counted
    as ``_displace.fill_displaced`` counts it, or their whole frame's count plus its
    noise, :data:`TOP_BUDGET_SE`); returns the net number added (in place).

    Extension of §5.1 for several sizes (§7). Measured first (helper s29m, three sizes
    --harder h6s19, ``benchmarks/results/s29m_findings.txt``): nn[large>medium] fails
    (0.487 at seed 1) with the medium budget open (26 stones), but of 6042 sites snug
    against a largest stone far from every medium only 6 were clear: growth filled the
    shell with smallest stones (copies bring their small stones where the copy's medium
    neighbour did not come), and ``_shell.fill_beside_far_small`` has no room to add into.
    So instead of adding, trade, as :func:`trade_far_small` does for far smallest stones.

    Sites: :data:`TOP_ANGLES` points (from a random start angle) at :data:`TOP_STEPS`
    multiples of the bound ``max(rc_p + rc_q, min_dist)`` from each far largest stone, for candidate collision
    radii at ``_shell.SHELL_LEVELS``, kept where inside the domain and no farther than the
    exemplar's far distance (so the trade brings the largest stone within it); far largest
    stones visited in an order drawn from ``state.rng``, each traded for once at most. Only
    exemplars of at least :data:`FAR_CLASSES` size classes, one exemplar filling the
    region, no shape test.
    """
    from ._displace import _inner_deficit  # (lazy: _displace imports _grow)
    from ._shell import SHELL_LEVELS

    prep = state.prep
    far_setup = _far_setup(state) if TOP_TRADE else None
    if far_setup is None:
        return 0
    s, sel, top, mid, low, cand = far_setup
    etop, emid = prep.pos[sel & (prep.size_class == top)], prep.pos[sel & (prep.size_class == mid)]
    if len(etop) < 3 or len(emid) < 3:
        return 0
    if np.count_nonzero(sel & (prep.size_class == low)) < len(emid):
        # smallest stones rarer than middle ones: each trade takes up to TOP_TAKE of the rare
        # kind (--harder h7s22, small 4.5 per 1e4 against medium 26.8: nn[medium>small] 0.32
        # -> 0.348 FAIL at seed 1 when traded)
        return 0
    dtop = cKDTree(emid).query(etop)[0]
    if TOP_FAR_BORDER:
        # the nearest-neighbour border method (as the fidelity metric's nn): a largest
        # stone nearer the frame than every middle one is left out (its nearest may lie
        # beyond the frame); the raw quantile counts them as far
        seen = dtop <= shapely.distance(prep.domains[s].boundary, shapely.points(etop))
        if np.count_nonzero(seen) >= 3:
            dtop = dtop[seen]
    far = float(np.quantile(dtop, TOP_FAR_Q))
    near_d = np.sort(dtop[dtop <= far])
    # budget: the middle kinds' deficit against their exemplar density (as fill_displaced)
    deficit = _inner_deficit(state, prep.skind[cand])
    if deficit is None:
        return 0
    inner, vis, budget = deficit
    if TOP_BUDGET_SE > 0:
        # the exemplar's count of each middle kind over its whole frame, plus its
        # sampling noise (Poisson standard errors), per unit area: a rare middle class
        # (14 stones) is a noisy sample of its density, and the trade acts only where a
        # largest stone lacks the middle neighbour the exemplar gives them all
        mine = np.bincount(prep.skind[sel], minlength=len(budget)).astype(float)
        cap = (mine + TOP_BUDGET_SE * np.sqrt(mine)) / float(prep.domains[s].area) * float(inner.area)
        inn = vis[shapely.contains_xy(inner, state.pos[vis, 0], state.pos[vis, 1])]
        have = np.bincount(prep.skind[state.src[inn]], minlength=len(budget))
        kk = np.unique(prep.skind[cand])
        # not for a rare middle class (helper sm: it takes its share, not the share plus
        # its sampling error; three sizes 400:15:15 medium 1.257x its share with the cap)
        kk = kk[mine[kk] >= TOP_BUDGET_SHARE * mine.sum()]
        budget[kk] = np.maximum(budget[kk], np.floor(cap[kk] - have[kk]).astype(np.int64))
    geom = state.region.geometry
    cand = cand[budget[prep.skind[cand]] > 0]
    if len(cand) == 0:
        return 0
    cls = prep.size_class[state.src[vis]]
    if not np.any(cls == mid) or not np.any(cls == top):
        return 0
    dmid = cKDTree(state.pos[vis[cls == mid]]).query(state.pos[vis])[0]
    owners = vis[(cls == top) & (dmid > far) & (vis >= since)]
    if len(owners) == 0:
        return 0
    owners = owners[state.rng.permutation(len(owners))]
    opos = state.pos[owners].copy()  # (positions: removals renumber)
    orc = prep.rc[state.src[owners]]
    new_mid: list[np.ndarray] = []
    ok = int(prep.skind[state.src[owners[0]]])
    rcs = prep.rc[cand]
    levels = sorted({float(np.quantile(rcs, q)) for q in SHELL_LEVELS})
    rbar = float(prep.rbar[cand].max())
    reach = max(rbar, 2.0 * float(prep.rc.max()), float(prep.min_dist.max()))
    wall = geom.boundary
    net = 0
    tree = cKDTree(state.pos[:state.n])
    for i in range(len(opos)):
        if room is not None and net >= room:
            break
        if not budget.any():
            break
        if new_mid and float(np.hypot(*(np.asarray(new_mid) - opos[i]).T).min()) <= far:
            continue  # (served by an earlier trade)
        a0 = float(state.rng.uniform(0.0, 2.0 * np.pi))
        ang = a0 + 2.0 * np.pi * np.arange(TOP_ANGLES) / TOP_ANGLES
        pts = []
        dist = []
        for lev in levels:
            d0 = max(float(orc[i]) + lev, float(prep.min_dist[int(prep.skind[cand[0]]), ok])) * (1.0 + 1e-9) + 1e-9
            for st in TOP_STEPS:
                d = d0 * st
                if d > far:
                    continue
                pts.append(opos[i] + d * np.column_stack([np.cos(ang), np.sin(ang)]))
                dist.append(np.full(TOP_ANGLES, d))
        if not pts:
            continue
        pts = np.concatenate(pts)
        if TOP_DRAW and len(near_d) and getattr(state, "top_held", False):
            # sites nearest a distance drawn from the exemplar's largest-to-middle nearest
            # distances first (helper s44t): bound first, every trade put its middle stone
            # at the closest approach, where the exemplar holds none (--varied three sizes
            # 60:60:26, variant 27: the share of inner large stones whose nearest medium
            # stands nearer than the exemplar's closest pair 0.133 -> 0.218 in this pass,
            # nn[large>medium] failing, benchmarks/s42t_contacts.py)
            want = float(near_d[int(state.rng.integers(len(near_d)))])
            pts = pts[np.argsort(np.abs(np.concatenate(dist) - want), kind="stable")]
        pts = pts[state.in_domain(pts)]
        if len(pts) == 0:
            continue
        wd = shapely.distance(wall, shapely.points(pts))
        par = prep.parent[cand]
        par_d = np.where(par >= 0, np.hypot(*(prep.pos[cand] - prep.pos[np.maximum(par, 0)]).T) + prep.r[cand], np.inf)
        for h in range(len(pts)):
            gone = _trade_at(state, tree, pts[h], float(wd[h]), cand, low, since, reach, par, par_d, rbar, TOP_TAKE)
            if gone < 0:
                continue
            k = int(prep.skind[state.src[state.n - 1]])
            budget[k] -= 1
            cand = cand[budget[prep.skind[cand]] > 0]
            net += 1 - gone
            new_mid.append(pts[h].copy())
            tree = cKDTree(state.pos[:state.n])
            break
        if len(cand) == 0:
            break
    return net

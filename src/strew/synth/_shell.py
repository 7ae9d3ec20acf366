"""Small stones snug against the largest ones (extension of §5.1, §7).

:func:`fill_beside_largest` runs at the end of :func:`strew.synth._grow.grow`, after
``_displace.fill_displaced`` and before :func:`~strew.synth._grow.fill_room`.
"""

from __future__ import annotations

import numpy as np
import shapely
from scipy.spatial import cKDTree

from ._shapes import shape_test_needed
from ._state import SynthState

SHELL_FILL = True
""":func:`grow` puts an exemplar's saturated smallest stones into the places snug
against its largest ones that the output left open (see :func:`fill_beside_largest`;
off: the output as growth and ``fill_displaced`` leave it)."""

SHELL_CLASSES = 3
"""Least size classes in an exemplar for :func:`fill_beside_largest` to act (as
``_grow.NEAR_LARGE_CLASSES``: the shell deficit was measured on three sizes only)."""

SHELL_LEVELS = (0.0, 0.5, 1.0)
"""Quantiles of the candidates' collision radii at which snug sites are laid out."""


def _snug_sites(big: np.ndarray, rb: np.ndarray, other: np.ndarray, ro: np.ndarray, pairs: list[list[int]]) -> np.ndarray:
    """(m, 2) points at distance ``rb[i]`` from ``big[i]`` and ``ro[j]`` from ``other[j]``
    for every pair ``j in pairs[i]`` (both intersections of the two circles)."""
    return _snug_sites_owned(big, rb, other, ro, pairs)[0]


def _snug_sites_owned(big: np.ndarray, rb: np.ndarray, other: np.ndarray, ro: np.ndarray, pairs: list[list[int]]) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_snug_sites` and (m,) the index ``i`` into ``big`` of each point."""
    ii = np.repeat(np.arange(len(big)), [len(p) for p in pairs])
    if len(ii) == 0:
        return np.zeros((0, 2)), np.zeros(0, np.int64)
    jj = np.fromiter((j for p in pairs for j in p), np.int64, len(ii))
    c0, c1 = big[ii], other[jj]
    a, b = rb[ii], ro[jj]
    v = c1 - c0
    d = np.hypot(v[:, 0], v[:, 1])
    ok = (d > 1e-12) & (d < a + b) & (d > np.abs(a - b))
    c0, v, d, a, b = c0[ok], v[ok], d[ok], a[ok], b[ok]
    x = (d * d + a * a - b * b) / (2.0 * d)
    h = np.sqrt(np.maximum(a * a - x * x, 0.0))
    u = v / d[:, None]
    n = np.c_[-u[:, 1], u[:, 0]]
    m = c0 + x[:, None] * u
    return np.concatenate([m + h[:, None] * n, m - h[:, None] * n]), np.tile(ii[ok], 2)


def _fits_at(
    state: SynthState, tree: cKDTree, n0: int, reach: float, cand: np.ndarray, c: np.ndarray, wall_d: float, budget: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Which candidate stones fit at one site ``c``, shape (2,).

    The output's elements within ``reach`` of ``c`` (``tree`` holds the first ``n0``;
    those added since are all tested) as indices ``near``, shape (m,), their offsets
    ``off``, shape (m, 2), distances ``dist`` and exemplar sources ``src``, shape (m,),
    and ``fits``, shape (len(cand),): the candidate keeps its collision radius plus each
    neighbour's, and the kinds' ``min_dist`` (§4.1), from every one, lies within
    ``wall_d`` of the region's edge, and its kind still has ``budget``.
    """
    prep = state.prep
    near = np.r_[np.asarray(tree.query_ball_point(c, reach), np.int64), np.arange(n0, state.n)]
    off = state.pos[near] - c
    dist = np.hypot(off[:, 0], off[:, 1])
    src = state.src[near]
    lim = np.maximum(prep.rc[cand][:, None] + prep.rc[src][None, :], prep.min_dist[prep.skind[cand][:, None], prep.skind[src][None, :]])
    fits = np.all(dist[None, :] >= lim, axis=1) & (prep.r[cand] <= wall_d) & (budget[prep.skind[cand]] > 0)
    return near, off, dist, src, fits


def fill_beside_largest(state: SynthState, room: int | None = None, since: int = 0) -> int:
    """Put an exemplar's saturated smallest stones (``_grow._saturated_candidates(prep,
    smallest=True)``) into the places snug against an output element of its largest
    size class where one fits, in random order, until the kind reaches its exemplar's
    density (``_grow._room_cap``); returns the number added (in place).

    Extension of §5.1 for several sizes (§7: "significant differences in element size
    ... are not supported"). Measured first (helper syn13v; three sizes at 50x the
    exemplar's area, ``python benchmarks/syn13v_windows.py --seeds 1,4 --oracle-seeds
    1``, and 12x, seeds 1-2): the failing windows of the local map fail on
    nn[small>large] through its upper deciles (q60-q90 0.23-0.75 s too far; over all
    windows q80 +0.16 s against the generator's +0.05 s). The large stones themselves
    are placed as a fresh draw of the exemplar's generator places them (empty-space
    distances to the nearest large stone q50-q99 15.1/21.1/24.2/26.8/31.7 against
    14.7/20.4/23.5/26.1/31.0, large-to-large nearest distances alike); the small stones
    are not: in the shell 14-16 from a large stone's centre (contact) 57-62 per 1e4
    units of area against the exemplar's 71 and the generator's 75-76, 16-18: 106-111
    against 116 and 127-130, while the share of that shell where one more small stone
    fits is 0.048 against the exemplar's 0.034 (16-18: 0.044 against 0.024). So 25 %
    of the small stones lie beyond 20 from every large one against the exemplar's and
    the generator's 19 %. Growth places 98 % of the small stones (fill_room 1.6 %): a
    copy brings its small stones at its own exemplar's offsets from its large stone,
    and where the copy's large stone moved or another copy's stands, the snug place
    stays open; ``fill_room`` looks at Delaunay circumcentres only, which in the thin
    crescent along a large stone's edge are seldom where a small stone fits.

    Sites: for each output element of the largest size class added since ``since``
    and each output neighbour, the two points at which a small stone touches both
    (``max(rc_p + rc_q, min_dist)`` from each; the test of every other step) for
    candidate collision radii at :data:`SHELL_LEVELS`, kept where one fits; visited in
    an order drawn from ``state.rng``, each takes the candidate whose neighbourhood
    matches the site's surroundings best (Eq. 1, ``_grow._ranked_fits``: a candidate
    that leans on a larger element only beside an output element of its parent's kind,
    as ``fill_room``) among those that fit there. Only exemplars of at least
    :data:`SHELL_CLASSES` size classes, one exemplar filling the region, no shape test.
    """
    from ._grow import (  # (lazy: _grow imports this module)
        _ranked_fits,
        _room_cap,
        _saturated_candidates,
    )

    prep = state.prep
    if not SHELL_FILL or state.n < 3 or state.region is None or shape_test_needed(prep) or np.count_nonzero(prep.selected) != 1:
        return 0
    sel = prep.selected_elements & ~prep.void
    s = int(np.flatnonzero(prep.selected)[0])
    cls = prep.size_class[sel & (prep.source == s)]
    if len(np.unique(cls)) < SHELL_CLASSES:
        return 0
    top = int(cls.max())
    cand = _saturated_candidates(prep, smallest=True)
    cand = cand[prep.parent[cand] != -3]
    if len(cand) == 0:
        return 0
    S = int(prep.skind.max()) + 1
    budget = np.zeros(S, np.int64)
    for k in np.unique(prep.skind[cand]):
        cap = _room_cap(state, int(k))
        budget[k] = 0 if cap is None else cap
    if room is not None:
        budget = np.minimum(budget, room)
    cand = cand[budget[prep.skind[cand]] > 0]
    if len(cand) == 0:
        return 0
    n = state.n
    vis = np.flatnonzero(~prep.void[state.src[:n]])
    pos, src = state.pos[vis], state.src[vis]
    sk = prep.skind[src]
    big = np.flatnonzero((prep.size_class[src] == top) & (vis >= since))
    if len(big) == 0:
        return 0
    tree = cKDTree(pos)
    rcs = prep.rc[cand]
    reach = float(prep.rc.max() + 2.0 * rcs.max() + prep.rc.max())
    reach = max(reach, float(prep.min_dist.max() + 2.0 * rcs.max()))
    pairs = [[j for j in lst if j != i] for i, lst in zip(big, tree.query_ball_point(pos[big], reach))]
    k0 = int(prep.skind[cand[0]])  # (sites for the first kind's min_dist; each candidate is tested with its own below)
    sites = []
    eps = 1e-9
    for lev in sorted({float(np.quantile(rcs, q)) for q in SHELL_LEVELS}):
        lim = np.maximum(lev + prep.rc[src], prep.min_dist[k0, sk]) * (1.0 + eps) + eps
        sites.append(_snug_sites(pos[big], lim[big], pos, lim, pairs))
    pts = np.concatenate(sites) if sites else np.zeros((0, 2))
    if len(pts) == 0:
        return 0
    pts = pts[state.in_domain(pts)]
    # a first, static test against the output with the smallest candidate
    m0 = cand[np.argmin(rcs)]
    ok = ~state.conflicts(pts, np.full(len(pts), m0, np.int64))
    pts = pts[ok]
    if len(pts) == 0:
        return 0
    pts = pts[state.rng.permutation(len(pts))]
    wall = state.region.geometry.boundary
    wd = shapely.distance(wall, shapely.points(pts))
    par = prep.parent[cand]
    par_d = np.where(par >= 0, np.hypot(*(prep.pos[cand] - prep.pos[np.maximum(par, 0)]).T) + prep.r[cand], np.inf)
    rbar = float(prep.rbar[cand].max())
    reach2 = max(rbar, float(prep.rc.max() + rcs.max()), float(prep.min_dist.max()))
    tree = cKDTree(state.pos[:n])
    n0 = n
    added = 0
    for h in range(len(pts)):
        if not budget.any():
            break
        c = pts[h]
        near_h, off, dist, s_, fits = _fits_at(state, tree, n0, reach2, cand, c, float(wd[h]), budget)
        if not fits.any():
            continue
        ids, order = _ranked_fits(prep, cand, fits, par, par_d, near_h, off, dist, s_, rbar)
        if len(order):
            best = order[0]
            state.add(ids[best : best + 1], c[None], horizon=False)
            budget[prep.skind[ids[best]]] -= 1
            added += 1
    return added


MID_FAR_Q = 0.9
"""Quantile of the exemplar's smallest-to-middle nearest distances beyond which an
output smallest stone counts as far from the middle size class (:func:`fill_beside_far_small`)."""


def fill_beside_far_small(state: SynthState, room: int | None = None, since: int = 0) -> int:
    """Put saturated stones of an exemplar's middle size class, below their exemplar's
    density, into the places snug against the output's smallest stones that lie farther
    from every middle-class stone than the exemplar's :data:`MID_FAR_Q` quantile of
    those distances (in rng order, each small stone served once); returns the number
    added (in place).

    Extension of §5.1 for several sizes (§7: "significant differences in element size
    ... are not supported"). Measured first (helper syn13y; three sizes --harder h7s7,
    20:120:20, seeds 1-2, ``/tmp/syn13y/diag.py``): nn[small>medium] fails (0.0568 and
    0.0516 against 0.0509) on its top deciles only (signed error q70/q80/q90 +0.06/+0.11
    /+0.25 s; exemplar deciles 0.75-0.87 s: every small stone of the exemplar lies snug
    against a medium one), medium stones at 0.90-0.92x their exemplar density after
    ``fill_displaced`` (small 0.99x, large 1.03x), 33 % of the small stones (95 of 289)
    beyond the exemplar's q95 small-to-medium distance; 46 % of those have room for a
    medium stone touching them (10 % of the exemplar's small stones have). Growth placed
    them all (copies bring their small stones at their own offsets, and where the
    copy's medium neighbour did not come the place stays open); ``fill_displaced`` and
    ``fill_room`` look at Delaunay circumcentres, which beside a small stone's edge are
    seldom where a medium stone fits (as :func:`fill_beside_largest` found for small
    stones beside large ones).

    Sites: the two points at which a middle-class stone touches both a far smallest
    stone and one of its output neighbours (``max(rc_p + rc_q, min_dist)``), for
    candidate collision radii at :data:`SHELL_LEVELS`, kept where one fits; visited in
    an order drawn from ``state.rng``; each takes the candidate whose neighbourhood
    matches the site's surroundings best (Eq. 1, ``_grow._ranked_fits``) among those
    that fit, where the new stone's nearest middle-class stone is no farther than the
    exemplar's :data:`MID_FAR_Q` quantile of middle-to-middle nearest distances, until
    the kind reaches its exemplar's density (counted as ``_displace.fill_displaced``
    counts it). Only exemplars of at least
    :data:`SHELL_CLASSES` size classes, one exemplar filling the region, no shape test.
    """
    from ._displace import _inner_deficit  # (lazy: _displace imports _grow)
    from ._grow import (  # (lazy: _grow imports this module)
        _ranked_fits,
        _saturated_candidates,
    )

    prep = state.prep
    if not SHELL_FILL or state.n < 3 or state.region is None or shape_test_needed(prep) or np.count_nonzero(prep.selected) != 1:
        return 0
    s = int(np.flatnonzero(prep.selected)[0])
    sel = prep.selected_elements & ~prep.void & (prep.source == s)
    ucls = np.unique(prep.size_class[sel])
    if len(ucls) < SHELL_CLASSES:
        return 0
    low, mid = int(ucls.min()), int(ucls[-2])
    cand = _saturated_candidates(prep)
    cand = cand[(prep.size_class[cand] == mid) & (prep.parent[cand] != -3)]
    if len(cand) == 0:
        return 0
    # the exemplar's far distance: small to middle nearest distances
    esm, emid = prep.pos[sel & (prep.size_class == low)], prep.pos[sel & (prep.size_class == mid)]
    if len(esm) < 10 or len(emid) < 3:
        return 0
    far = float(np.quantile(cKDTree(emid).query(esm)[0], MID_FAR_Q))
    # ... and its middle-to-middle one: a new middle stone comes no farther than that
    # from every other (helper syn13y: unguarded, a stone beside a far small one was
    # itself a far middle one; three sizes at 50x seed 3, window (7, 1) of few medium
    # stones among 34 large, nn[medium>medium] 0.934 -> 1.011)
    far_mm = float(np.quantile(cKDTree(emid).query(emid, k=2)[0][:, 1], MID_FAR_Q))
    # budget: the middle kinds' deficit against their exemplar density (as fill_displaced)
    deficit = _inner_deficit(state, prep.skind[cand])
    if deficit is None:
        return 0
    _, vis, budget = deficit
    n = state.n
    if room is not None:
        budget = np.minimum(budget, room)
    cand = cand[budget[prep.skind[cand]] > 0]
    if len(cand) == 0:
        return 0
    pos, src = state.pos[vis], state.src[vis]
    cls = prep.size_class[src]
    if not np.any(cls == mid):
        return 0
    dmid = cKDTree(pos[cls == mid]).query(pos)[0]
    owners = np.flatnonzero((cls == low) & (dmid > far) & (vis >= since))
    if len(owners) == 0:
        return 0
    sk = prep.skind[src]
    tree = cKDTree(pos)
    rcs = prep.rc[cand]
    reach = float(prep.rc.max() + 2.0 * rcs.max() + prep.rc.max())
    reach = max(reach, float(prep.min_dist.max() + 2.0 * rcs.max()))
    pairs = [[j for j in lst if j != i] for i, lst in zip(owners, tree.query_ball_point(pos[owners], reach))]
    k0 = int(prep.skind[cand[0]])
    pts, own = [], []
    for lev in sorted({float(np.quantile(rcs, q)) for q in SHELL_LEVELS}):
        lim = np.maximum(lev + prep.rc[src], prep.min_dist[k0, sk]) * (1.0 + 1e-9) + 1e-9
        p, o = _snug_sites_owned(pos[owners], lim[owners], pos, lim, pairs)
        pts.append(p)
        own.append(o)
    pts = np.concatenate(pts)
    own = np.concatenate(own)
    if len(pts) == 0:
        return 0
    keep = state.in_domain(pts)
    pts, own = pts[keep], own[keep]
    m0 = cand[np.argmin(rcs)]
    keep = ~state.conflicts(pts, np.full(len(pts), m0, np.int64))
    pts, own = pts[keep], own[keep]
    if len(pts) == 0:
        return 0
    order = state.rng.permutation(len(pts))
    pts, own = pts[order], own[order]
    wd = shapely.distance(state.region.geometry.boundary, shapely.points(pts))
    par = prep.parent[cand]
    par_d = np.where(par >= 0, np.hypot(*(prep.pos[cand] - prep.pos[np.maximum(par, 0)]).T) + prep.r[cand], np.inf)
    rbar = float(prep.rbar[cand].max())
    reach2 = max(rbar, float(prep.rc.max() + rcs.max()), float(prep.min_dist.max()))
    tree = cKDTree(state.pos[:n])
    otree = cKDTree(pos[owners])
    served = np.zeros(len(owners), bool)
    mtree = cKDTree(pos[cls == mid])
    new_mid: list[np.ndarray] = []
    n0 = n
    added = 0
    for h in range(len(pts)):
        if not budget.any():
            break
        if served[own[h]]:
            continue
        c = pts[h]
        near_h, off, dist, s_, fits = _fits_at(state, tree, n0, reach2, cand, c, float(wd[h]), budget)
        if not fits.any():
            continue
        dm = mtree.query(c)[0]
        if new_mid:
            dm = min(dm, float(np.hypot(*(np.asarray(new_mid) - c).T).min()))
        if dm > far_mm:
            continue
        ids, rank = _ranked_fits(prep, cand, fits, par, par_d, near_h, off, dist, s_, rbar)
        if len(rank):
            best = rank[0]
            state.add(ids[best : best + 1], c[None], horizon=False)
            budget[prep.skind[ids[best]]] -= 1
            served[np.asarray(otree.query_ball_point(c, far), np.int64)] = True
            new_mid.append(c.copy())
            added += 1
    return added

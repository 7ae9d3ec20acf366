"""Lone small elements given a partner copied from the exemplar (extension of §5.1, §7).

:func:`fill_partners` runs at the end of :func:`strew.synth._grow.grow`, after
:func:`~strew.synth._grow.fill_room` and before :func:`~strew.synth._grow.fill_holes`.
"""

from __future__ import annotations

import numpy as np
import shapely
from scipy.spatial import cKDTree

from ._shapes import shape_clashes, shape_test_needed
from ._state import SynthState, map_offsets

PARTNERS = True
""":func:`grow` gives lone elements of a saturated smallest kind a partner (see
:func:`fill_partners`)."""

PARTNER_Q = 0.9
"""The quantile of a kind's nearest same-kind distance in its exemplar (away from the
frame) beyond which an element stands alone (:func:`fill_partners`)."""


def fill_partners(state: SynthState, room: int | None = None) -> int:
    """Give lone elements of a kind of the exemplar's smallest size class that the
    exemplar leaves saturated (``_grow._room_rate(smallest=True)`` finite) a partner,
    a copy of one of the exemplar's pairs of that kind, until the output's share of
    lone ones (inside the region shrunk by two of the largest collision radii) falls to
    the exemplar's (in place); returns the number added.

    Extension of §5.1 for several sizes (§7). Small elements thrown to saturation into
    the gaps between larger ones stand in groups wherever a gap holds more than one;
    growth copies them with their neighbourhood, but a copy whose neighbours are
    refused (they overlap elements already placed) leaves its small element alone in a
    gap, and the gaps between larger ones that no copy's free-space point reached are
    filled singly (``fill_room``). Measured first (two sizes ratio 0.65, 30:150 asked,
    30:50 drawn, variant seed 8 at 3.5x; ``python benchmarks/synth_variants.py
    --harder``, h11s8, seeds 1 and 2): 157 of 491-512 pebbles away from the frame
    (0.31-0.32) had no pebble within the exemplar's 90th percentile of the pebbles'
    nearest-pebble distance, against 0.11 in the exemplar; nn[pebble>pebble] 0.109 and
    0.122 against 0.086, its signed error +0.17 to +0.39 s at the two upper deciles and
    under 0.13 s below; growth leaves it so (``fill_room``, capped at the pebbles'
    density, added 2 and 0 pebbles). The exemplar's generator drawn at the output's
    size (six draws, ``benchmarks/svar13i_oracle.big_params``) scores 0.033-0.227,
    two of six passing.

    The lone elements are visited farthest from their nearest same-kind neighbour
    first; each takes, at the offset of one of the exemplar's pairs of its kind no
    farther apart than that quantile (both ways round, drawn in the ``rng``'s order
    among those that fit), a copy of the pair's other element, where it clears every
    element by ``max(rc_p + rc_q, min_dist)``, lies in the domain and its disc within
    the region, and its shape clashes with none. An element that a partner given
    before already groups is skipped. At most ``room`` elements are added. One
    exemplar only (several share the region: their kinds' lone shares are not one
    exemplar's); a ring's tiles (``_grow._ring_kids``) take no part. The partners
    are not capped at the kind's density (``fill_room``'s cap): h11s8 gained 22-24
    pebbles on 546-567 (+4 %); at 2x, seeds 1 and 2, the lone share 0.267 -> 0.208
    (the test).

    Measured (``python benchmarks/synth_variants.py --harder``): h11s8 seeds 1-6 0/6
    -> 5/6 (nn[pebble>pebble] 0.090-0.122 -> pass, 0.090 on seed 2).
    """
    from ._grow import _ring_kids, _room_rate  # (lazy: _grow imports this module)

    prep = state.prep
    if not PARTNERS or state.n < 3 or state.region is None or np.count_nonzero(prep.selected) != 1:
        return 0
    rate = _room_rate(prep, smallest=True)
    kinds = np.flatnonzero(np.isfinite(rate))
    if not len(kinds):
        return 0
    sel = prep.selected_elements & ~prep.void
    s = int(np.flatnonzero(prep.selected)[0])
    margin = 2.0 * float(prep.rc.max())
    ex_inner = prep.domains[s].buffer(-margin)
    inner = state.region.geometry.buffer(-margin)
    if ex_inner.is_empty or inner.is_empty:
        return 0
    boundary = state.region.geometry.boundary
    shape_test = shape_test_needed(prep)
    reach = max(2.0 * float(prep.rc.max()), float(prep.min_dist.max()))
    added = 0
    for k in kinds:
        mine = np.flatnonzero(sel & (prep.skind == k) & (prep.source == s))
        if len(mine) < 10 or _ring_kids(prep)[0][mine].any():
            # a ring's tiles stand where their ring puts them (_complete_anchor_rings):
            # a partner beside a lone one is a stray tile (rings h2s7 of --harder, seed
            # 2: 3089 -> 3132 elements, regularity 0.086 against 0.05)
            continue
        exy = prep.pos[mine]
        ein = shapely.contains_xy(ex_inner, exy[:, 0], exy[:, 1])
        if ein.sum() < 5:
            continue
        extree = cKDTree(exy)
        d = extree.query(exy, k=2)[0][:, 1]
        g = float(np.quantile(d[ein], PARTNER_Q))
        lone_ex = float(np.mean(d[ein] > g))
        pr = np.array(sorted(extree.query_pairs(g)), np.int64).reshape(-1, 2)
        if not len(pr):
            continue
        pr = np.r_[pr, pr[:, ::-1]]
        off = exy[pr[:, 1]] - exy[pr[:, 0]]
        part = mine[pr[:, 1]]
        own = np.flatnonzero((prep.skind[state.src[: state.n]] == k) & ~prep.void[state.src[: state.n]])
        if len(own) < 2:
            continue
        oxy = state.pos[own]
        oin = shapely.contains_xy(inner, oxy[:, 0], oxy[:, 1])
        dl = cKDTree(oxy).query(oxy, k=2)[0][:, 1]
        lone = oin & (dl > g)
        budget = int(np.floor(lone.sum() - lone_ex * oin.sum()))
        if budget <= 0:
            continue
        todo = own[lone][np.argsort(-dl[lone], kind="stable")]  # the loneliest first
        tree = cKDTree(state.pos[: state.n])
        n0 = state.n
        for e in todo:
            if budget <= 0 or (room is not None and added >= room):
                break
            p = state.pos[e]
            if state.n > n0:
                # grouped by a partner given before
                newer = np.arange(n0, state.n)
                if np.any((prep.skind[state.src[newer]] == k) & (np.hypot(*(state.pos[newer] - p).T) <= g)):
                    continue
            c = p + map_offsets(np.broadcast_to(p, off.shape), off)
            near = np.r_[np.asarray(tree.query_ball_point(p, g + reach), np.int64), np.arange(n0, state.n)]
            dd = np.hypot(c[:, None, 0] - state.pos[near][None, :, 0], c[:, None, 1] - state.pos[near][None, :, 1])
            s_ = state.src[near]
            lim = np.maximum(prep.rc[part][:, None] + prep.rc[s_][None, :], prep.min_dist[prep.skind[part][:, None], prep.skind[s_][None, :]])
            f = np.flatnonzero(np.all(dd >= lim, axis=1))
            if len(f):
                f = f[state.in_domain(c[f])]
            if len(f):
                f = f[shapely.distance(boundary, shapely.points(c[f])) >= prep.r[part[f]]]
            if not len(f):
                continue
            for b in f[state.rng.permutation(len(f))]:
                if shape_test and shape_clashes(state, part[b : b + 1], c[b][None])[0]:
                    continue
                state.add(part[b : b + 1], c[b][None], horizon=False)
                budget -= 1
                added += 1
                break
    return added

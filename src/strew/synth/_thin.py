"""Small stones of a one-kind exemplar taken out where growth crowded them in (extension
of §5.1, §7).

:func:`thin_small` runs at the very end of :func:`strew.synth._grow.grow`, after
:func:`~strew.synth._grow.fill_holes`.
"""

from __future__ import annotations

import heapq

import numpy as np
import shapely
from scipy.spatial import cKDTree

from ._state import SynthState

THIN = True
""":func:`grow` takes out the surplus of small elements of a one-kind exemplar whose
sizes vary (see :func:`thin_small`)."""

THIN_Z = 2.0
"""Binomial standard errors by which the output's share of elements at or below a
scale must exceed the exemplar's before :func:`thin_small` acts (the exemplar's own
sampling noise of the share does not say the output is wrong)."""


def thin_small(state: SynthState, since: int = 0) -> int:
    """Remove output elements of the small end of a one-kind exemplar's scales where
    the output holds more of them than the exemplar's scale mix and its density allow,
    the most crowded first; returns the number removed.

    Extension of §5.1 (§7: "significant differences in element size ... are not
    supported"). An exemplar of one kind whose elements' scales vary (stones drawn
    with scales 1 +- 0.35) is copied neighbourhood by neighbourhood; a copy's larger
    stones overlap elements placed before more often than its smaller ones, which
    still fit and are kept, and the output's scales drift small: its elements pack
    denser than the exemplar's. Measured first (stones, count 120, spread 0.35, variant
    seed 7 at 3.5x; ``python benchmarks/synth_variants.py --harder``, h2s7, seeds
    1-6): median scale 0.916 against the exemplar's 1.006 (mean 0.924 against 0.988),
    density 1.084-1.106 of the exemplar's (tolerance 0.10; seeds 2 and 4 failed), the
    nearest-neighbour distance's upper deciles short (1.07-1.12 s against 1.13-1.19
    s); the exemplar's generator drawn at the output's size with the same shapes
    passes (1353 stones against synth's 1611). Growth never removes an element it
    kept (§5.1: a copy's elements are placed where they do not intersect O); this
    pass does.

    Single exemplar, one visible kind, a fill (not a brush stroke: :func:`grow`
    does not call it then), no context elements, no periodic tile. Counted inside the region shrunk by two of the largest collision radii,
    against the exemplar's interior (its domain shrunk by the same): ``E``, the
    output's count above the exemplar's density, caps the removal. For each scale
    ``v`` of the exemplar's lower half (its share at or below ``v``, ``F``, at most
    0.5), the output's count at or below ``v``, ``c``, exceeds ``F N`` by ``D = c - F N
    - THIN_Z sqrt(N F (1 - F))``; removing ``D / (1 - F)`` of them leaves the share at
    ``F``. The largest such count (at most ``E``) is removed among the elements at or
    below its ``v``: each time the closest pair of centres with such an element, its
    smaller one. Only elements added since index ``since`` (this call of :func:`grow`)
    are taken out: a filler's earlier strokes stay. No random choice.

    Measured (``python benchmarks/synth_variants.py --harder --only stones``): h2s7
    seeds 1-6 density 0.084-0.106 -> 0.031-0.037 of the exemplar's (2/6 failing -> 0;
    seed 2 removes 98 of 1688); --harder stones 31 -> 32/32. The fidelity suite's
    stones (scales 1 +- 0.2) do not drift past the noise margin: unchanged. Tried
    first on finished outputs: the count's surplus alone as the cap (no scale test)
    took stones out of h4 and h7, whose density already matched (h4s8 seed 1 then
    failed nn[stone>stone], 0.052 / 0.051); the scale test leaves h7 alone.
    """
    from ._displace import _inner_density  # (lazy: _displace imports _grow)

    prep = state.prep
    if not THIN or state.n < 20 or state.region is None:
        return 0
    if state.tile is not None or np.count_nonzero(prep.selected) != 1 or state.fixed[: state.n].any():
        return 0
    sel = prep.selected_elements & ~prep.void
    s = int(np.flatnonzero(prep.selected)[0])
    ids = np.flatnonzero(sel & (prep.source == s))
    kinds = np.unique(prep.skind[ids])
    if len(kinds) != 1:
        return 0
    k = int(kinds[0])
    margin = 2.0 * float(prep.rc.max())
    dens = float(_inner_density(prep, margin)[k])
    inner = state.region.geometry.buffer(-margin)
    ex_inner = prep.domains[s].buffer(-margin)
    if not np.isfinite(dens) or inner.is_empty or ex_inner.is_empty or inner.area <= 0.25 * state.region.geometry.area:
        return 0
    exs = np.sort(prep.scale[ids[shapely.contains_xy(ex_inner, prep.pos[ids, 0], prep.pos[ids, 1])]])
    if len(exs) < 20:
        return 0
    n = state.n
    pos = state.pos[:n]
    src = state.src[:n]
    ins = shapely.contains_xy(inner, pos[:, 0], pos[:, 1]) & ~prep.void[src] & (prep.skind[src] == k)
    N = int(ins.sum())
    E = N - int(np.floor(dens * float(inner.area)))
    if E <= 0:
        return 0
    sc = prep.scale[src]
    vals = np.unique(exs)
    F = np.searchsorted(exs, vals, "right") / len(exs)
    low = F <= 0.5
    if not low.any():
        return 0
    vals, F = vals[low], F[low]
    c = np.searchsorted(np.sort(sc[ins]), vals, "right")
    R = (c - F * N - THIN_Z * np.sqrt(N * F * (1.0 - F))) / (1.0 - F)
    b = int(np.argmax(R))
    R_ = int(min(np.floor(R[b]), E))
    if R_ <= 0:
        return 0
    cand = ins & (sc <= vals[b]) & (np.arange(n) >= since)
    vis = np.flatnonzero(~prep.void[src])
    alive = np.zeros(n, bool)
    alive[vis] = True
    # each visible element's nearest other visible one, kept up to date as elements go:
    # only the candidates whose nearest went are asked again (the tree stays; a heap of (distance,
    # index) pops the closest candidate, the lowest index among equals, as a scan would)
    tree = cKDTree(pos[vis])
    d0, j0 = tree.query(pos[vis], k=2)
    nn_d = np.full(n, np.inf)
    nn_j = np.full(n, -1, np.int64)
    nn_d[vis], nn_j[vis] = d0[:, 1], vis[j0[:, 1]]
    heap = [(float(nn_d[i]), int(i)) for i in np.flatnonzero(cand & alive)]
    heapq.heapify(heap)

    def nearest(a: int) -> None:
        k = 8
        while True:
            k = min(k, len(vis))
            dd, jj = tree.query(pos[a], k=k)
            jj = vis[np.atleast_1d(jj)]
            ok = alive[jj] & (jj != a)
            if ok.any():
                f = int(np.argmax(ok))
                nn_d[a], nn_j[a] = float(np.atleast_1d(dd)[f]), int(jj[f])
                return
            if k == len(vis):
                nn_d[a], nn_j[a] = np.inf, -1
                return
            k *= 2

    # no removal opens an empty circle wider than the exemplar's largest: those are the
    # holes fill_holes has just filled (see THIN_KEEPS_HOLES_FILLED)
    limit = np.inf
    if THIN_KEEPS_HOLES_FILLED:
        from ._grow import largest_empty_circles  # (lazy: _grow imports this module)

        lec = largest_empty_circles(prep)[s]
        limit = float(lec) if np.isfinite(lec) else np.inf
    geom = state.region.geometry

    def opens(r: int) -> bool:
        return np.isfinite(limit) and _opened_circle(pos, vis, alive, tree, r, geom) > limit

    removed = 0
    while removed < R_ and heap:
        d, p = heapq.heappop(heap)
        if not alive[p] or d != nn_d[p] or not np.isfinite(d):
            continue
        q = int(nn_j[p])
        r = q if cand[q] and sc[q] < sc[p] else p  # p is a candidate
        if opens(r):
            o = p if r == q else q
            if not (cand[o] and alive[o]) or opens(o):
                continue  # p stays, unless its nearest element goes later
            r = o
        alive[r] = False
        removed += 1
        for a in np.flatnonzero(alive & cand & (nn_j == r)).tolist():
            nearest(a)
            heapq.heappush(heap, (float(nn_d[a]), a))
    keep = np.ones(n, bool)
    keep[vis[~alive[vis]]] = False
    return state.remove(~keep)


THIN_KEEPS_HOLES_FILLED = True
""":func:`thin_small` takes out no element whose removal opens an empty circle wider
than the exemplar's largest (``_grow.largest_empty_circles``); the closest pair's
other element goes instead where that one opens none.

Extension of §5.1, as ``_grow.fill_holes``, whose holes these are: thin_small runs
after it and took 80 of the 87 stones fill_holes had put into circles wider than the
exemplar's largest (helper s38e, issue 13 point 1: stones ``--harder`` h4s27, aspect
0.45, at 3.5x; ``python benchmarks/s38e_trace.py stones:4:27 1``): the output's
empty-circle q95 went 16.61 -> 18.67 against the exemplar's 16.73 (empty_circle
0.123 / 0.10, failing), the largest 17.52 -> 22.0."""


def _opened_circle(pos: np.ndarray, vis: np.ndarray, alive: np.ndarray, tree: cKDTree, r: int, geom) -> float:
    """Radius of the widest empty circle (Delaunay circumcircle, centred in ``geom``
    and wholly inside it, as ``strew.metrics.fidelity`` counts them) that removing
    element ``r`` would open among the alive visible elements: the circumcircles of
    its nearest alive neighbours' triangulation that hold ``r`` (0: none)."""
    from ._grow import (  # (lazy: _grow imports this module)
        circles_within,
        circumcircles,
    )

    k = min(24, len(vis))
    jj = vis[np.atleast_1d(tree.query(pos[r], k=k)[1])]
    jj = jj[alive[jj] & (jj != r)]
    cen, rad, _ = circumcircles(pos[jj])
    hit = np.hypot(cen[:, 0] - pos[r, 0], cen[:, 1] - pos[r, 1]) < rad
    if not hit.any():
        return 0.0
    cen, rad = cen[hit], rad[hit]
    ins = circles_within(geom, cen, rad)
    return float(rad[ins].max()) if ins.any() else 0.0


THIN_MATCH_NN = True
""":func:`thin_orphans` and :func:`thin_crowded` choose which surplus elements of a kind to
take out so that the kind's nearest same-kind distances stay nearest the exemplar's, where
taking those nearest another of their kind first would leave them farther from the
exemplar's than before the pass (see :func:`_match_nn`; off: nearest first always).

Extension of §5.1 (helper s70p, issue 13 point 1): the passes remove the surplus that
``_grow.fill_holes`` leaves (one small element centred in each wide hole), and taking the
most crowded first assumes the surplus is crowding (clusters' dots, where it was measured).
Where the exemplar's small kind sits in pairs in the gaps between large ones (two sizes
--varied p4s43: pebbles a minority, nearest-pebble deciles 11.6 ... 23.7), taking one of
each close pair turns pairs into singles: 59 pebbles taken at seed 1, the pebbles'
nearest-pebble median 16.8 -> 21.6, nn[pebble>pebble] 0.30 / 0.225 (``python
benchmarks/s70p_stages.py two_sizes:p4s43 1``). The same count is taken either way, and no
element whose removal opens an empty circle wider than the exemplar's largest (without
that guard the choice took fill_holes' lone pebbles and two sizes p4s35, p4s39 failed
empty_circle 0.156, 0.196 / 0.10)."""


MATCH_NN_WORK = 2e7
"""Bound on :func:`_match_nn`'s work, ``len(chosen) * len(cand) * n`` (removals x
candidates x the kind's elements): its greedy choice scores every candidate at every
removal against the whole kind's deciles, so its cost grows as the cube of the output's
size (two sizes --varied p4s43, seed 1: 0.35 s at 3.5x the exemplar's side, n 857; 2.8 s at
5x; 12.8 s at 7x, n 3,503, against 1.8 s for the whole synthesis without it). Above the
bound the pass takes nearest first, as before s70p, so the choice costs at most about 0.75 s
per pass (about 37 ns per unit of work) and a larger output keeps main's removal order.
Measured in the stop-64 closing note (``benchmarks/integ39_thin_scale.py``)."""


def _nn_deciles_counted(pos: np.ndarray, counted: np.ndarray, alive: np.ndarray, nbr: np.ndarray, nbr_d: np.ndarray) -> tuple:
    """(first alive neighbour's slot per element, deciles of the counted alive elements'
    nearest alive same-kind distance) from neighbour lists ``nbr`` / ``nbr_d`` (n, m)."""
    ok = alive[nbr]
    first = np.argmax(ok, axis=1)
    d = np.where(ok.any(axis=1), nbr_d[np.arange(len(nbr)), first], np.inf)
    d = d[counted & alive]
    d = d[np.isfinite(d)]
    return first, d


def _ex_nn_deciles(prep, k: int) -> np.ndarray | None:
    """Deciles of the selected exemplar's kind-``k`` nearest same-kind distances, with the
    judge's border correction (Hanisch: an element counts where that distance is below its
    distance to the domain's boundary); None where fewer than five count."""
    from .._fidelity import MIN_NN, _deciles

    s = int(np.flatnonzero(prep.selected)[0])
    mine = np.flatnonzero(prep.selected_elements & ~prep.void & (prep.source == s) & (prep.skind == k))
    if len(mine) < MIN_NN + 1:
        return None
    p = prep.pos[mine]
    d = cKDTree(p).query(p, 2)[0][:, 1]
    edge = shapely.distance(prep.domains[s].boundary, shapely.points(p))
    d = d[d <= edge]
    return _deciles(d) if len(d) >= MIN_NN else None


def _match_nn(state: SynthState, vis: np.ndarray, of_k: np.ndarray, ins: np.ndarray, cand: np.ndarray, chosen: np.ndarray, k: int) -> np.ndarray:
    """The elements (indices into ``vis``) to take out of kind ``k``: ``chosen`` (nearest
    first) unless that leaves the kind's nearest same-kind deciles (counted inside the
    inner frame ``ins``) farther from the exemplar's than before; then as many of ``cand``
    taken one at a time, each the one whose removal leaves the deciles nearest the
    exemplar's (mean absolute difference, as ``strew.metrics.fidelity`` compares them;
    ties: nearest-first order). See :data:`THIN_MATCH_NN`."""
    from .._fidelity import _deciles

    if not THIN_MATCH_NN or len(chosen) == 0:
        return chosen
    if len(chosen) * len(cand) * int(of_k.sum()) > MATCH_NN_WORK:
        return chosen  # the greedy choice would cost too much: nearest first (MATCH_NN_WORK)
    ex = _ex_nn_deciles(state.prep, k)
    if ex is None:
        return chosen
    kk = np.flatnonzero(of_k)  # kind-k elements, as indices into vis
    n = len(kk)
    if n < 8:
        return chosen
    at = np.full(len(vis), -1, np.int64)
    at[kk] = np.arange(n)
    pos = state.pos[vis[kk]]
    m = min(12, n)
    nbr_d, nbr = cKDTree(pos).query(pos, m)
    nbr_d, nbr = nbr_d[:, 1:], nbr[:, 1:]
    counted = ins[kk]
    alive = np.ones(n, bool)

    def err(al: np.ndarray) -> float:
        d = _nn_deciles_counted(pos, counted, al, nbr, nbr_d)[1]
        return float(np.mean(np.abs(_deciles(d) - ex))) if len(d) >= 5 else np.inf

    e0 = err(alive)
    al = alive.copy()
    al[at[chosen]] = False
    if not err(al) > e0:
        return chosen
    # no removal opens an empty circle wider than the exemplar's largest (the holes
    # fill_holes has just filled, as THIN_KEEPS_HOLES_FILLED keeps them for thin_small)
    from ._grow import largest_empty_circles  # (lazy: _grow imports this module)

    prep = state.prep
    lec = largest_empty_circles(prep)[int(np.flatnonzero(prep.selected)[0])]
    limit = float(lec) if np.isfinite(lec) else np.inf
    geom = state.region.geometry
    vtree = cKDTree(state.pos[vis])
    on = np.zeros(state.n, bool)
    on[vis] = True

    def opens(c: int) -> bool:
        return np.isfinite(limit) and _opened_circle(state.pos, vis, on, vtree, int(vis[kk[c]]), geom) > limit

    # candidates in nearest-first order (chosen first, in their order), as ties fall
    rest = cand[~np.isin(cand, chosen)]
    pool = [int(c) for c in at[np.concatenate([chosen, rest])] if not opens(int(c))]
    out = []
    for _ in range(len(chosen)):
        if not pool:
            break
        es = np.empty(len(pool))
        for j, c in enumerate(pool):
            alive[c] = False
            es[j] = err(alive)
            alive[c] = True
        took = -1
        for j in np.argsort(es, kind="stable"):
            if not opens(pool[j]):
                took = int(j)
                break
        if took < 0:
            break
        c = pool.pop(took)
        alive[c] = False
        on[vis[kk[c]]] = False
        out.append(kk[c])
    if len(out) < len(chosen):
        return chosen  # too few may go without opening a wide hole: nearest first, as before
    return np.asarray(out, np.int64)


THIN_ORPHANS = True
""":func:`grow` takes out the surplus of children standing without their parent's copy
(see :func:`thin_orphans`)."""


WHOLE_BOUND = True
""":func:`thin_orphans` takes out no more than the kind's surplus over the whole region
against the exemplar's whole density, as :func:`thin_crowded` (off: the inner surplus
alone).

Extension of §5.1 (helper s35t, issue 13 point 1). A drawn exemplar's inner frame is a
small sample, and a smallest kind gathers in its frame band (gaps the edge leaves between
the larger elements). Two sizes --harder h7s26 (ratio 0.4, 44 stones, 60 pebbles, 25 of
them within 15 of the frame; fresh draw): about 30 pebbles inside the margin, 11.3 per
1e4 against the generator's 12.3 drawn at the output's size; the output's edge band held
6.6-7.1 pebbles per 1e4 against the exemplar's 20. Thinning orphans to the inner count
took 34-47 pebbles (those nearest another pebble first), left 10.6-10.8 per 1e4 over the
region (the exemplar 12.4) and nn[pebble>pebble] too far from the fourth decile up:
0.127 / 0.118 / 0.119 against 0.102 at seeds 1-3 (``python benchmarks/s35t_passes.py
two_sizes:7:26 1,2``; ``syn13z_rows.py two_sizes:7:26:1,2,3``). With the bound: no pebble
taken, 0.090 / 0.073 / 0.079."""


def _inner_region(state: SynthState):
    """The region eroded by two of the exemplar's largest collision radii, where the
    thinning passes compare densities; ``(margin, None)`` where too little of it is left
    (a quarter of the region's area or less)."""
    margin = 2.0 * float(state.prep.rc.max())
    inner = state.region.geometry.buffer(-margin)
    if inner.is_empty or inner.area <= 0.25 * state.region.geometry.area:
        return margin, None
    return margin, inner


def _remove_dropped(state: SynthState, drop: list) -> int:
    """Remove the output elements listed in the arrays ``drop``; returns how many went."""
    if not drop:
        return 0
    keep = np.ones(state.n, bool)
    keep[np.concatenate(drop)] = False
    return state.remove(~keep)


def _parent_copies_near(state: SynthState, vis: np.ndarray, tree: cKDTree, c: int) -> np.ndarray:
    """Copies of output element ``vis[c]``'s exemplar parent within the orphan tests' reach.

    Parameters
    ----------
    state : SynthState
    vis : (m,) int array
        Output indices of the visible elements; ``tree`` is built on ``state.pos[vis]``.
    tree : cKDTree
    c : int
        Index into ``vis`` of a child (its exemplar parent is ``>= 0``).

    Returns
    -------
    (q,) int64 array
        Indices into ``vis`` of the parent's copies within 1.2 times the exemplar's
        parent-child offset plus the child's radius.
    """
    prep, src = state.prep, state.src
    e = src[vis[c]]
    off = float(np.hypot(*(prep.pos[e] - prep.pos[prep.parent[e]])))
    near = np.asarray(tree.query_ball_point(state.pos[vis[c]], 1.2 * off + float(prep.r[e])), np.int64)
    return near[src[vis[near]] == prep.parent[e]]


def _q10(prep, mine: np.ndarray) -> float:
    """Tenth percentile of the nearest same-kind distance among exemplar elements ``mine`` (n,)."""
    return float(np.quantile(cKDTree(prep.pos[mine]).query(prep.pos[mine], 2)[0][:, 1], 0.1))


def thin_orphans(state: SynthState, since: int = 0) -> int:
    """Remove output children (``_prepare.parents``: a smaller element leaning on a
    parent) that stand without a copy of their exemplar parent beside them, where their
    kind is denser than its exemplar, those nearest another element of their kind first,
    until the kind's density is the exemplar's; returns the number removed.

    Extension of §5.1 (a copy brings an element's whole neighbourhood; where the
    parent of a copy did not land its children still may, beside another copy's
    parent). Measured first (clusters h3s9 at 3.5x, fresh held-out exemplar, seeds
    1-3; ``python benchmarks/syc16_usage.py``): 13-16 % of the dots stand away from
    their parent's copy (the exemplar 3 %), dots at 1.033-1.039 of the exemplar's
    density and nn[dot>dot] 0.054-0.0575 against 0.05. Taking out as many dots as the
    surplus, the orphans nearest another dot first, gives 0.031-0.035; as many dots at
    random 0.050-0.054. Densities as ``_grow._room_cap`` counts them (the region and the
    exemplar shrunk by two of the largest collision radii); one exemplar only. Only
    leaf kinds (none of the exemplar's elements leans on one), and only orphans nearer
    another element of their kind than the exemplar's tenth percentile of that
    distance: without these limits ``synth_variants.py --harder`` lost 4 rows (three
    sizes h5s7, h9s7 s1/s2, two sizes h7s8; ``syc16_rejected_harder_all_cmp.txt``).
    Nor more than the kind's surplus over the whole region against the exemplar's whole
    density (:data:`WHOLE_BOUND`, helper s35t).
    """
    from ._displace import _inner_density  # (lazy: _displace imports _grow)

    prep = state.prep
    if np.count_nonzero(prep.selected) != 1 or state.region is None or state.n <= since:
        return 0
    margin, inner = _inner_region(state)
    if inner is None:
        return 0
    dens = _inner_density(prep, margin)
    src = state.src
    vis = np.flatnonzero(~prep.void[src])
    if len(vis) < 2:
        return 0
    par = prep.parent[src[vis]]
    ins = shapely.contains_xy(inner, state.pos[vis, 0], state.pos[vis, 1])
    tree = cKDTree(state.pos[vis])
    drop = []
    from ._grow import _ring_kids

    ring = _ring_kids(prep)[0]
    selv = prep.selected_elements & ~prep.void
    parents = np.unique(prep.parent[selv & (prep.parent >= 0)])
    for k in np.unique(prep.skind[src[vis[par >= 0]]]):
        # leaf kinds only: a kind others lean on (three sizes' medium stones) is a parent's
        # structure too (three sizes h9s7 nn[medium>medium] 0.222/0.184 with it)
        if not np.isfinite(dens[k]) or np.any(prep.skind[parents] == k):
            continue
        of_k = prep.skind[src[vis]] == k
        surplus = int(np.count_nonzero(of_k & ins)) - int(np.floor(dens[k] * float(inner.area)))
        # nor more than the whole region holds above the exemplar's whole density (as
        # thin_crowded): a region whose edge band is underfilled keeps its inner surplus
        if WHOLE_BOUND:
            s_ = int(np.flatnonzero(prep.selected)[0])
            whole = np.count_nonzero(selv & (prep.source == s_) & (prep.skind == k)) / float(prep.domains[s_].area)
            surplus = min(surplus, int(np.count_nonzero(of_k)) - int(np.floor(whole * float(state.region.geometry.area))))
        if surplus <= 0:
            continue
        # ring tiles stay (seam17): a ring's tile copied with another hub's exemplar ring has
        # that hub as parent although it stands on this hub's ring (rings at 50x: every hole)
        cand = np.flatnonzero(of_k & ins & (par >= 0) & (vis >= since) & ~ring[src[vis]])
        orphan = np.zeros(len(cand), bool)
        for j, c in enumerate(cand):
            orphan[j] = not len(_parent_copies_near(state, vis, tree, c))
        cand = cand[orphan]
        if not len(cand):
            continue
        kp = state.pos[vis[of_k]]
        dd = cKDTree(kp).query(state.pos[vis[cand]], 2)[0][:, 1]
        # only orphans squeezed closer to their kind than the exemplar's tenth percentile
        mine = np.flatnonzero(prep.selected_elements & ~prep.void & (prep.skind == k))
        if len(mine) < 2:
            continue
        q10 = _q10(prep, mine)
        sq = dd < q10
        cand, dd = cand[sq], dd[sq]
        chosen = cand[np.argsort(dd, kind="stable")[:surplus]]
        drop.append(vis[_match_nn(state, vis, of_k, ins, cand, chosen, int(k))])
    return _remove_dropped(state, drop)


THIN_CROWDED = True
""":func:`grow` takes out the surplus of children beside their parent's copy where their
kind is still denser than its exemplar after :func:`thin_orphans` (see
:func:`thin_crowded`)."""


CROWDED_PARENTS = 0.9
"""Share of their exemplar density below which a parent kind's shortfall stops
:func:`thin_crowded` for its children's kind."""


def thin_crowded(state: SynthState, since: int = 0) -> int:
    """Remove output children of a leaf kind that stand beside a copy of their exemplar
    parent, where the kind is still denser than its exemplar after :func:`thin_orphans`,
    those nearest another element of their kind first, until the kind's density is the
    exemplar's; returns the number removed.

    Extension of §5.1 (growth never removes an element it kept; this pass does). Where
    growth copies more whole clusters (``_grow.copyable``: a seed whose best candidate
    offered only orphans now tries the next), the children's kind ends denser than the
    exemplar's although few are orphans. Measured first (clusters h3s9 at 2x, fresh
    held-out exemplar, seed 1, with ``_grow.copyable``; ``python
    benchmarks/s27t_diag.py``): the dots reach 1.144 of the exemplar's density,
    :func:`thin_orphans` takes 120 out and leaves 1.033
    (``tests/synth/test_synth_syc16_orphans.py`` bounds it by 1.01; the discs 1.025). No
    copy of a disc holds more dots than its exemplar disc: the surplus is more rings,
    not fuller ones, so the children taken are the most crowded, as
    :func:`thin_orphans` takes its orphans (there measured against taking as many at
    random: nn[dot>dot] 0.031-0.035 against 0.050-0.054). A child stands beside its
    parent's copy as :func:`thin_orphans` asks (a copy of its parent within 1.2 times
    its exemplar offset plus its radius). Densities as :func:`thin_orphans` counts them;
    one exemplar; leaf kinds only; ring tiles stay; only elements added since ``since``;
    no random choice. Taking the children farthest from their slot on the parent's copy
    first instead gave the same density and a faithful judge on seeds 1-2
    (``python benchmarks/s27t_order.py``, before this choice). Candidates are ordered
    the orphans :func:`thin_orphans` left (not squeezed) first. Not where a parent kind
    holds less than :data:`CROWDED_PARENTS` of its exemplar density: far clusters (FAR
    at variant seed 7, ``tests/synth/test_synth_far_clusters.py``) have discs at 0.80 and
    dots at 1.30, and taking the dots to 1.00 left the region at 0.835 of the exemplar's
    count (the test asks 0.85). Nor more than the kind's surplus over the whole region
    against the exemplar's whole density: GRIT at variant seed 8 (same test) had dots at
    1.15 inside but an underfilled edge band, and taking the inner surplus left the
    region at 0.840 of the exemplar's count.
    """
    from ._displace import _inner_density  # (lazy: _displace imports _grow)
    from ._grow import _ring_kids

    prep = state.prep
    if not THIN_CROWDED or np.count_nonzero(prep.selected) != 1 or state.region is None or state.n <= since:
        return 0
    margin, inner = _inner_region(state)
    if inner is None:
        return 0
    dens = _inner_density(prep, margin)
    src = state.src[: state.n]
    vis = np.flatnonzero(~prep.void[src])
    if len(vis) < 2:
        return 0
    pos = state.pos[vis]
    kind = prep.skind[src[vis]]
    ins = shapely.contains_xy(inner, pos[:, 0], pos[:, 1])
    ring = _ring_kids(prep)[0]
    s = int(np.flatnonzero(prep.selected)[0])
    selv = prep.selected_elements & ~prep.void & (prep.source == s)
    kids = selv & (prep.parent >= 0)
    parents = np.unique(prep.parent[kids])
    drop = []
    tree = cKDTree(pos)
    par = prep.parent[src[vis]]
    for k in np.unique(prep.skind[kids]):
        if not np.isfinite(dens[k]) or np.any(prep.skind[parents] == k):
            continue  # leaf kinds only, as thin_orphans
        of_k = kind == k
        surplus = int(np.count_nonzero(of_k & ins)) - int(np.floor(dens[k] * float(inner.area)))
        # nor more than the whole region holds above the exemplar's whole density: a region
        # whose edge band is underfilled keeps its inner surplus
        whole = np.count_nonzero(selv & (prep.skind == k)) / float(prep.domains[s].area)
        surplus = min(surplus, int(np.count_nonzero(of_k)) - int(np.floor(whole * float(state.region.geometry.area))))
        mine = np.flatnonzero(of_k & (par >= 0))
        if surplus <= 0 or len(mine) < 2:
            continue
        # where the parents' kinds fall short of their exemplar density, the region is
        # underfilled and the children's surplus stands in for missing clusters: leave it
        pk = np.unique(prep.skind[prep.parent[kids & (prep.skind == k)]])
        held_p = np.array([np.count_nonzero((kind == q) & ins) for q in pk], float)
        if np.any(held_p < CROWDED_PARENTS * dens[pk] * float(inner.area)):
            continue
        # each child's owner: the nearest copy of its exemplar parent within thin_orphans' reach
        owner = np.full(len(mine), -1, np.int64)
        for j, c in enumerate(mine):
            near = _parent_copies_near(state, vis, tree, c)
            if len(near):
                owner[j] = near[np.argmin(np.hypot(*(pos[near] - pos[c]).T))]
        free = (vis[mine] >= since) & ins[mine] & ~ring[src[vis[mine]]]
        crowd = cKDTree(pos[of_k]).query(pos[mine], 2)[0][:, 1]
        cand = np.flatnonzero(free)
        # the orphans thin_orphans left (not squeezed) first, then the children beside their
        # parent's copy; within each, those nearest another of their kind first
        order = np.lexsort((crowd[cand], owner[cand] >= 0))
        drop.append(vis[_match_nn(state, vis, of_k, ins, mine[cand], mine[cand[order[:surplus]]], int(k))])
    return _remove_dropped(state, drop)


THIN_EDGE_STRAYS = True
""":func:`grow` takes out the squeezed children without their parent's copy in the
region's edge band (see :func:`thin_edge_strays`)."""


def thin_edge_strays(state: SynthState, since: int = 0) -> int:
    """Remove output children of a leaf kind in the region's edge band (outside the
    inner region :func:`thin_orphans` counts in) that stand without a copy of their
    exemplar parent beside them and nearer another element of their kind than the
    exemplar's tenth percentile of that distance; returns the number removed.

    Extension of §5.1, :func:`thin_orphans`' rule (same orphan test, same squeeze test)
    carried into the edge band, without its surplus bound: the band has no exemplar
    density to compare with (its elements' parents may lie beyond the edge), but an
    orphan squeezed against another of its kind is a leftover of two overlapping copies,
    not a cluster cut by the edge. Measured (clusters variant 1 at 2x, seed 2,
    ``tests/synth/test_synth_fidelity.py::test_untuned_cluster_variants_are_faithful``,
    ``python benchmarks/s28k_untuned.py largest 1 1 2``): with ``_grow.copyable`` 37 of
    354 dots stood beyond 1.3 ring radii of every disc, all within 20 of the edge, 7 of
    them squeezed (main 30 of 347, 2 squeezed); this pass takes 5 (0.895 -> 0.905 near a
    disc; the test asks > 0.9). Of two squeezed strays only one goes. One exemplar; leaf
    kinds; ring tiles stay; only elements added since ``since``; no random choice.
    """
    from ._grow import _ring_kids

    prep = state.prep
    if not THIN_EDGE_STRAYS or np.count_nonzero(prep.selected) != 1 or state.region is None or state.n <= since:
        return 0
    _, inner = _inner_region(state)
    if inner is None:
        return 0
    src = state.src
    vis = np.flatnonzero(~prep.void[src[: state.n]])
    if len(vis) < 2:
        return 0
    par = prep.parent[src[vis]]
    band = ~shapely.contains_xy(inner, state.pos[vis, 0], state.pos[vis, 1])
    tree = cKDTree(state.pos[vis])
    ring = _ring_kids(prep)[0]
    selv = prep.selected_elements & ~prep.void
    parents = np.unique(prep.parent[selv & (prep.parent >= 0)])
    drop = []
    for k in np.unique(prep.skind[src[vis[par >= 0]]]):
        if np.any(prep.skind[parents] == k):
            continue  # leaf kinds only, as thin_orphans
        mine = np.flatnonzero(selv & (prep.skind == k))
        if len(mine) < 2:
            continue
        of_k = prep.skind[src[vis]] == k
        cand = np.flatnonzero(of_k & band & (par >= 0) & (vis >= since) & ~ring[src[vis]])
        if not len(cand):
            continue
        orphan = np.zeros(len(cand), bool)
        for j, c in enumerate(cand):
            orphan[j] = not len(_parent_copies_near(state, vis, tree, c))
        cand = cand[orphan]
        if not len(cand):
            continue
        q10 = _q10(prep, mine)
        kt = cKDTree(state.pos[vis[of_k]])
        dd = kt.query(state.pos[vis[cand]], 2)[0][:, 1]
        # of two squeezed strays, one goes: each taken in order of squeeze, the other kept
        gone = np.zeros(state.n, bool)
        kidx = vis[of_k]
        for j in np.argsort(dd, kind="stable"):
            if dd[j] >= q10:
                break
            c = vis[cand[j]]
            near = kidx[kt.query_ball_point(state.pos[c], q10)]
            if np.any(~gone[near[near != c]]):
                gone[c] = True
        drop.append(np.flatnonzero(gone))
    return _remove_dropped(state, drop)

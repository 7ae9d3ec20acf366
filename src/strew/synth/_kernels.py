"""Numba kernels of Davison et al.'s synthesis: pairing, matching, generation, constraints.

Everything here works on plain arrays. Neighbourhoods are stored CSR-style: for the
neighbourhood of element ``i``, rows ``ptr[i]:ptr[i + 1]`` of ``off`` (offsets
``p_j - p_i``), ``kind`` and ``d`` (pairing thresholds ``d_j = 2 r_j``), sorted by
distance from ``p_i`` (§4: "we sort elements in the output neighbourhood by distance").
"""

from __future__ import annotations

import numba
import numpy as np

# the uniform bucket grid over points is the shared one (issue 15 point 5)
from .._kernels.geometry import seg_dist2 as _seg_dist2
from .._kernels.geometry import seg_hit as _seg_hit
from .._kernels.grid import bucket_grid as _bucket_grid

__all__ = [
    "map_offset",
    "pair_cost",
    "sort_segments",
    "candidate_costs",
    "generate_proposals",
    "place_proposals",
    "best_matches",
    "greedy_separated",
]

INF = np.inf
SIZE_STEP = 2.0  # bounding radii this many times apart are of different sizes (see _prepare.size_classes)


@numba.njit(cache=True, nogil=True)
def map_offset(px: float, py: float, ox: float, oy: float) -> tuple[float, float]:
    """m_p (§5.1, Eq. 3): map an example-space offset to output space at ``p``.

    In the plane this is the identity; a surface (§5.7) would walk the orientation
    field from ``p`` here. Every placement, free-space point and prediction goes
    through this one function.
    """
    return ox, oy


@numba.njit(cache=True, nogil=True)
def pair_cost(o_off, o_kind, o_d, e_off, e_kind, e_d, kind_cost, rim, pair_out, used, elen, bound=INF):
    """Neighbourhood distance |n(o) - n(e)| of Eq. 1 with greedy pair assignment (§4).

    Parameters
    ----------
    o_off : (m, 2) float
        Output neighbourhood offsets ``p_o' - p_o``, sorted by length.
    o_kind : (m,) int
    o_d : (m,) float
        Pairing thresholds ``d_o' = 2 r_o'``.
    e_off : (q, 2) float
        Exemplar neighbourhood offsets ``p_e' - p_e``, sorted by length (as every
        neighbourhood of :class:`Prepared` is): an output neighbour at distance ``l``
        can only pair with exemplar neighbours whose length is within ``d`` of ``l``,
        so only that band is scanned (found by bisection).
    e_kind : (q,) int
    e_d : (q,) float
    kind_cost : float
        Attribute mismatch cost omega, in units of ``d_o'^2``.
    rim : float
        Neighbourhood radius r-bar of the output element. Exemplar neighbourhoods reach a
        little further (by the largest pairing threshold); a right-partial pair counts
        only when its element lies at least ``d_e' / 2`` inside ``rim``, so that elements
        on the rim of the neighbourhood do not flip the distance.
    pair_out : (m,) int, output
        Index into the exemplar neighbourhood of each output neighbour's pair, or -1 for
        a left-partial pair (o', 0).
    used : (q,) bool, output
        True for exemplar neighbours in a full pair; the others are the right-partial
        pairs (0, e').
    elen : (q,) float, scratch
        Lengths of ``e_off`` (overwritten).
    bound : float
        Stop early, returning inf, once the cost reaches ``bound`` (every term is
        non-negative, so the full cost would too); the pairs are then incomplete. A
        search for the best of several candidates passes the best cost so far.

    Returns
    -------
    float
        Sum over full pairs of ``|dp|^2 + omega``, plus ``d^2`` per partial pair.
    """
    q = e_off.shape[0]
    for j in range(q):
        elen[j] = np.sqrt(e_off[j, 0] * e_off[j, 0] + e_off[j, 1] * e_off[j, 1])
    return _pair_cost_lengths(o_off, o_kind, o_d, e_off, e_kind, e_d, kind_cost, rim, pair_out, used, elen, bound)


@numba.njit(cache=True, nogil=True)
def _segment_lengths(off):
    """(N,) float: the length of each offset row, as :func:`pair_cost` computes it."""
    out = np.empty(off.shape[0])
    for j in range(off.shape[0]):
        out[j] = np.sqrt(off[j, 0] * off[j, 0] + off[j, 1] * off[j, 1])
    return out


@numba.njit(cache=True, nogil=True)
def _pair_cost_lengths(o_off, o_kind, o_d, e_off, e_kind, e_d, kind_cost, rim, pair_out, used, elen, bound):
    """:func:`pair_cost` with the lengths of ``e_off`` given in ``elen`` (read only):
    a search over many candidates computes them once per exemplar neighbourhood, not
    once per (query, candidate) (helper s34v)."""
    m = o_off.shape[0]
    q = e_off.shape[0]
    for j in range(q):
        used[j] = False
    cost = 0.0
    for i in range(m):
        dd = o_d[i] * o_d[i]
        best = -1
        bestc = INF
        ox = o_off[i, 0]
        oy = o_off[i, 1]
        ol = np.sqrt(ox * ox + oy * oy)
        # band of exemplar neighbours that can lie within d: | |o| - |e| | <= |o - e| <= d
        lo = ol - o_d[i] - 1e-9 * (1.0 + ol)
        hi = ol + o_d[i] + 1e-9 * (1.0 + ol)
        j0 = 0
        j1 = q
        while j0 < j1:  # first j with elen[j] >= lo
            mid = (j0 + j1) // 2
            if elen[mid] < lo:
                j0 = mid + 1
            else:
                j1 = mid
        for j in range(j0, q):
            if elen[j] > hi:
                break
            if used[j]:
                continue
            dx = ox - e_off[j, 0]
            dy = oy - e_off[j, 1]
            r2 = dx * dx + dy * dy
            if r2 > dd:  # too far apart: not paired (§4)
                continue
            c = r2
            if o_kind[i] != e_kind[j]:
                c += kind_cost * dd  # omega(o', e')
            if c < bestc:
                bestc = c
                best = j
        pair_out[i] = best
        if best >= 0:
            used[best] = True
            cost += bestc
        else:
            cost += dd  # left-partial pair (o', 0)
        if cost >= bound:
            return INF  # cannot beat the bound
    for j in range(q):
        if not used[j]:
            lim = rim - 0.5 * e_d[j]
            if lim > 0 and e_off[j, 0] * e_off[j, 0] + e_off[j, 1] * e_off[j, 1] <= lim * lim:
                cost += e_d[j] * e_d[j]  # right-partial pair (0, e')
    return cost


@numba.njit(cache=True, nogil=True)
def sort_segments(ptr, idx, off):
    """Sort each CSR segment in place by offset length (ascending)."""
    n = ptr.shape[0] - 1
    for i in range(n):
        a = ptr[i]
        b = ptr[i + 1]
        if b - a < 2:
            continue
        # a loop, not the array expression ``off[a:b, 0] ** 2 + off[a:b, 1] ** 2``: the
        # same values, without the ufunc kernel numba would compile for it (issue 16)
        r2 = np.empty(b - a)
        for k in range(b - a):
            r2[k] = off[a + k, 0] * off[a + k, 0] + off[a + k, 1] * off[a + k, 1]
        order = np.argsort(r2, kind="mergesort")
        # gather by loops: numba compiles fancy indexing (``idx[a:b][order]``) about 10x
        # slower (issue 16: this kernel took 17 s to compile, 1.5 s written this way)
        tmp_idx = idx[a:b].copy()
        tmp_off = off[a:b].copy()
        for k in range(b - a):
            o = order[k]
            idx[a + k] = tmp_idx[o]
            off[a + k, 0] = tmp_off[o, 0]
            off[a + k, 1] = tmp_off[o, 1]


@numba.njit(cache=True, nogil=True)
def _vmax(a):
    """``a.max()`` of a non-empty 1-d array as a loop (NaN if it holds one, as numpy):
    numba compiles ``ndarray.max`` through ``np.nditer`` and ``take``, seconds of a first
    run (issue 16)."""
    m = a[0]
    for i in range(a.shape[0]):
        v = a[i]
        if np.isnan(v):
            return v
        if v > m:
            m = v
    return m


@numba.njit(cache=True, nogil=True)
def _pairing_scratch(q_ptr, e_ptr):
    """Scratch arrays for :func:`pair_cost` over CSR neighbourhoods: pair, used, elen."""
    maxq = 1
    for c in range(e_ptr.shape[0] - 1):
        maxq = max(maxq, e_ptr[c + 1] - e_ptr[c])
    maxm = 1
    for i in range(q_ptr.shape[0] - 1):
        maxm = max(maxm, q_ptr[i + 1] - q_ptr[i])
    return np.empty(maxm, np.int64), np.empty(maxq, np.bool_), np.empty(maxq)


@numba.njit(cache=True, nogil=True)
def _center_cost(ko, ke, d, kind_cost):
    return kind_cost * d * d if ko != ke else 0.0


@numba.njit(cache=True, nogil=True)
def _inside_convex(hp, nh, x, y):
    for t in range(nh):
        if hp[t, 0] * x + hp[t, 1] * y > hp[t, 2]:
            return False
    return True


@numba.njit(cache=True, nogil=True)
def candidate_costs_in_domain(q_ptr, q_off, q_kind, q_d, q_rbar, q_center_kind, q_center_d, q_pos, q_src, hp, hp_n, cands, e_ptr, e_off, e_kind, e_d, ex_kind, kind_cost):
    """Like :func:`candidate_costs` between exemplar neighbourhoods, where a right-partial
    pair only counts when its element would fall inside the query's own exemplar domain
    (a convex polygon given as half-planes ``a x + b y <= c``).

    Used for the k-coherence sets: an element near the edge of its exemplar lacks
    neighbours beyond the edge, which must not count against interior candidates.
    """
    nq, k = cands.shape
    out = np.full((nq, k), INF)
    pair, used, _ = _pairing_scratch(q_ptr, e_ptr)
    elen_all = _segment_lengths(e_off)  # once, not per (query, candidate) (helper s34v)
    for i in range(nq):
        a, b = q_ptr[i], q_ptr[i + 1]
        s = q_src[i]
        for j in range(k):
            c = cands[i, j]
            if c < 0:
                continue
            ea, eb = e_ptr[c], e_ptr[c + 1]
            cost = _pair_cost_lengths(q_off[a:b], q_kind[a:b], q_d[a:b], e_off[ea:eb], e_kind[ea:eb], e_d[ea:eb], kind_cost, q_rbar[i], pair, used, elen_all[ea:eb], INF)
            for t in range(eb - ea):
                if not used[t] and not _inside_convex(hp[s], hp_n[s], q_pos[i, 0] + e_off[ea + t, 0], q_pos[i, 1] + e_off[ea + t, 1]):
                    cost -= e_d[ea + t] * e_d[ea + t]
            out[i, j] = cost + _center_cost(q_center_kind[i], ex_kind[c], q_center_d[i], kind_cost)
    return out


@numba.njit(cache=True, nogil=True)
def candidate_costs(q_ptr, q_off, q_kind, q_d, q_rbar, q_center_kind, q_center_d, cands, e_ptr, e_off, e_kind, e_d, ex_kind, kind_cost):
    """|n(q) - n(c)| for every query neighbourhood ``q`` and each of its candidates.

    Parameters
    ----------
    q_ptr, q_off, q_kind, q_d : CSR neighbourhoods of the queries (output elements).
    q_rbar : (nq,) float
        Neighbourhood radius of each query.
    q_center_kind : (nq,) int
    q_center_d : (nq,) float
    cands : (nq, k) int
        Candidate exemplar elements (-1 for none).
    e_ptr, e_off, e_kind, e_d : CSR exemplar neighbourhoods.
    ex_kind : (n_ex,) int

    Returns
    -------
    (nq, k) float
        Costs (inf where there is no candidate).
    """
    nq, k = cands.shape
    out = np.full((nq, k), INF)
    pair, used, elen = _pairing_scratch(q_ptr, e_ptr)
    for i in range(nq):
        a, b = q_ptr[i], q_ptr[i + 1]
        for j in range(k):
            c = cands[i, j]
            if c < 0:
                continue
            ea, eb = e_ptr[c], e_ptr[c + 1]
            cost = pair_cost(q_off[a:b], q_kind[a:b], q_d[a:b], e_off[ea:eb], e_kind[ea:eb], e_d[ea:eb], kind_cost, q_rbar[i], pair, used, elen, INF)
            out[i, j] = cost + _center_cost(q_center_kind[i], ex_kind[c], q_center_d[i], kind_cost)
    return out


@numba.njit(cache=True, nogil=True)
def generate_proposals(seed_pos, q_ptr, q_off, q_kind, q_d, q_rbar, cands, e_ptr, e_idx, e_off, e_kind, e_d, kind_cost, out_ptr, parent, follow, anchored):
    """Right-partial pairs of each (seed, candidate), mapped to output space (§5.1).

    The new position of a copied element is ``p_s + m_{p_s}(p_{e'} - p_c)``.

    Parameters
    ----------
    seed_pos : (ns, 2) float
    q_* : CSR output neighbourhoods of the seeds.
    cands : (ns, k) int
    e_ptr, e_idx, e_off, e_kind, e_d : CSR exemplar neighbourhoods (``e_idx`` holds
        the exemplar index of each neighbour).
    out_ptr : (ns * k + 1,) int
        Upper-bound offsets (cumulative neighbourhood sizes of the candidates).
    parent : (n_ex,) int
        The larger element each exemplar element leans on (-1 for none, -3 for one
        beyond the exemplar's edge: never copied beside a candidate; see
        ``Prepared.parent``).
    follow : (n_ex,) bool
        Elements whose only larger Delaunay neighbour is their parent (a dot ringing
        its disc): placed from the output element paired with the parent.
    anchored : (n_ex,) bool
        Elements whose parent is an anchor of their own size class (a ring's tile on its
        hub, see ``_prepare.parents``): not copied when the output element paired with
        the parent is of another kind.

    Returns
    -------
    count : (ns * k,) int
        Number of proposals written for each (seed, candidate) from ``out_ptr``.
    ex : (P,) int
        Exemplar element to copy.
    pos : (P, 2) float
        Its output position.
    pslot : (P,) int
        The proposal of the element's parent, copied in the same copy (it must be
        placed first); -1 when the parent is the candidate itself, paired with an
        output element, or there is none; -2 when the parent lies outside ``n(c)``
        (the element would be copied without it: an orphan).
    """
    ns, k = cands.shape
    total = out_ptr[-1]
    ex = np.full(total, -1, np.int64)
    pos = np.zeros((total, 2))
    pslot = np.full(total, -1, np.int64)
    count = np.zeros(ns * k, np.int64)
    pair, used, elen = _pairing_scratch(q_ptr, e_ptr)
    slot = np.empty(elen.shape[0], np.int64)
    partner_d = np.empty(elen.shape[0])
    partner_off = np.empty((elen.shape[0], 2))
    partner_kind = np.empty(elen.shape[0], np.int64)
    for i in range(ns):
        a, b = q_ptr[i], q_ptr[i + 1]
        px, py = seed_pos[i, 0], seed_pos[i, 1]
        for j in range(k):
            c = cands[i, j]
            if c < 0:
                continue
            ea, eb = e_ptr[c], e_ptr[c + 1]
            pair_cost(q_off[a:b], q_kind[a:b], q_d[a:b], e_off[ea:eb], e_kind[ea:eb], e_d[ea:eb], kind_cost, q_rbar[i], pair, used, elen, INF)
            for u in range(b - a):
                if pair[u] >= 0:
                    partner_d[pair[u]] = q_d[a + u]
                    partner_kind[pair[u]] = q_kind[a + u]
                    partner_off[pair[u], 0] = q_off[a + u, 0]
                    partner_off[pair[u], 1] = q_off[a + u, 1]
            w = out_ptr[i * k + j]
            n = 0
            for t in range(eb - ea):
                if used[t]:
                    slot[t] = -1
                    continue
                mx, my = map_offset(px, py, e_off[ea + t, 0], e_off[ea + t, 1])
                ex[w + n] = e_idx[ea + t]
                pos[w + n, 0] = px + mx
                pos[w + n, 1] = py + my
                slot[t] = w + n
                n += 1
            for t in range(eb - ea):
                if used[t]:
                    continue
                par = parent[e_idx[ea + t]]
                if par == -1 or par == c:
                    continue
                ps = -2  # also for par == -3: the parent may lie beyond the exemplar's edge
                for u in range(eb - ea):
                    if e_idx[ea + u] == par:
                        ps = slot[u]
                        # A parent paired with a smaller output element (a dot where
                        # the exemplar has the disc it rings: Eq. 1 pairs across kinds
                        # at the cost omega) is not there: the child would be an orphan.
                        # Clusters variant 1 had 838 of 2049 dots without a disc (dots
                        # 1.7x too dense) before this test.
                        if used[u]:
                            if partner_d[u] * SIZE_STEP < e_d[ea + u] * (1.0 - 1e-9):
                                ps = -2
                            elif anchored[e_idx[ea + t]] and partner_kind[u] != e_kind[ea + u]:
                                # Likewise a parent of its own size class (an anchor: a
                                # ring's hub, see _prepare.parents) paired with an output
                                # element of another kind (a tile where the hub belongs):
                                # tiles placed from it formed hubless rings (rings at 50x:
                                # 34 of 143 local windows failing on empty circles).
                                ps = -2
                            elif follow[e_idx[ea + t]]:
                                # The child leans on the output element that stands for
                                # its parent (paired up to d = 2 r away): placed at the
                                # exemplar's offset from it, not from the seed, so a dot
                                # keeps its distance to the disc it rings (clusters
                                # variant 1: 7 % of dots 20-30 from any disc, none in
                                # the exemplar). Only children with one larger
                                # neighbour: a pebble between several stones that
                                # followed one of them was refused by the others more
                                # often (two sizes variant 1: pebbles sparser, failing
                                # nn[pebble>pebble] on 2/2 seeds).
                                mx, my = map_offset(px + partner_off[u, 0], py + partner_off[u, 1],
                                                    e_off[ea + t, 0] - e_off[ea + u, 0], e_off[ea + t, 1] - e_off[ea + u, 1])
                                pos[slot[t], 0] = px + partner_off[u, 0] + mx
                                pos[slot[t], 1] = py + partner_off[u, 1] + my
                        break
                pslot[slot[t]] = ps
            count[i * k + j] = n
    return count, ex, pos, pslot


@numba.njit(cache=True, nogil=True)
def snap_to_slots(targets, anchor_pos, anchor_src, cptr, cidx, e_pos, rc, ex, pos):
    """Move each target proposal to the nearest child slot of its output anchor (in
    place on ``ex`` and ``pos``), where that slot lies within the child's radius ``rc``.

    Parameters
    ----------
    targets : (m,) int
        Proposals to snap.
    anchor_pos : (m, 2) float
        Position of the output anchor each target stands beside.
    anchor_src : (m,) int
        The exemplar anchor that output anchor was copied as.
    cptr, cidx : CSR children of each exemplar element.
    e_pos : (n_ex, 2) float
    rc : (n_ex,) float
    ex : (P,) int
    pos : (P, 2) float
    """
    for u in range(targets.shape[0]):
        t = targets[u]
        a = anchor_src[u]
        best = INF
        bk = -1
        bx = 0.0
        by = 0.0
        for q in range(cptr[a], cptr[a + 1]):
            kid = cidx[q]
            mx, my = map_offset(anchor_pos[u, 0], anchor_pos[u, 1], e_pos[kid, 0] - e_pos[a, 0], e_pos[kid, 1] - e_pos[a, 1])
            sx = anchor_pos[u, 0] + mx
            sy = anchor_pos[u, 1] + my
            d = (sx - pos[t, 0]) ** 2 + (sy - pos[t, 1]) ** 2
            if d < best:
                best, bk, bx, by = d, kid, sx, sy
        if bk >= 0 and best <= rc[bk] * rc[bk]:
            ex[t] = bk
            pos[t, 0] = bx
            pos[t, 1] = by


@numba.njit(cache=True, nogil=True)
def place_proposals(costs, slack, out_ptr, count, prop_pos, prop_r, prop_sk, min_dist, prop_ok, c_ratio, factor, cell, pslot, parent_free, prop_cls, prop_gen):
    """Generation over seeds (Algorithm 1, §5.1), larger elements first.

    For each seed, candidates are visited by increasing distance; the best one ``e_0``
    is used if it can generate elements (some proposal passed the static checks
    ``prop_ok``), otherwise ``e_i`` is considered while
    ``|n(s) - n(e_i)| <= c |n(s) - n(e_0)| + slack`` (the ratio test of §5.1); a seed whose
    candidates all fail is abandoned. The chosen candidates' elements are then copied
    unless they intersect elements copied earlier in this step.

    Extension of §5.1: whether a candidate "can generate" is asked of ``prop_gen`` (a
    subset of ``prop_ok``: the proposals :func:`_grow.copyable` counts), while the
    chosen candidate's elements copied are all of its ``prop_ok`` ones (as before). With
    ``prop_gen = prop_ok`` this is the paper's rule.

    Departure (§4.1, §7 "significant differences in element size ... are not
    supported"): the copies of all seeds are placed in order of decreasing size class
    (``Prepared.size_class``; stable: seed order within a class), not seed by seed.
    Where two seeds' copies
    disagree, a small element of one would otherwise take the place of a large element
    of the other (a small element fits a leftover gap, a large one rarely does), and
    over a fill the small kinds crowd out the large ones (stones and pebbles: stones
    fell to 0.44 of the exemplar's fraction).

    Parameters
    ----------
    costs : (ns, k) float
    slack : (ns,) float
        Added to ``c |n(s) - n(e_0)|`` in the ratio test: two partial pairs' cost
        (``2 (2 r_s)^2``, one element shifted), so that a perfect match that cannot generate (``d_0 = 0``, as in
        a tiny exemplar) does not veto every other candidate.
    out_ptr, count : proposal layout from :func:`generate_proposals`.
    prop_pos : (P, 2) float
    prop_r : (P,) float
        Bounding radii.
    prop_sk : (P,) int
        Kind-in-exemplar class of each proposal (see ``Prepared.min_dist``).
    min_dist : (S, S) float
        Closest approach of two classes in the exemplar (0 where unknown).
    prop_ok : (P,) bool
    c_ratio : float
        The ratio constant c.
    factor : float
        Two elements intersect when ``|p - q| < factor (r_p + r_q)``.
    cell : float
        Grid cell for the dynamic intersection test (at least the largest limit).
    pslot : (P,) int
        Parent proposal of each proposal (see :func:`generate_proposals`): an element
        is copied only when its parent is (it is larger, so it is visited first), or
        when the parent lies outside the domain (``parent_free``); never with -2.
    parent_free : (P,) bool
    prop_cls : (P,) int
        Size class of each proposal.
    prop_gen : (P,) bool
        Proposals that make their candidate count as able to generate (within
        ``prop_ok``).

    Returns
    -------
    placed : (P,) bool
        Proposals copied to the output.
    seed_ok : (ns,) bool
        Seeds that generated at least one element.
    """
    ns, k = costs.shape
    P = prop_pos.shape[0]
    placed = np.zeros(P, np.bool_)
    seed_ok = np.zeros(ns, np.bool_)
    if P == 0:
        return placed, seed_ok
    sel = np.empty(P, np.int64)
    owner = np.empty(P, np.int64)
    m = 0
    for i in range(ns):
        order = np.argsort(costs[i], kind="mergesort")
        d0 = costs[i, order[0]]
        if d0 == INF:
            continue
        for jj in range(k):
            j = order[jj]
            cj = costs[i, j]
            if cj == INF or cj > c_ratio * d0 + slack[i]:
                break  # bad suggestion: abandon the seed (§5.1)
            w = out_ptr[i * k + j]
            gen = False
            for t in range(w, w + count[i * k + j]):
                if prop_gen[t]:
                    gen = True
                    break
            if not gen:
                continue
            for t in range(w, w + count[i * k + j]):
                if prop_ok[t]:
                    sel[m] = t
                    owner[m] = i
                    m += 1
            break
    if m == 0:
        return placed, seed_ok
    x0 = INF
    y0 = INF
    x1 = -INF
    y1 = -INF
    key = np.empty(m)
    for u in range(m):
        t = sel[u]
        key[u] = -prop_cls[t]
        x0 = min(x0, prop_pos[t, 0])
        y0 = min(y0, prop_pos[t, 1])
        x1 = max(x1, prop_pos[t, 0])
        y1 = max(y1, prop_pos[t, 1])
    visit = np.argsort(key, kind="mergesort")
    nx = int((x1 - x0) / cell) + 1
    ny = int((y1 - y0) / cell) + 1
    head = np.full(nx * ny, -1, np.int64)
    nxt = np.full(P, -1, np.int64)
    for uu in range(m):
        u = visit[uu]
        t = sel[u]
        ps = pslot[t]
        if ps == -2 or (ps >= 0 and not placed[ps] and not parent_free[ps]):
            continue  # its parent was not copied: no orphans
        px, py = prop_pos[t, 0], prop_pos[t, 1]
        gx = int((px - x0) / cell)
        gy = int((py - y0) / cell)
        hit = False
        for ax in range(max(gx - 1, 0), min(gx + 2, nx)):
            for ay in range(max(gy - 1, 0), min(gy + 2, ny)):
                q = head[ax * ny + ay]
                while q >= 0:
                    dx = px - prop_pos[q, 0]
                    dy = py - prop_pos[q, 1]
                    lim = max(factor * (prop_r[t] + prop_r[q]), min_dist[prop_sk[t], prop_sk[q]])
                    if dx * dx + dy * dy < lim * lim:
                        hit = True
                        break
                    q = nxt[q]
                if hit:
                    break
            if hit:
                break
        if not hit:
            placed[t] = True
            seed_ok[owner[u]] = True
            g = gx * ny + gy
            nxt[t] = head[g]
            head[g] = t
    return placed, seed_ok


@numba.njit(cache=True, nogil=True)
def best_matches(q_ptr, q_idx, q_off, q_kind, q_d, q_rbar, q_center_kind, q_center_d, cands, e_ptr, e_idx, e_off, e_kind, e_d, ex_kind, kind_cost):
    """Most similar exemplar neighbourhood for each query and its full pairs (§5.2).

    Returns
    -------
    best : (nq,) int
        Chosen exemplar element (-1 if none).
    cost : (nq,) float
    con_q : (C,) int
        Query number of each full pair.
    con_o : (C,) int
        Output element ``h'`` of the pair (from ``q_idx``).
    con_off : (C, 2) float
        Target offset ``p_e' - p_e`` (prediction vector) in example space.
    """
    nq, k = cands.shape
    best = np.full(nq, -1, np.int64)
    bcost = np.full(nq, INF)
    pair, used, _ = _pairing_scratch(q_ptr, e_ptr)
    # helper s34v: the lengths of every exemplar offset once, and the pairs of each
    # query's best candidate kept as it is found (not paired again afterwards); the
    # same pairs and costs as pair_cost gives
    elen_all = _segment_lengths(e_off)
    bpair = np.empty(q_ptr[nq], np.int64)
    for i in range(nq):
        a, b = q_ptr[i], q_ptr[i + 1]
        for j in range(k):
            c = cands[i, j]
            if c < 0:
                continue
            ea, eb = e_ptr[c], e_ptr[c + 1]
            cc = _center_cost(q_center_kind[i], ex_kind[c], q_center_d[i], kind_cost)
            # branch and bound: a candidate is dropped as soon as it cannot beat the best
            cost = cc + _pair_cost_lengths(q_off[a:b], q_kind[a:b], q_d[a:b], e_off[ea:eb], e_kind[ea:eb], e_d[ea:eb], kind_cost, q_rbar[i], pair, used, elen_all[ea:eb], bcost[i] - cc)
            if cost < bcost[i]:
                bcost[i] = cost
                best[i] = c
                for t in range(b - a):
                    bpair[a + t] = pair[t]
    total = 0
    for i in range(nq):
        total += q_ptr[i + 1] - q_ptr[i]
    con_q = np.empty(total, np.int64)
    con_o = np.empty(total, np.int64)
    con_off = np.empty((total, 2))
    n = 0
    for i in range(nq):
        c = best[i]
        if c < 0:
            continue
        a, b = q_ptr[i], q_ptr[i + 1]
        ea = e_ptr[c]
        for t in range(b - a):
            if bpair[a + t] >= 0:
                con_q[n] = i
                con_o[n] = q_idx[a + t]
                con_off[n, 0] = e_off[ea + bpair[a + t], 0]
                con_off[n, 1] = e_off[ea + bpair[a + t], 1]
                n += 1
    return best, bcost, con_q[:n], con_o[:n], con_off[:n]


@numba.njit(cache=True, nogil=True)
def own_jitter(h, center, hp, off, src, source, nb_ptr, nb_idx, nb_off, jit, pos, bound, spacing, seam_offset):
    """Prediction vectors with the jitter of the output elements they relate (the loop of
    ``_optimize._own_jitter``, which documents it; the same operations in the same order).

    For each pair the exemplar element ``e'`` of ``n(center)`` at exactly ``off`` (a
    full pair's prediction vector is a copy of one of ``center``'s neighbourhood
    offsets) is the first such row of the neighbourhood (the sorted hash lookup that
    found it before, main at bae7e74, took the first row of equal hash, so the same);
    pairs without one keep ``off``.

    Returns
    -------
    (c, 2) float
    """
    c = off.shape[0]
    out = off.copy()
    for t in range(c):
        e = center[t]
        ox = off[t, 0]
        oy = off[t, 1]
        e2 = -1
        for r in range(nb_ptr[e], nb_ptr[e + 1]):
            if nb_off[r, 0] == ox and nb_off[r, 1] == oy:
                e2 = nb_idx[r]
                break
        if e2 < 0:
            continue
        a = src[h[t]]
        b = src[hp[t]]
        if source[b] != source[e] or source[a] != source[e]:
            continue
        wx = jit[b, 0] - jit[a, 0]
        wy = jit[b, 1] - jit[a, 1]
        # a seam pair: its relative jitter kept within the exemplar's own bonds'
        if np.hypot((pos[b, 0] - pos[a, 0]) - ox, (pos[b, 1] - pos[a, 1]) - oy) > seam_offset * spacing[a]:
            m = np.hypot(wx, wy)
            f = min(m, bound[a]) / max(m, 1e-300)
            wx *= f
            wy *= f
        out[t, 0] = ox + (wx - (jit[e2, 0] - jit[e, 0]))
        out[t, 1] = oy + (wy - (jit[e2, 1] - jit[e, 1]))
    return out


@numba.njit(cache=True, nogil=True)
def _uf_find(parent, i):
    while parent[i] != i:
        parent[i] = parent[parent[i]]
        i = parent[i]
    return i


@numba.njit(cache=True, nogil=True)
def dbscan_labels(points, eps, min_samples):
    """DBSCAN over the pairs within ``eps`` (``|p - q|^2 <= eps^2``), as
    ``_prepare.dbscan`` defines it: a core point has at least ``min_samples`` points
    (itself included) within ``eps``; clusters are the connected components of the core
    points, numbered by their lowest core index; a border point joins the cluster of its
    core neighbours. Points are bucketed on a grid of side ``eps`` whose occupied cells
    are found by bisection in the sorted cell keys (the points may spread far along x).

    Returns
    -------
    labels : (n,) int
        -1 for noise.
    ambiguous : bool
        Some border point has core neighbours in two clusters (which one it joins then
        depends on the order of the pairs: the caller decides).
    """
    n = points.shape[0]
    labels = np.full(n, -1, np.int64)
    if n == 0:
        return labels, False
    e2 = eps * eps
    cell = eps * (1.0 + 1e-9)  # pairs within eps lie in neighbouring cells despite rounding
    x0 = points[0, 0]
    y0 = points[0, 1]
    for i in range(n):
        x0 = min(x0, points[i, 0])
        y0 = min(y0, points[i, 1])
    cy = np.empty(n, np.int64)
    cx = np.empty(n, np.int64)
    ny = 1
    for i in range(n):
        cx[i] = int((points[i, 0] - x0) / cell)
        cy[i] = int((points[i, 1] - y0) / cell)
        ny = max(ny, cy[i] + 3)
    key = np.empty(n, np.int64)
    for i in range(n):
        key[i] = (cx[i] + 1) * ny + cy[i] + 1
    order = np.argsort(key, kind="mergesort")
    skey = np.empty(n, np.int64)
    for t in range(n):
        skey[t] = key[order[t]]
    # every pair once: from each point, the later points of its own cell and of the
    # cell above it (contiguous in key order), and the three cells of the next column
    pi = np.empty(max(16, 4 * n), np.int64)
    pj = np.empty(max(16, 4 * n), np.int64)
    npair = 0
    for t in range(n):
        i = order[t]
        xi = points[i, 0]
        yi = points[i, 1]
        k = skey[t]
        lo2 = k + ny - 1
        a2 = np.searchsorted(skey, lo2)
        for part in range(2):
            a = t + 1 if part == 0 else a2
            hi = k + 1 if part == 0 else lo2 + 2
            for u in range(a, n):
                if skey[u] > hi:
                    break
                j = order[u]
                ddx = xi - points[j, 0]
                ddy = yi - points[j, 1]
                if ddx * ddx + ddy * ddy <= e2:
                    if npair == pi.shape[0]:
                        pi = np.concatenate((pi, np.empty(npair, np.int64)))
                        pj = np.concatenate((pj, np.empty(npair, np.int64)))
                    pi[npair] = i
                    pj[npair] = j
                    npair += 1
    deg = np.ones(n, np.int64)
    for p in range(npair):
        deg[pi[p]] += 1
        deg[pj[p]] += 1
    parent = np.arange(n)
    for p in range(npair):
        i = pi[p]
        j = pj[p]
        if deg[i] >= min_samples and deg[j] >= min_samples:
            ri = _uf_find(parent, i)
            rj = _uf_find(parent, j)
            if ri != rj:
                parent[max(ri, rj)] = min(ri, rj)
    nl = 0
    root_label = np.full(n, -1, np.int64)
    for i in range(n):
        if deg[i] >= min_samples:
            r = _uf_find(parent, i)
            if root_label[r] < 0:
                root_label[r] = nl
                nl += 1
            labels[i] = root_label[r]
    ambiguous = False
    for p in range(npair):
        i = pi[p]
        j = pj[p]
        ci = deg[i] >= min_samples
        cj = deg[j] >= min_samples
        if ci == cj:
            continue
        b, c = (j, i) if ci else (i, j)
        if labels[b] < 0:
            labels[b] = labels[c]
        elif labels[b] != labels[c]:
            ambiguous = True
    return labels, ambiguous


@numba.njit(cache=True, nogil=True)
def greedy_separated(pos, order, sep):
    """Greedy subset of ``order`` whose members are at least ``sep[i]`` apart (§5.1 seeds).

    Parameters
    ----------
    pos : (n, 2) float
    order : (m,) int
        Indices into ``pos`` in visiting order.
    sep : (n,) float
        Separation radius of each element (0.75 r-bar for seeds).

    Returns
    -------
    (s,) int
        Chosen indices (a subset of ``order``, in order).
    """
    m = order.shape[0]
    out = np.empty(m, np.int64)
    ns = 0
    if m == 0:
        return out[:0]
    cell = 0.0
    for t in range(m):
        cell = max(cell, sep[order[t]])
    cell = max(cell, 1e-12)
    x0 = INF
    y0 = INF
    x1 = -INF
    y1 = -INF
    for t in range(m):
        i = order[t]
        x0 = min(x0, pos[i, 0])
        y0 = min(y0, pos[i, 1])
        x1 = max(x1, pos[i, 0])
        y1 = max(y1, pos[i, 1])
    nx = int((x1 - x0) / cell) + 1
    ny = int((y1 - y0) / cell) + 1
    head = np.full(nx * ny, -1, np.int64)
    nxt = np.full(m, -1, np.int64)
    for t in range(m):
        i = order[t]
        gx = int((pos[i, 0] - x0) / cell)
        gy = int((pos[i, 1] - y0) / cell)
        ok = True
        for ax in range(max(gx - 1, 0), min(gx + 2, nx)):
            for ay in range(max(gy - 1, 0), min(gy + 2, ny)):
                q = head[ax * ny + ay]
                while q >= 0:
                    j = out[q]
                    dx = pos[i, 0] - pos[j, 0]
                    dy = pos[i, 1] - pos[j, 1]
                    lim = max(sep[i], sep[j])
                    if dx * dx + dy * dy < lim * lim:
                        ok = False
                        break
                    q = nxt[q]
                if not ok:
                    break
            if not ok:
                break
        if ok:
            out[ns] = i
            g = gx * ny + gy
            nxt[ns] = head[g]
            head[g] = ns
            ns += 1
    return out[:ns]


@numba.njit(cache=True, nogil=True)
def conflict_check(pts, qr, qsk, qcover, opos, orad, osk, min_dist, factor, use_sk, cell):
    """Which query points would intersect an output element (uniform grid search).

    A query ``i`` and an output element ``j`` intersect when ``|p_i - p_j|`` is below
    ``factor (qr_i + orad_j)``, below ``min_dist[qsk_i, osk_j]`` (when ``use_sk``), or
    below ``qcover_i``.

    Parameters
    ----------
    pts : (m, 2) float
    qr, qcover : (m,) float
    qsk : (m,) int
    opos : (n, 2) float
    orad : (n,) float
    osk : (n,) int
    min_dist : (S, S) float
    cell : float
        At least the largest limit.

    Returns
    -------
    (m,) bool
    """
    m = pts.shape[0]
    n = opos.shape[0]
    out = np.zeros(m, np.bool_)
    if n == 0 or m == 0:
        return out
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(opos, cell, m, np.bool_(False))
    for i in range(m):
        gx = int(np.floor((pts[i, 0] - x0) / cell))
        gy = int(np.floor((pts[i, 1] - y0) / cell))
        hit = False
        for ax in range(max(gx - 1, 0), min(gx + 2, nx)):
            for ay in range(max(gy - 1, 0), min(gy + 2, ny)):
                j = head[ax * ny + ay]
                while j >= 0:
                    dx = pts[i, 0] - opos[j, 0]
                    dy = pts[i, 1] - opos[j, 1]
                    lim = factor * (qr[i] + orad[j])
                    if use_sk:
                        lim = max(lim, min_dist[qsk[i], osk[j]])
                    lim = max(lim, qcover[i])
                    if dx * dx + dy * dy < lim * lim:
                        hit = True
                        break
                    j = nxt[j]
                if hit:
                    break
            if hit:
                break
        out[i] = hit
    return out


@numba.njit(cache=True, nogil=True)
def _kind_near(x, y, kind, r2, opos, okind, x0, y0, cell, nx, ny, head, nxt):  # pragma: no cover - numba
    """(nearest, count): the output element of kind ``kind`` nearest (x, y) within
    sqrt(``r2``) (-1 if none; the first met wins a tie) and how many of that kind lie
    within it, from the 3 x 3 cells of the bucket grid around (x, y) (``cell`` at least
    sqrt(``r2``)). Both questions of :func:`ring_full`."""
    gx = int(np.floor((x - x0) / cell))
    gy = int(np.floor((y - y0) / cell))
    best = -1
    bd = np.inf
    cnt = 0
    for ax in range(max(gx - 1, 0), min(gx + 2, nx)):
        for ay in range(max(gy - 1, 0), min(gy + 2, ny)):
            j = head[ax * ny + ay]
            while j >= 0:
                if okind[j] == kind:
                    dx = x - opos[j, 0]
                    dy = y - opos[j, 1]
                    d2 = dx * dx + dy * dy
                    if d2 <= r2:
                        cnt += 1
                        if d2 < bd:
                            bd = d2
                            best = j
                j = nxt[j]
    return best, cnt


@numba.njit(cache=True, nogil=True)
def ring_full(pts, reach, pk, ck, opos, okind, osrc, cap, cell):  # pragma: no cover - numba
    """(m,) bool: proposals ``pts`` whose nearest output element of kind ``pk[i]``
    within ``reach[i]`` already has at least ``cap[osrc[h], ck[i]]`` output elements of
    kind ``ck[i]`` within ``reach[i]`` (see ``_grow._ring_full``). ``cell`` is at least
    the largest reach, so a uniform grid over ``opos`` answers both from 3 x 3 cells
    (:func:`_kind_near`)."""
    m = pts.shape[0]
    out = np.zeros(m, np.bool_)
    if m == 0 or opos.shape[0] == 0:
        return out
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(opos, cell, m, np.bool_(False))
    for i in range(m):
        r2 = reach[i] * reach[i]
        best, _ = _kind_near(pts[i, 0], pts[i, 1], pk[i], r2, opos, okind, x0, y0, cell, nx, ny, head, nxt)
        if best < 0:
            continue
        _, cnt = _kind_near(opos[best, 0], opos[best, 1], ck[i], r2, opos, okind, x0, y0, cell, nx, ny, head, nxt)
        out[i] = cnt >= cap[osrc[best], ck[i]]
    return out


@numba.njit(cache=True, nogil=True)
def conflict_split(pts, qr, qsk, qcls, opos, orad, osk, ocls, oyield, min_dist, factor, cell):
    """Like :func:`conflict_check` (with ``use_sk``), telling apart intersections with
    elements that yield to the query: ``oyield[j]`` and a smaller size class,
    ``ocls[j] < qcls[i]``.

    Returns
    -------
    hard : (m,) bool
        Intersects an element that does not yield.
    soft : (m,) bool
        Intersects only elements that yield (and at least one).
    """
    m = pts.shape[0]
    n = opos.shape[0]
    hard = np.zeros(m, np.bool_)
    soft = np.zeros(m, np.bool_)
    if n == 0 or m == 0:
        return hard, soft
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(opos, cell, m, np.bool_(False))
    for i in range(m):
        gx = int(np.floor((pts[i, 0] - x0) / cell))
        gy = int(np.floor((pts[i, 1] - y0) / cell))
        for ax in range(max(gx - 1, 0), min(gx + 2, nx)):
            for ay in range(max(gy - 1, 0), min(gy + 2, ny)):
                j = head[ax * ny + ay]
                while j >= 0:
                    dx = pts[i, 0] - opos[j, 0]
                    dy = pts[i, 1] - opos[j, 1]
                    lim = max(factor * (qr[i] + orad[j]), min_dist[qsk[i], osk[j]])
                    if dx * dx + dy * dy < lim * lim:
                        if oyield[j] and ocls[j] < qcls[i]:
                            soft[i] = True
                        else:
                            hard[i] = True
                            break
                    j = nxt[j]
                if hard[i]:
                    break
            if hard[i]:
                break
        if hard[i]:
            soft[i] = False
    return hard, soft


@numba.njit(cache=True, nogil=True)
def _disc_hits(pts, pr, centers, cr, strict):
    """(n,) bool: is ``|pts[i] - centers[j]|`` below ``max(pr[i], cr[j])`` for some j.

    ``strict``: ``<``, else ``<=``. A uniform grid over the centres, with cells of the
    largest limit (coarser when that grid would be much larger than the input).
    """
    n = pts.shape[0]
    m = centers.shape[0]
    out = np.zeros(n, np.bool_)
    if n == 0 or m == 0:
        return out
    cell = 1e-12
    for i in range(n):
        cell = max(cell, pr[i])
    for j in range(m):
        cell = max(cell, cr[j])
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(centers, cell, n, np.bool_(False))
    for i in range(n):
        fx = (pts[i, 0] - x0) / cell
        fy = (pts[i, 1] - y0) / cell
        if not (fx >= -1.0 and fy >= -1.0 and fx < nx + 1.0 and fy < ny + 1.0):
            continue  # no centre within one cell (also NaN)
        gx = int(np.floor(fx))
        gy = int(np.floor(fy))
        hit = False
        for ax in range(max(gx - 1, 0), min(gx + 2, nx)):
            for ay in range(max(gy - 1, 0), min(gy + 2, ny)):
                j = head[ax * ny + ay]
                while j >= 0:
                    dx = pts[i, 0] - centers[j, 0]
                    dy = pts[i, 1] - centers[j, 1]
                    lim = max(pr[i], cr[j])
                    d2 = dx * dx + dy * dy
                    if d2 < lim * lim or (not strict and d2 == lim * lim):
                        hit = True
                        break
                    j = nxt[j]
                if hit:
                    break
            if hit:
                break
        out[i] = hit
    return out


# The three front ends of _disc_hits are plain Python: as compiled wrappers each cost a
# compile of its own on a first run (about a second of CPU each, for a one-line body;
# issue 16), and they are only called from Python.
def overlaps_any(pts, pr, centers, cr):
    """(n,) bool: is ``|pts[i] - centers[j]| < max(pr[i], cr[j])`` for some j."""
    return _disc_hits(pts, pr, centers, cr, True)


def in_discs(pts, centers, radii):
    """(n,) bool: which ``pts`` lie in some disc ``(centers[j], radii[j])``."""
    return _disc_hits(pts, np.zeros(pts.shape[0]), centers, radii, False)


def near_any(pts, centers, reach):
    """(n,) bool: which ``pts`` lie within ``reach`` of some point of ``centers``."""
    return _disc_hits(pts, np.zeros(pts.shape[0]), centers, np.full(centers.shape[0], float(reach)), False)


@numba.njit(cache=True, nogil=True)
def spacing_violations(pos, rad, sk, min_dist, factor, moved, cell):
    """(n,) bool: moved elements closer to another element than allowed.

    The limit is ``max(factor (r_i + r_j), min_dist[sk_i, sk_j])``; only pairs with a
    moved element are checked, and the moved member(s) are flagged.
    """
    n = pos.shape[0]
    out = np.zeros(n, np.bool_)
    if n < 2:
        return out
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(pos, cell, np.int64(0), np.bool_(False))
    for i in range(n):
        if not moved[i]:
            continue
        gx = int((pos[i, 0] - x0) / cell)
        gy = int((pos[i, 1] - y0) / cell)
        for ax in range(max(gx - 1, 0), min(gx + 2, nx)):
            for ay in range(max(gy - 1, 0), min(gy + 2, ny)):
                j = head[ax * ny + ay]
                while j >= 0:
                    if j != i:
                        dx = pos[i, 0] - pos[j, 0]
                        dy = pos[i, 1] - pos[j, 1]
                        lim = max(factor * (rad[i] + rad[j]), min_dist[sk[i], sk[j]])
                        if dx * dx + dy * dy < lim * lim:
                            out[i] = True
                            if moved[j]:
                                out[j] = True
                    j = nxt[j]
    return out


@numba.njit(cache=True, nogil=True)
def grid_neighborhoods(pos, query, radius):
    """CSR neighbourhoods of ``pos[query]`` within ``radius`` (self excluded), sorted by
    distance; a uniform grid replaces the k-d tree for the output's hot loop.

    Returns
    -------
    ptr : (m + 1,) int
    idx : (N,) int
    off : (N, 2) float
    """
    n = pos.shape[0]
    m = query.shape[0]
    ptr = np.zeros(m + 1, np.int64)
    if n == 0 or m == 0:
        return ptr, np.zeros(0, np.int64), np.zeros((0, 2))
    rmax = _vmax(radius)
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(pos, float(rmax), np.int64(0), np.bool_(True))
    reach = int(np.ceil(rmax / cell))
    idx = np.empty(0, np.int64)
    off = np.empty((0, 2))
    for t in range(2):
        w = 0
        for a in range(m):
            i = query[a]
            r2 = radius[a] * radius[a]
            gx = int((pos[i, 0] - x0) / cell)
            gy = int((pos[i, 1] - y0) / cell)
            start = w
            for ax in range(max(gx - reach, 0), min(gx + reach + 1, nx)):
                for ay in range(max(gy - reach, 0), min(gy + reach + 1, ny)):
                    j = head[ax * ny + ay]
                    while j >= 0:
                        if j != i:
                            dx = pos[j, 0] - pos[i, 0]
                            dy = pos[j, 1] - pos[i, 1]
                            if dx * dx + dy * dy <= r2:
                                if t == 1:
                                    idx[w] = j
                                    off[w, 0] = dx
                                    off[w, 1] = dy
                                w += 1
                        j = nxt[j]
            if t == 0:
                ptr[a + 1] = w
            else:
                # sort the segment by distance (insertion sort: segments are small)
                for u in range(start + 1, w):
                    ju = idx[u]
                    ox = off[u, 0]
                    oy = off[u, 1]
                    du = ox * ox + oy * oy
                    v = u - 1
                    while v >= start and (off[v, 0] * off[v, 0] + off[v, 1] * off[v, 1] > du or (off[v, 0] * off[v, 0] + off[v, 1] * off[v, 1] == du and idx[v] > ju)):
                        idx[v + 1] = idx[v]
                        off[v + 1, 0] = off[v, 0]
                        off[v + 1, 1] = off[v, 1]
                        v -= 1
                    idx[v + 1] = ju
                    off[v + 1, 0] = ox
                    off[v + 1, 1] = oy
        if t == 0:
            idx = np.empty(w, np.int64)
            off = np.empty((w, 2))
    return ptr, idx, off


@numba.njit(cache=True, nogil=True)
def same_kind_nearest(pos, sk, query, radius, want):
    """(m,) float: distance from each element ``query[a]`` to its nearest other element
    of kind ``want[a]`` (``sk``) within ``radius`` (inf where none is that near); a
    uniform grid, for the optimisation's spread guard (``_optimize._undo_overspread``)."""
    n = pos.shape[0]
    m = query.shape[0]
    out = np.full(m, np.inf)
    if n < 2 or m == 0:
        return out
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(pos, float(radius), np.int64(m), np.bool_(False))
    reach = int(np.ceil(radius / cell))
    r2 = radius * radius
    for a in range(m):
        i = query[a]
        best = np.inf
        gx = int((pos[i, 0] - x0) / cell)
        gy = int((pos[i, 1] - y0) / cell)
        for ax in range(max(gx - reach, 0), min(gx + reach + 1, nx)):
            for ay in range(max(gy - reach, 0), min(gy + reach + 1, ny)):
                j = head[ax * ny + ay]
                while j >= 0:
                    if j != i and sk[j] == want[a]:
                        dx = pos[j, 0] - pos[i, 0]
                        dy = pos[j, 1] - pos[i, 1]
                        d2 = dx * dx + dy * dy
                        if d2 <= r2 and d2 < best:
                            best = d2
                    j = nxt[j]
        if best < np.inf:
            out[a] = np.sqrt(best)
    return out


@numba.njit(cache=True, nogil=True)
def nearest_by_kind(pos, sk, query, radius, n_kinds):
    """(m, n_kinds) float: distance from each element ``query[a]`` to its nearest other
    element of each kind (``sk``) within ``radius`` (inf where none is that near); one
    pass over a uniform grid, for the optimisation's spread guard
    (``_optimize._undo_overspread``)."""
    n = pos.shape[0]
    m = query.shape[0]
    out = np.full((m, n_kinds), np.inf)
    if n < 2 or m == 0:
        return out
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(pos, float(radius), np.int64(m), np.bool_(False))
    reach = int(np.ceil(radius / cell))
    r2 = radius * radius
    for a in range(m):
        i = query[a]
        gx = int((pos[i, 0] - x0) / cell)
        gy = int((pos[i, 1] - y0) / cell)
        for ax in range(max(gx - reach, 0), min(gx + reach + 1, nx)):
            for ay in range(max(gy - reach, 0), min(gy + reach + 1, ny)):
                j = head[ax * ny + ay]
                while j >= 0:
                    b = sk[j]
                    if j != i and b >= 0 and b < n_kinds:
                        dx = pos[j, 0] - pos[i, 0]
                        dy = pos[j, 1] - pos[i, 1]
                        d2 = dx * dx + dy * dy
                        if d2 <= r2 and d2 < out[a, b]:
                            out[a, b] = d2
                    j = nxt[j]
        for b in range(n_kinds):
            if out[a, b] < np.inf:
                out[a, b] = np.sqrt(out[a, b])
    return out


@numba.njit(cache=True, nogil=True, inline="always")
def _seg_seg_dist2(ax, ay, bx, by, cx, cy, dx, dy):  # pragma: no cover - numba
    """Squared distance between closed segments ab and cd (0 when they meet)."""
    if _seg_hit(ax, ay, bx, by, cx, cy, dx, dy):
        return 0.0
    return min(min(_seg_dist2(ax, ay, cx, cy, dx, dy), _seg_dist2(bx, by, cx, cy, dx, dy)),
               min(_seg_dist2(cx, cy, ax, ay, bx, by), _seg_dist2(dx, dy, ax, ay, bx, by)))


@numba.njit(cache=True, nogil=True, inline="always")
def _in_segs(px, py, s, n):  # pragma: no cover - numba
    """Even-odd: ``(px, py)`` inside the closed rings whose edges are ``s[:n]`` (ax, ay, bx, by)."""
    ins = False
    for k in range(n):
        ay = s[k, 1]
        by = s[k, 3]
        if (ay > py) != (by > py):
            xc = s[k, 0] + (py - ay) * (s[k, 2] - s[k, 0]) / (by - ay)
            if px < xc:
                ins = not ins
    return ins


@numba.njit(cache=True, nogil=True, inline="always")
def _place_segs(seg, k0, k1, x, y, c, s, out):  # pragma: no cover - numba
    """Local segments ``seg[k0:k1]`` rotated and scaled by ``(c, s)`` and moved to ``(x, y)``, into ``out``."""
    for k in range(k0, k1):
        t = k - k0
        out[t, 0] = x + c * seg[k, 0] - s * seg[k, 1]
        out[t, 1] = y + s * seg[k, 0] + c * seg[k, 1]
        out[t, 2] = x + c * seg[k, 2] - s * seg[k, 3]
        out[t, 3] = y + s * seg[k, 2] + c * seg[k, 3]
    return k1 - k0


@numba.njit(cache=True, nogil=True, inline="always")
def _pt_shape_dist2(px, py, s, n, areal):  # pragma: no cover - numba
    """Squared distance from ``(px, py)`` to the shape with edges ``s[:n]`` (0 inside an areal one)."""
    if areal and _in_segs(px, py, s, n):
        return 0.0
    best = np.inf
    for k in range(n):
        best = min(best, _seg_dist2(px, py, s[k, 0], s[k, 1], s[k, 2], s[k, 3]))
    return best


@numba.njit(cache=True, nogil=True)
def _shapes_within(sa, na, areal_a, sb, nb, areal_b, r2):  # pragma: no cover - numba
    """Whether two shapes (edges ``sa[:na]``, ``sb[:nb]``) come within ``sqrt(r2)``: their
    edges do, or a vertex of one lies inside the other (areal) one."""
    for p in range(na):
        for q in range(nb):
            if _seg_seg_dist2(sa[p, 0], sa[p, 1], sa[p, 2], sa[p, 3], sb[q, 0], sb[q, 1], sb[q, 2], sb[q, 3]) <= r2:
                return True
    if areal_a and nb > 0 and _in_segs(sb[0, 0], sb[0, 1], sa, na):
        return True
    return areal_b and na > 0 and _in_segs(sa[0, 0], sa[0, 1], sb, nb)


@numba.njit(cache=True, nogil=True)
def shape_counts(pts, qsrc, qcap, qself, opos, osrc, ovis, el_kind, el_c, el_s, el_rad, el_reach, seg, kptr, areal, centre_in, cell):  # pragma: no cover - numba
    """(m,) int64: for each query copy, the visible output shapes within its reach
    (``_grow.shape_limits``), counted up to ``qcap[i] + 1`` (0 where ``qcap[i] < 0``).

    Query ``i`` is a copy of exemplar element ``qsrc[i]`` at ``pts[i]``; output element
    ``j`` one of ``osrc[j]`` at ``opos[j]`` (counted when ``ovis[j]``, and never when
    ``j == qself[i]``: an element is not its own neighbour; -1 for none). An element
    ``e``'s shape is its kind's local segments ``seg[kptr[k]:kptr[k + 1]]`` (ax, ay, bx,
    by) turned by ``(el_c[e], el_s[e])`` (cosine and sine of its rotation times its
    scale); ``el_rad[e]`` its bounding radius (the largest distance of a vertex from its
    centre), ``areal[k]`` whether its rings bound an area (even-odd), ``centre_in[k]``
    whether the origin lies in the shape. Two shapes come within ``reach`` when their
    centres do and both centres lie in their shapes (the shapes are no farther apart
    than their centres), never when the centres are beyond ``reach`` plus both bounding
    radii, and otherwise exactly: their edges come within ``reach``, or a vertex of one
    lies inside the other (the distance is 0). Counting stops past the cap.
    ``cell``: the grid's cell side (twice the largest bounding radius plus the largest
    reach, so a query walks about three cells across).
    """
    m = pts.shape[0]
    n = opos.shape[0]
    out = np.zeros(m, np.int64)
    if n == 0 or m == 0:
        return out
    ms = 1
    for k in range(kptr.shape[0] - 1):
        ms = max(ms, kptr[k + 1] - kptr[k])
    sa = np.empty((ms, 4))
    sb = np.empty((ms, 4))
    rmax = 0.0
    for j in range(n):
        if ovis[j]:
            rmax = max(rmax, el_rad[osrc[j]])
    x0, y0, cell, nx, ny, head, nxt = _bucket_grid(opos, cell, np.int64(m), np.bool_(False))
    for i in range(m):
        lim = qcap[i]
        me = qself[i]
        if lim < 0:
            continue
        e = qsrc[i]
        ka = el_kind[e]
        px = pts[i, 0]
        py = pts[i, 1]
        ra = el_rad[e]
        reach = el_reach[e]
        r2 = reach * reach
        na = _place_segs(seg, kptr[ka], kptr[ka + 1], px, py, el_c[e], el_s[e], sa)
        span = ra + reach + rmax
        cx0 = max(int((px - span - x0) / cell), 0)
        cx1 = min(int((px + span - x0) / cell), nx - 1)
        cy0 = max(int((py - span - y0) / cell), 0)
        cy1 = min(int((py + span - y0) / cell), ny - 1)
        cnt = 0
        for ax in range(cx0, cx1 + 1):
            for ay in range(cy0, cy1 + 1):
                j = head[ax * ny + ay]
                while j >= 0 and cnt <= lim:
                    if ovis[j] and j != me:
                        f = osrc[j]
                        kb = el_kind[f]
                        dx = opos[j, 0] - px
                        dy = opos[j, 1] - py
                        d2 = dx * dx + dy * dy
                        rb = el_rad[f]
                        far = reach + ra + rb
                        if d2 <= r2 and centre_in[ka] and centre_in[kb]:
                            cnt += 1
                        elif d2 <= far * far:
                            nb = _place_segs(seg, kptr[kb], kptr[kb + 1], opos[j, 0], opos[j, 1], el_c[f], el_s[f], sb)
                            # the centre of each against the other's shape: within reach of
                            # a shape holding its own centre counts, beyond reach plus its
                            # bounding radius never does
                            da = _pt_shape_dist2(opos[j, 0], opos[j, 1], sa, na, areal[ka])
                            db = _pt_shape_dist2(px, py, sb, nb, areal[kb])
                            ta = reach + rb
                            tb = reach + ra
                            if da > ta * ta or db > tb * tb:
                                hit = False
                            elif (da <= r2 and centre_in[kb]) or (db <= r2 and centre_in[ka]):
                                hit = True
                            else:
                                hit = _shapes_within(sa, na, areal[ka], sb, nb, areal[kb], r2)
                            if hit:
                                cnt += 1
                    j = nxt[j]
        out[i] = cnt
    return out


@numba.njit(cache=True, nogil=True)
def shape_crowded(pts, qsrc, qlim, opos, osrc, ovis, el_kind, el_c, el_s, el_rad, el_reach, seg, kptr, areal, centre_in, cell):  # pragma: no cover - numba
    """(m,) bool: query copies with more visible output shapes within their reach than
    their limit ``qlim`` (-1: none; see :func:`shape_counts`, whose arguments these are)."""
    qself = np.full(pts.shape[0], -1, np.int64)
    cnt = shape_counts(pts, qsrc, qlim, qself, opos, osrc, ovis, el_kind, el_c, el_s, el_rad, el_reach, seg, kptr, areal, centre_in, cell)
    return (cnt > qlim) & (qlim >= 0)

"""Pairing (Eq. 1), k-coherence, free-space clustering and horizon pruning (§4, §5.1)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from strew import Region
from strew.synth import new_state, seed_patch
from strew.synth import _kernels as K
from strew.synth._exemplars import grid, stripes
from strew.synth._grow import update_free_space
from strew.synth._prepare import cluster_free_space, dbscan


def _pair(o_off, o_kind, e_off, e_kind, d=2.0, kind_cost=1.0, rim=100.0):
    o_off = np.asarray(o_off, float).reshape(-1, 2)
    e_off = np.asarray(e_off, float).reshape(-1, 2)
    order = np.argsort(np.hypot(*o_off.T), kind="stable")
    o_off = np.ascontiguousarray(o_off[order])
    o_kind = np.asarray(o_kind, np.int64)[order]
    # exemplar neighbourhoods are sorted by length (pair_cost's precondition); report
    # pairs and ``used`` in the caller's order
    e_order = np.argsort(np.hypot(*e_off.T), kind="stable")
    e_sorted = np.ascontiguousarray(e_off[e_order])
    e_kind = np.asarray(e_kind, np.int64).reshape(-1)[e_order]
    pair = np.empty(max(len(o_off), 1), np.int64)
    used = np.empty(max(len(e_off), 1), bool)
    elen = np.empty(max(len(e_off), 1))
    cost = K.pair_cost(o_off, o_kind, np.full(len(o_off), d), e_sorted, e_kind, np.full(len(e_off), d), kind_cost, rim, pair, used, elen)
    pair = np.where(pair[: len(o_off)] >= 0, e_order[np.maximum(pair[: len(o_off)], 0)], -1) if len(e_off) else pair[: len(o_off)]
    used_in = np.zeros(len(e_off), bool)
    used_in[e_order] = used[: len(e_off)]
    return cost, pair, used_in, order


def _pair_brute(o_off, o_kind, o_d, e_off, e_kind, e_d, kind_cost, rim):
    """Eq. 1 with greedy pairing, scanning every exemplar neighbour (reference)."""
    used = np.zeros(len(e_off), bool)
    pair = np.full(len(o_off), -1)
    cost = 0.0
    for i in range(len(o_off)):
        dd = o_d[i] ** 2
        best, bestc = -1, np.inf
        for j in range(len(e_off)):
            if used[j]:
                continue
            r2 = float(np.sum((o_off[i] - e_off[j]) ** 2))
            if r2 > dd:
                continue
            c = r2 + (kind_cost * dd if o_kind[i] != e_kind[j] else 0.0)
            if c < bestc:
                best, bestc = j, c
        pair[i] = best
        if best >= 0:
            used[best] = True
            cost += bestc
        else:
            cost += dd
    for j in range(len(e_off)):
        lim = rim - 0.5 * e_d[j]
        if not used[j] and lim > 0 and np.sum(e_off[j] ** 2) <= lim * lim:
            cost += e_d[j] ** 2
    return cost, pair, used


_offsets = st.lists(st.tuples(st.floats(-12, 12), st.floats(-12, 12), st.integers(0, 1), st.floats(0.5, 4.0)), max_size=14)


@given(_offsets, _offsets, st.floats(0.0, 2.0), st.floats(1.0, 15.0))
def test_banded_pairing_equals_the_full_scan(o, e, kind_cost, rim):
    """pair_cost scans only the band of exemplar neighbours whose length is within d of
    the output neighbour's; the result equals the scan of every exemplar neighbour."""

    def unpack(rows):
        a = np.asarray(rows, float).reshape(-1, 4)
        a = a[np.argsort(np.hypot(a[:, 0], a[:, 1]), kind="stable")]
        return np.ascontiguousarray(a[:, :2]), a[:, 2].astype(np.int64), a[:, 3].copy()

    o_off, o_kind, o_d = unpack(o)
    e_off, e_kind, e_d = unpack(e)
    pair = np.empty(max(len(o_off), 1), np.int64)
    used = np.empty(max(len(e_off), 1), bool)
    elen = np.empty(max(len(e_off), 1))
    cost = K.pair_cost(o_off, o_kind, o_d, e_off, e_kind, e_d, kind_cost, rim, pair, used, elen)
    ref_cost, ref_pair, ref_used = _pair_brute(o_off, o_kind, o_d, e_off, e_kind, e_d, kind_cost, rim)
    assert cost == pytest.approx(ref_cost, rel=1e-12, abs=1e-12)
    assert np.array_equal(pair[: len(o_off)], ref_pair)
    assert np.array_equal(used[: len(e_off)], ref_used)


def test_identical_neighbourhoods_pair_fully_at_zero_cost():
    off = [[3, 0], [0, 4], [-5, 1]]
    cost, pair, used, order = _pair(off, [0, 1, 0], off, [0, 1, 0])
    assert cost == 0
    assert np.all(pair >= 0) and used.all()
    # each output neighbour pairs with its own copy
    assert np.array_equal(pair, order)


def test_shifted_pair_costs_squared_distance():
    cost, pair, used, _ = _pair([[3, 0]], [0], [[3.5, 0.5]], [0])
    assert pair[0] == 0
    assert cost == pytest.approx(0.5)


def test_left_and_right_partial_pairs_cost_threshold_squared():
    # output neighbour far from any exemplar neighbour: left-partial (o', 0);
    # exemplar neighbour left over: right-partial (0, e')
    cost, pair, used, _ = _pair([[3, 0]], [0], [[-3, 0]], [0], d=2.0)
    assert pair[0] == -1
    assert not used[0]
    assert cost == pytest.approx(2 * 2.0**2)


def test_greedy_order_nearest_output_element_pairs_first():
    # two output neighbours compete for one exemplar neighbour; the one nearer p_o wins
    cost, pair, used, order = _pair([[1.5, 0], [1.0, 0]], [0, 0], [[1.2, 0]], [0], d=2.0)
    first = order[0]  # index of [1.0, 0] in the input
    assert np.hypot(*np.asarray([[1.5, 0], [1.0, 0]])[first]) == 1.0
    assert pair[0] == 0 and pair[1] == -1
    assert cost == pytest.approx(0.2**2 + 2.0**2)


def test_kind_mismatch_cost_is_added():
    same, *_ = _pair([[3, 0]], [0], [[3, 0]], [0], kind_cost=1.0)
    diff, pair, *_ = _pair([[3, 0]], [0], [[3, 0]], [1], kind_cost=1.0)
    assert same == 0
    assert pair[0] == 0
    assert diff == pytest.approx(1.0 * 2.0**2)
    # a same-kind element a little further is preferred over a mismatched one
    cost, pair, *_ = _pair([[3, 0]], [0], [[3, 0], [3.5, 0]], [1, 0], kind_cost=1.0)
    assert pair[0] == 1


def test_right_partials_on_the_rim_do_not_count():
    inner, *_ = _pair([], [], [[3, 0]], [0], d=2.0, rim=10.0)
    rim, *_ = _pair([], [], [[9.5, 0]], [0], d=2.0, rim=10.0)
    assert inner == pytest.approx(4.0)
    assert rim == 0


@given(st.lists(st.tuples(st.floats(-10, 10), st.floats(-10, 10)), min_size=1, max_size=12), st.floats(-0.4, 0.4), st.floats(-0.4, 0.4))
def test_small_shifts_keep_full_pairs(points, dx, dy):
    pts = np.asarray(points)
    # keep points at least one threshold apart so that pairs are unambiguous
    keep = [0]
    for i in range(1, len(pts)):
        if np.min(np.hypot(*(pts[keep] - pts[i]).T)) > 4.5:
            keep.append(i)
    pts = pts[keep]
    cost, pair, used, _ = _pair(pts + (dx, dy), [0] * len(pts), pts, [0] * len(pts), d=2.0)
    assert np.all(pair >= 0) and used.all()
    assert cost == pytest.approx(len(pts) * (dx * dx + dy * dy), rel=1e-9, abs=1e-9)


def test_k_coherence_sets_on_a_grid():
    ex = grid(n=12, jitter=0.0)
    s = new_state(ex, Region.rectangle(50, 50), k=5, rng=0)
    prep = s.prep
    assert prep.co.shape == (len(ex), 5)
    inner = np.concatenate(prep.interior)
    # an interior element is first in its own set; every candidate is interior
    assert np.array_equal(prep.co[inner, 0], inner)
    assert np.isin(prep.co[prep.co >= 0], inner).all()
    # on a perfect grid all interior neighbourhoods are alike: members are distinct and
    # their neighbourhoods match the element's exactly
    for e in inner[:10]:
        assert len(set(prep.co[e])) == 5


def test_k_coherence_prefers_the_same_stripe():
    ex = stripes()
    s = new_state(ex, Region.rectangle(50, 50), k=3, rng=0)
    prep = s.prep
    inner = np.concatenate(prep.interior)
    for e in inner:
        # candidates sit on a column of the same kind
        assert np.all(prep.kind[prep.co[e]] == prep.kind[e])


def test_dbscan_finds_blobs_and_noise():
    rng = np.random.default_rng(0)
    pts = np.r_[rng.normal(0, 0.1, (15, 2)), rng.normal(5, 0.1, (15, 2)), [[20.0, 20.0]]]
    labels = dbscan(pts, eps=0.5, min_samples=3)
    assert len(set(labels[:15])) == 1 and len(set(labels[15:30])) == 1
    assert labels[0] != labels[15] and labels[0] >= 0
    assert labels[30] == -1


def test_free_space_clusters_replace_vectors_by_centroids():
    rng = np.random.default_rng(1)
    a = rng.normal((10, 0), 0.2, (6, 2))
    b = rng.normal((0, 10), 0.2, (6, 2))
    cent, vals = cluster_free_space(np.r_[a, b], np.c_[np.ones(12), 2 * np.ones(12)], eps=1.0, min_samples=1)
    assert len(cent) == 2
    got = sorted(map(tuple, np.round(cent, 6)))
    want = sorted([tuple(np.round(a.mean(0), 6)), tuple(np.round(b.mean(0), 6))])
    assert np.allclose(got, want)
    assert np.allclose(vals, [[1, 2], [1, 2]])


def test_free_space_of_grid_elements_points_at_grid_neighbours():
    ex = grid(n=12, spacing=10.0, jitter=0.0)
    s = new_state(ex, Region.rectangle(50, 50), rng=0)
    prep = s.prep
    e = int(np.concatenate(prep.interior)[0])
    v = prep.free_off[prep.free_ptr[e] : prep.free_ptr[e + 1]]
    assert len(v) > 8
    # every free-space vector is a lattice offset
    assert np.allclose(v / 10.0, np.round(v / 10.0), atol=1e-6)
    assert {(10, 0), (-10, 0), (0, 10), (0, -10)} <= {tuple(np.round(x).astype(int)) for x in v}


def test_horizon_pruning():
    ex = grid(n=12, jitter=0.0)
    s = new_state(ex, Region.rectangle(300, 300), rng=0)
    idx = seed_patch(s, (150, 150))
    assert len(idx) > 10 and s.horizon.all()
    from scipy.spatial import cKDTree

    update_free_space(s, np.arange(s.n), cKDTree(s.pos))
    fpos, *_ = s.free_points(np.arange(s.n))
    fpos = fpos[s.in_domain(fpos)]
    d = np.hypot(*(s.pos[:, None, :] - fpos[None, :, :]).transpose(2, 0, 1))
    has_free = (d <= s.rbar[:, None]).any(axis=1)
    # horizon == elements with a live free-space point within their neighbourhood radius
    assert np.array_equal(s.horizon, has_free)
    # the rim of the patch stays in the horizon
    rim = np.argmax(np.hypot(*(s.pos - (150, 150)).T))
    assert s.horizon[rim]
    # no live free-space point sits on an element
    dd = np.hypot(*(fpos[:, None, :] - s.pos[None, :, :]).transpose(2, 0, 1))
    assert dd.min() > 2 * s.r.max() * s.prep.factor - 1e-9
    # after growth has filled the region, nothing is left in the horizon
    from strew.synth import grow

    grow(s)
    assert not s.horizon.any()


_pts = st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(0.1, 12.0)), max_size=30)


@given(_pts, _pts)
def test_grid_disc_queries_equal_brute_force(q, c):
    """The numba grid searches behind the brush discs and free-space overlap."""
    qa = np.asarray(q, float).reshape(-1, 3)
    ca = np.asarray(c, float).reshape(-1, 3)
    p, pr = np.ascontiguousarray(qa[:, :2]), qa[:, 2].copy()
    cen, cr = np.ascontiguousarray(ca[:, :2]), ca[:, 2].copy()
    d2 = ((p[:, None, 0] - cen[None, :, 0]) ** 2 + (p[:, None, 1] - cen[None, :, 1]) ** 2).reshape(len(p), len(cen))
    in_ref = np.any(d2 <= cr[None, :] ** 2, axis=1) if len(cen) else np.zeros(len(p), bool)
    ov_ref = np.any(d2 < np.maximum(pr[:, None], cr[None, :]) ** 2, axis=1) if len(cen) else np.zeros(len(p), bool)
    assert np.array_equal(K.in_discs(p, cen, cr), in_ref)
    assert np.array_equal(K.overlaps_any(p, pr, cen, cr), ov_ref)
    reach = float(cr[0]) if len(cr) else 1.0
    near_ref = np.any(d2 <= reach**2, axis=1) if len(cen) else np.zeros(len(p), bool)
    assert np.array_equal(K.near_any(p, cen, reach), near_ref)
    # radii far below the spread: the grid coarsens instead of growing without bound
    ps, cs, tiny = p * 1e3, cen * 1e3, np.full(len(cr), 1e-6)
    d2s = ((ps[:, None, 0] - cs[None, :, 0]) ** 2 + (ps[:, None, 1] - cs[None, :, 1]) ** 2).reshape(len(p), len(cen))
    assert np.array_equal(K.in_discs(ps, cs, tiny), np.any(d2s <= tiny[None, :] ** 2, axis=1) if len(cen) else np.zeros(len(p), bool))


@given(_offsets, _offsets, st.floats(0.0, 200.0))
def test_pair_cost_bound_only_drops_candidates_that_cannot_win(o, e, bound):
    def unpack(rows):
        a = np.asarray(rows, float).reshape(-1, 4)
        a = a[np.argsort(np.hypot(a[:, 0], a[:, 1]), kind="stable")]
        return np.ascontiguousarray(a[:, :2]), a[:, 2].astype(np.int64), a[:, 3].copy()

    o_off, o_kind, o_d = unpack(o)
    e_off, e_kind, e_d = unpack(e)
    pair = np.empty(max(len(o_off), 1), np.int64)
    used = np.empty(max(len(e_off), 1), bool)
    elen = np.empty(max(len(e_off), 1))
    full = K.pair_cost(o_off, o_kind, o_d, e_off, e_kind, e_d, 1.0, 10.0, pair, used, elen)
    bounded = K.pair_cost(o_off, o_kind, o_d, e_off, e_kind, e_d, 1.0, 10.0, pair, used, elen, bound)
    if np.isinf(bounded):
        assert full >= bound
    else:
        assert bounded == full

"""Matching (Ijiri et al. §5.2, Eq. 2-4) on hand-built neighbourhoods."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from strew.grow import match_references, matching_set, order_target


def _rings(rels, kinds=None, subs=None):
    """Padded ring arrays of hand-built reference neighbourhoods."""
    r = len(rels)
    k = max(len(x) for x in rels)
    rel = np.zeros((r, k, 2))
    kind = np.full((r, k), -1, dtype=np.int64)
    sub = np.full((r, k), -1, dtype=np.int64)
    n = np.zeros(r, dtype=np.int64)
    for a, x in enumerate(rels):
        n[a] = len(x)
        rel[a, : len(x)] = x
        kind[a, : len(x)] = 0 if kinds is None else kinds[a]
        sub[a, : len(x)] = np.arange(len(x)) + 100 * a if subs is None else subs[a]
    return {"ids": np.arange(r, dtype=np.int64), "rel": rel, "kind": kind, "sub": sub, "n": n}


HEX = 10.0 * np.c_[np.cos(np.arange(6) * np.pi / 3), np.sin(np.arange(6) * np.pi / 3)]


@given(st.integers(0, 9), st.integers(1, 9))
def test_size_of_F(t, n):
    F = matching_set(t, n)
    if t > n:
        assert F == []
        return
    assert len(F) == n  # Fig. 4: one matching per starting reference neighbour
    for k, f in enumerate(F):
        assert [i for i, _ in f] == list(range(t))  # no skipping
        js = [j for _, j in f]
        assert all((js[i + 1] - js[i]) % n == 1 for i in range(t - 1))  # no flipping
        if t:
            assert js[0] == k


def test_error_is_eq2_minimum_over_F():
    # target: three neighbours that match reference slots 2, 3, 4 exactly
    tgt = HEX[[2, 3, 4]] + np.array([[0.5, 0.0], [0.0, 0.0], [0.0, -0.25]])
    rings = _rings([HEX])
    err, shift, theta = match_references(rings, tgt, np.zeros(3, int), np.full(3, -1))
    assert shift[0] == 2
    assert err[0] == pytest.approx(0.5 + 0.0 + 0.25)  # w1 * sum of distances
    assert theta[0] == 0.0
    # brute force over F agrees
    best = min(sum(np.linalg.norm(tgt[i] - HEX[j]) for i, j in f) for f in matching_set(3, 6))
    assert err[0] == pytest.approx(best)


def test_symbol_id_and_subid_terms():
    tgt = HEX[[0, 1]]
    rings = _rings([HEX], kinds=[np.array([0, 1, 0, 0, 0, 0])])
    # a kind mismatch costs w2 = 1 per pair
    err, shift, _ = match_references(rings, tgt, np.array([0, 0]), np.array([-1, -1]))
    assert err[0] == pytest.approx(1.0, abs=1e-9) and shift[0] == 0
    err_ok, _, _ = match_references(rings, tgt, np.array([0, 1]), np.array([-1, -1]))
    assert err_ok[0] == pytest.approx(0.0, abs=1e-9)
    # a target neighbour copying the reference element itself costs w3 = 100
    err_sub, _, _ = match_references(rings, tgt, np.array([0, 1]), np.array([0, -1]))
    assert err_sub[0] == pytest.approx(100.0, abs=1e-9)


def test_references_with_fewer_neighbours_are_skipped():
    small = HEX[[0, 2, 4]]
    rings = _rings([small, HEX])
    tgt = HEX[[0, 1, 2, 3]]
    err, _, _ = match_references(rings, tgt, np.zeros(4, int), np.full(4, -1))
    assert np.isinf(err[0]) and np.isfinite(err[1])


def test_candidates_restrict_the_search():
    rings = _rings([HEX, HEX])
    err, _, _ = match_references(rings, HEX[:2], np.zeros(2, int), np.full(2, -1), candidates=np.array([False, True]))
    assert np.isinf(err[0]) and np.isfinite(err[1])


@given(st.floats(-np.pi, np.pi), st.integers(1, 6))
def test_rotate_mode_finds_the_rotation_eq4(angle, t):
    c, s = np.cos(angle), np.sin(angle)
    tgt = HEX[:t] @ np.array([[c, -s], [s, c]]).T
    rings = _rings([HEX])
    err, shift, theta = match_references(rings, tgt, np.zeros(t, int), np.full(t, -1), mode="rotate")
    assert err[0] == pytest.approx(0.0, abs=1e-6)
    # the rotation maps the matched reference slots onto the target
    k = shift[0]
    rc, rs = np.cos(theta[0]), np.sin(theta[0])
    rot = HEX[[(k + i) % 6 for i in range(t)]] @ np.array([[rc, -rs], [rs, rc]]).T
    assert np.allclose(rot, tgt, atol=1e-6)
    # fixed mode cannot undo the rotation unless it is a lattice symmetry
    err_fixed, _, _ = match_references(rings, tgt, np.zeros(t, int), np.full(t, -1), mode="fixed")
    assert err_fixed[0] >= err[0] - 1e-9


def test_flow_mode_rotates_the_reference_to_the_flow():
    rings = _rings([HEX[[0, 2, 4]]])
    th = np.pi / 6
    c, s = np.cos(th), np.sin(th)
    tgt = (HEX[[0, 2]] @ np.array([[c, -s], [s, c]]).T)
    err, _, theta = match_references(rings, tgt, np.zeros(2, int), np.full(2, -1), mode="flow", flow_theta=th)
    assert theta[0] == pytest.approx(th)
    assert err[0] == pytest.approx(0.0, abs=1e-9)


def test_order_target_starts_at_the_boundary():
    # neighbours at 0°, 60°, 120° and 300°: the big gap is 120° -> 300°, so start at 300°
    rel = HEX[[1, 2, 0, 5]]
    order = order_target(rel)
    assert rel[order].round(6).tolist() == HEX[[5, 0, 1, 2]].round(6).tolist()


@given(st.floats(-0.08, 0.08).filter(lambda t: abs(t) > 1e-3), st.integers(0, 5))
def test_few_neighbours_keep_the_frame_when_a_turn_gains_less_than_it_costs(turn, start):
    # two target neighbours of a hexagonal ring, both turned by a small angle (noise):
    # the fitted turn is within max_turn, but with a frame weight of 3 l per radian and
    # neighbour, keeping the neighbours' frame costs less than the turn saves
    rings = _rings([HEX])
    c, s = np.cos(turn), np.sin(turn)
    t = HEX[[start, (start + 1) % 6]] @ np.array([[c, s], [-s, c]])
    kw = dict(mode="rotate", frame_theta=0.0, frame_weight=30.0, max_turn=0.2)
    err, shift, theta = match_references(rings, t, np.zeros(2, np.int64), np.full(2, -7), keep_frame=3, **kw)
    assert theta[0] == 0.0 and shift[0] == start
    # without the candidate the noisy fit turns the element
    _, _, theta0 = match_references(rings, t, np.zeros(2, np.int64), np.full(2, -7), keep_frame=0, **kw)
    assert abs(theta0[0] - turn) < 1e-9
    # three neighbours or more take the fitted turn
    t3 = HEX[[start, (start + 1) % 6, (start + 2) % 6]] @ np.array([[c, s], [-s, c]])
    _, _, theta3 = match_references(rings, t3, np.zeros(3, np.int64), np.full(3, -7), keep_frame=3, **kw)
    assert abs(theta3[0] - turn) < 1e-9

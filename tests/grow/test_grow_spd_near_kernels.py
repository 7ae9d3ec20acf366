"""Flow mode's measures: the compiled ``_near_kernels.ball_counts`` and ``far_from``
answer as the cKDTree queries they replace, to the last bit (issue 14 point 5, speed;
byte-identical output)."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from scipy.spatial import cKDTree

from strew.grow import _near_kernels as nk

coords = st.floats(-30, 30, allow_nan=False, width=32)
pts_st = st.lists(st.tuples(coords, coords), min_size=1, max_size=60)
radius = st.floats(0.05, 12.0, allow_nan=False)


def _ref_counts(pts, q, r_hi, r_lo):
    t = cKDTree(pts)
    return (np.asarray(t.query_ball_point(q, r_hi, return_length=True)), np.asarray(t.query_ball_point(q, r_lo, return_length=True)))


def _ref_far(pts, q, r):
    return cKDTree(pts).query(q, distance_upper_bound=r)[0] > r


@given(pts_st, pts_st, radius, st.floats(0.1, 1.0))
def test_ball_counts_equal_ckdtree(pts, qs, r, f):
    p = np.array(pts, dtype=float)
    q = np.array(qs, dtype=float)
    hi, lo = nk.ball_counts(p, q, r, f * r)
    rh, rl = _ref_counts(p, q, r, f * r)
    assert hi.tolist() == rh.tolist()
    assert lo.tolist() == rl.tolist()
    # queries at the points themselves (the six-site test's use)
    hi, lo = nk.ball_counts(p, p, r, f * r)
    rh, rl = _ref_counts(p, p, r, f * r)
    assert hi.tolist() == rh.tolist() and lo.tolist() == rl.tolist()


@given(pts_st, pts_st, radius)
def test_far_from_equals_ckdtree(pts, qs, r):
    p = np.array(pts, dtype=float)
    q = np.array(qs, dtype=float)
    assert nk.far_from(p, q, r).tolist() == _ref_far(p, q, r).tolist()


@given(st.integers(1, 9), st.integers(1, 9), st.sampled_from([0.1, 0.25, 0.3, 1.0, 1.7, 2.5]), st.sampled_from([1.0, 2.0, 5.0, 2.0**0.5, 3.0**0.5 / 2]))
def test_exact_ties_on_a_lattice(nx, ny, step, r):
    # points exactly at the radius (lattice distances): the comparisons must be cKDTree's,
    # <= for the ball counts and < (then the root against r) for the far test
    g = np.mgrid[0:nx, 0:ny].reshape(2, -1).T * step
    hexg = g + np.c_[0.5 * step * (np.arange(len(g)) % 2), np.zeros(len(g))]
    for p in (g, hexg):
        q = np.r_[p, p + 0.5 * step, p + [r * step, 0.0], p - [0.0, r * step]]
        for rr in (r * step, step, 0.75 * step):
            hi, lo = nk.ball_counts(p, q, rr, 0.85 * rr)
            rh, rl = _ref_counts(p, q, rr, 0.85 * rr)
            assert hi.tolist() == rh.tolist() and lo.tolist() == rl.tolist()
            assert nk.far_from(p, q, rr).tolist() == _ref_far(p, q, rr).tolist()


def test_empty_and_far_queries():
    p = np.array([[0.0, 0.0], [1.0, 0.0]])
    q = np.array([[1e6, -1e6], [0.5, 0.0], [-3.0, 0.0]])
    hi, lo = nk.ball_counts(p, q, 1.0, 0.5)
    assert hi.tolist() == [0, 2, 0] and lo.tolist() == [0, 2, 0]
    assert nk.far_from(p, q, 0.6).tolist() == [True, False, True]
    assert nk.far_from(np.zeros((0, 2)), q, 1.0).tolist() == [True] * 3
    assert nk.ball_counts(p, np.zeros((0, 2)), 1.0, 0.5)[0].tolist() == []
    # a very sparse set (more cells than points allow) falls back to cKDTree's answer
    sparse = np.array([[0.0, 0.0], [1e5, 1e5], [1e5, 0.0]])
    qq = np.r_[sparse, sparse + 0.3]
    assert nk.far_from(sparse, qq, 0.5).tolist() == _ref_far(sparse, qq, 0.5).tolist()
    assert nk.ball_counts(sparse, qq, 0.5, 0.4)[0].tolist() == _ref_counts(sparse, qq, 0.5, 0.4)[0].tolist()

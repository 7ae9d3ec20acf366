"""Relaxation (Ijiri et al. §5.5, Eq. 5 and 6) and the flow field it may follow."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from strew import InputError
from strew.fields import flow_field
from strew.grow import delaunay_edges, grow, relax_positions
from strew.grow._exemplars import hex_lattice


def _lattice_terms(xy):
    e = delaunay_edges(xy)
    src = np.r_[e[:, 0], e[:, 1]]
    dst = np.r_[e[:, 1], e[:, 0]]
    return src, dst, xy[dst] - xy[src]


@given(st.integers(0, 2**32 - 1), st.floats(0.5, 3.0), st.floats(-np.pi, np.pi), st.floats(-50, 50))
def test_relaxation_restores_a_perturbed_lattice(seed, noise, angle, shift):
    xy = hex_lattice(8, 8)
    src, dst, off = _lattice_terms(xy)
    rng = np.random.default_rng(seed)
    pert = xy + rng.normal(0, noise, xy.shape)
    free = np.ones(len(xy), dtype=bool)
    free[0] = False  # Eq. 6: hold the initial element
    pert[0] = xy[0] + shift
    out = relax_positions(pert, src, dst, off, free)
    # the unique minimiser of Eq. 5 with x_0 fixed is the lattice translated to x_0
    assert np.abs(out - (xy + shift)).max() < 1e-3
    assert np.abs(pert - (xy + shift)).max() > 0.1


def test_fixed_elements_stay_and_residual_decreases():
    xy = hex_lattice(6, 6)
    src, dst, off = _lattice_terms(xy)
    pert = xy + np.random.default_rng(1).normal(0, 2, xy.shape)
    free = np.ones(len(xy), dtype=bool)
    free[[0, 5, 30, 35]] = False
    out = relax_positions(pert, src, dst, off, free)
    assert np.array_equal(out[~free], pert[~free])

    def energy(p):
        return float(np.sum((p[dst] - p[src] - off) ** 2))

    assert energy(out) < 0.5 * energy(pert)
    # it is the least-squares minimum: small moves of a free point do not lower it
    for k in (7, 14, 21):
        for d in ((1e-3, 0), (0, 1e-3)):
            q = out.copy()
            q[k] += d
            assert energy(q) >= energy(out) - 1e-9


def test_windowed_relaxation_in_growth_keeps_rings_close_to_the_reference():
    # jittered growth (rotation noise) on stones: relaxation must not increase the mean
    # deviation of nearest-neighbour distances from the exemplar's
    from scipy.spatial import cKDTree

    from strew.grow._exemplars import stone_exemplar

    ex = stone_exemplar()
    d_ex = cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]
    res = {}
    for relax in (False, True):
        out = grow(ex, count=300, rng=2, relax=relax)
        d = cKDTree(out.xy).query(out.xy, k=2)[0][:, 1]
        res[relax] = abs(np.median(d) - np.median(d_ex))
    assert res[True] <= res[False] + 0.05 * np.median(d_ex)


def test_flow_field_from_strokes():
    f = flow_field([np.array([[0.0, 0.0], [100.0, 0.0]]), np.array([[0.0, 100.0], [0.0, 200.0]])])
    v = f(np.array([[50.0, 0.0], [0.0, 150.0]]))
    assert np.allclose(np.linalg.norm(v, axis=1), 1.0)
    assert v[0] == pytest.approx([1.0, 0.0], abs=1e-3)
    assert v[1] == pytest.approx([0.0, 1.0], abs=1e-3)
    assert f.angle([[50.0, 0.0]])[0] == pytest.approx(0.0, abs=1e-3)
    with pytest.raises(InputError, match="no stroke"):
        flow_field([np.array([[1.0, 1.0]])])


def test_relax_positions_weights_one_is_unweighted_and_weights_pull_harder():
    rng = np.random.default_rng(0)
    pos = rng.uniform(0, 10, (8, 2))
    src = np.array([0, 1, 2, 3, 4, 5, 6, 0])
    dst = np.array([1, 2, 3, 4, 5, 6, 7, 7])
    off = rng.uniform(-2, 2, (8, 2))
    free = np.array([False, True, True, True, True, True, True, True])
    plain = relax_positions(pos, src, dst, off, free)
    ones = relax_positions(pos, src, dst, off, free, weights=np.ones(8))
    assert np.allclose(plain, ones, atol=1e-9)
    # a heavy term is met more nearly than with weight one
    w = np.ones(8)
    w[3] = 100.0
    heavy = relax_positions(pos, src, dst, off, free, weights=w)

    def miss(p):
        return float(np.hypot(*(p[dst[3]] - p[src[3]] - off[3])))

    assert miss(heavy) < 0.1 * miss(plain)

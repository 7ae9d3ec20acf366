"""Issue 13 point 1 (helper opt13d): the horizon optimisation must not push an element
further from its nearest element of a kind than its exemplar keeps them (90th
percentile)
(``_optimize.spread_bound``, ``_undo_overspread``).

two_sizes with stones the majority (``ratio=0.35, n_large=120, n_small=35``: the
dart-thrown stones nearly saturate the frame) failed on nn[stone>stone] at 550ea99
(0.080 / 0.075 against a tolerance of 0.0685): the least-squares targets of the stone
pairs were on average 1.1-1.4 longer than the pairs' distances, and every stone decile
moved up by about 1 (0.040 with ``optimize="none"``).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize
from strew.synth import _optimize as O
from strew.synth import new_state
from strew.synth._grow import fill

from strew_testing import fidelity_suite

make_exemplar = fidelity_suite().make_exemplar

P4 = dict(ratio=0.35, n_large=120, n_small=35)


def _out(ex, seed, scale=3.5):
    x0, y0, x1, y1 = ex.region.bounds
    return synthesize(ex, Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=seed, measure=False)


@pytest.mark.parametrize("name,variant,kw", [("two_sizes", 7, P4), ("two_sizes", 1, {})])
def test_two_sizes_faithful(name, variant, kw):
    """Both fail at 550ea99: stones the majority (nn[stone>stone] 0.080 / 0.075 against
    0.0685) and the default variant 1 (nn[pebble>pebble] 0.071 / 0.077 against 0.065)."""
    ex = make_exemplar(name, rng=variant, **kw)
    for seed in (1, 2):
        rep = fidelity(ex, _out(ex, seed), eq5=False, local=False)
        assert rep.faithful, (variant, seed, [k for k, v in rep.metrics.items() if v.applicable and not v.passed])


def test_spread_bound_is_the_exemplar_quantile():
    """On an irregular exemplar of two kinds: one bound per kind, within its own
    nearest-neighbour distances; on a one-kind or near-regular exemplar: no bound."""
    ex = make_exemplar("two_sizes", rng=7, **P4)
    st = new_state(ex, Region.rectangle(300, 300), rng=1)
    prep = st.prep
    b = O.spread_bound(prep)
    for c in np.unique(prep.skind):
        m = np.flatnonzero(prep.skind == c)
        for k in np.unique(prep.skind):
            mk = np.flatnonzero(prep.skind == k)
            d = cKDTree(prep.pos[mk]).query(prep.pos[m], k=2)[0]
            d = d[:, 1] if k == c else d[:, 0]
            # one bound per pair of kinds, between the closest and farthest nearest neighbour
            assert np.all(b[m, k] == b[m[0], k])
            assert d.min() <= b[m[0], k] <= d.max()
    # a one-kind exemplar (stones) and a near-regular one (rings) get no bound
    for name in ("stones", "rings"):
        p = new_state(make_exemplar(name), Region.rectangle(300, 300), rng=1).prep
        assert np.isinf(O.spread_bound(p)).all(), name


def test_step_never_overspreads():
    """After any optimisation step, no moved element stands further than the bound from
    its nearest element of any kind unless it already did before the step."""
    ex = make_exemplar("two_sizes", rng=7, **P4)
    st = new_state(ex, Region.rectangle(400, 400), optimize="none", rng=3)
    fill(st, max_iterations=8)
    prep = st.prep
    sk = prep.skind[st.src]
    bound = O.spread_bound(prep)[st.src]
    old = st.pos.copy()

    def nn(pos):
        d = np.full(bound.shape, np.inf)
        for b in np.unique(sk):
            ids = np.flatnonzero(sk == b)
            dd, j = cKDTree(pos[ids]).query(pos, k=2)
            d[:, b] = np.where(ids[j[:, 0]] == np.arange(len(pos)), dd[:, 1], dd[:, 0])
        return d

    d0 = nn(old)
    O.optimize(st, None)
    moved = np.any(st.pos != old, axis=1)
    assert moved.any()
    d1 = nn(st.pos)
    bad = moved & np.any((d1 > bound) & (d1 > d0 + 1e-9), axis=1)
    assert not bad.any(), int(bad.sum())


def test_same_kind_nearest_matches_kdtree():
    """The guard's grid kernel: the nearest other element of the same kind, exact up to
    the radius, inf beyond it."""
    from strew.synth import _kernels as K

    rng = np.random.default_rng(5)
    pos = rng.uniform(0, 200, (600, 2))
    sk = rng.integers(0, 3, 600).astype(np.int64)
    query = rng.choice(600, 150, replace=False).astype(np.int64)
    for radius in (4.0, 15.0, 400.0):
        got = K.same_kind_nearest(pos, sk, query, radius, sk[query])
        want = np.full(len(query), np.inf)
        for c in range(3):
            ids = np.flatnonzero(sk == c)
            m = sk[query] == c
            want[m] = cKDTree(pos[ids]).query(pos[query[m]], k=2)[0][:, 1]
        want[want > radius] = np.inf
        fin = np.isfinite(want)
        assert np.array_equal(np.isinf(got), ~fin)
        assert np.allclose(got[fin], want[fin], rtol=0, atol=1e-9)

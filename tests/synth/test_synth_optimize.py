"""Optimisation (§5.2-5.3): Eq. 4 weights, frozen elements, lower energy (Eq. 2)."""

from __future__ import annotations

import numpy as np
import pytest

from strew import Region
from strew.synth import energy, new_state, optimize
from strew.synth._exemplars import grid, rings
from strew.synth._optimize import prediction_weights


def _jittered_copy(ex, sigma, seed=0, keep=None):
    """A state holding the exemplar's own elements, displaced by Gaussian noise."""
    s = new_state(ex, Region.rectangle(1000, 1000, -500, -500), optimize="global", rng=seed)
    ids = np.arange(len(ex)) if keep is None else keep
    noise = np.random.default_rng(seed).normal(0, sigma, (len(ids), 2))
    s.add(ids, s.prep.pos[ids] + noise)
    return s


@pytest.mark.parametrize("make, sigma", [(lambda: grid(n=10, jitter=0.0), 1.2), (rings, 1.0)])
def test_optimisation_lowers_the_energy(make, sigma):
    ex = make()
    s = _jittered_copy(ex, sigma)
    e0 = energy(s)
    for _ in range(3):
        optimize(s, None)
    e1 = energy(s)
    assert e1 < 0.8 * e0


def test_horizon_optimisation_lowers_the_energy_of_the_horizon():
    ex = grid(n=12, jitter=0.0)
    s = _jittered_copy(ex, 1.2, seed=2)
    hz = np.flatnonzero(np.hypot(*(s.pos - s.pos.mean(0)).T) < 30)
    before = energy(s, hz)
    for _ in range(3):
        optimize(s, hz)
    assert energy(s, hz) < before


def test_frozen_elements_barely_move():
    ex = grid(n=12, jitter=0.0)
    s = _jittered_copy(ex, 1.0, seed=3)
    centre = s.pos.mean(0)
    hz = np.flatnonzero(np.hypot(*(s.pos - centre).T) < 25)
    old = s.pos.copy()
    optimize(s, hz)
    moved = np.hypot(*(s.pos - old).T)
    frozen = np.setdiff1d(np.arange(s.n), hz)
    assert moved[hz].mean() > 3 * moved[frozen].mean()


def test_prediction_weights_eq4():
    # one prediction: weight 1
    w = prediction_weights(np.array([0]), np.array([[1.0, 2.0]]), np.array([0.1]))
    assert w[0] == pytest.approx(1.0)
    # four agreeing predictions and one outlier for the same element
    pred = np.array([[0, 0], [0.1, 0], [0, 0.1], [0.1, 0.1], [3.0, 3.0]])
    w = prediction_weights(np.zeros(5, int), pred, np.full(5, 0.05))
    assert np.argmin(w) == 4
    assert np.all(w[:4] > w[4])
    assert np.all((w > 0) & (w <= 1))
    # weights are per element: a second element's predictions do not change the first's
    w2 = prediction_weights(np.r_[np.zeros(5, int), np.ones(2, int)], np.r_[pred, [[50, 50], [60, 60]]], np.full(7, 0.05))
    assert np.allclose(w2[:5], w)


def test_optimisation_keeps_centres_in_the_region():
    ex = grid(n=10, jitter=0.0)
    s = new_state(ex, Region.rectangle(60, 60, 5, 5), optimize="global", rng=0)
    s.add(np.arange(len(ex)), s.prep.pos + np.random.default_rng(0).normal(0, 1.0, (len(ex), 2)))
    inside = s.region.contains(s.pos)
    optimize(s, None)
    assert np.array_equal(s.region.contains(s.pos) | ~inside, np.ones(s.n, bool))


def test_metric_is_tracked_while_synthesis_runs():
    from strew.synth import average_neighborhood_distance, synthesize

    trace = []
    out = synthesize(grid(), Region.rectangle(150, 150), rng=1, trace=trace)
    assert len(trace) >= 3
    t = np.array(trace)
    assert np.all(np.diff(t[:, 0]) >= 0) and np.all(np.diff(t[:, 1]) >= 0)
    assert t[-1, 1] >= len(out)
    assert np.all(np.isfinite(t[:, 2])) and np.all(t[:, 2] >= 0)
    # Eq. 5 is zero for a verbatim copy of the exemplar's interior and grows with noise
    ex = grid(n=12, jitter=0.0)
    s = new_state(ex, Region.rectangle(1000, 1000, -500, -500), rng=0)
    s.add(np.arange(len(ex)), s.prep.pos)
    assert average_neighborhood_distance(s) == pytest.approx(0.0, abs=1e-9)
    s2 = _jittered_copy(ex, 1.0)
    assert average_neighborhood_distance(s2) > 1.0


def test_optimisation_keeps_the_exemplar_spacing_on_rings():
    """Moves that crowd elements are put back, however many rounds that takes: after a
    fill no two elements are closer than the exemplar allows (§5.2 guard)."""
    from scipy.spatial import cKDTree

    from strew import Region
    from strew.synth import fill, new_state
    from strew.synth._exemplars import rings

    s = new_state(rings(), Region.rectangle(840, 760), rng=1)
    fill(s)
    pos, r, prep = s.pos, s.r, s.prep
    sk = prep.skind[s.src]
    a, b = cKDTree(pos).query_pairs(max(2 * r.max(), prep.min_dist.max()), output_type="ndarray").T
    d = np.hypot(*(pos[a] - pos[b]).T)
    lim = np.maximum(prep.factor * (r[a] + r[b]), prep.min_dist[sk[a], sk[b]])
    assert np.all(d >= lim - 1e-9)

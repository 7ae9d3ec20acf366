"""Issue 13 point 2: synth does not repeat one part of the exemplar within a window.

k-coherence keeps copying the neighbourhoods the output already holds; before
``_grow._prefer_unrepeated`` a window of the exemplar's size at 50x the area could hold
one medium-poor, large-rich part of the three-sizes exemplar twice over (each exemplar
element copied about twice in the window) and fail ``nn[medium>medium]``.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

import strew.synth._grow as G
from strew import Region
from strew.synth import fill, new_state

from strew_testing import fidelity_suite


def _repeats(state, side: float) -> float:
    """Mean number of other output elements copied from the same exemplar element within
    ``side`` of each element."""
    pos, src = state.pos[: state.n], state.src[: state.n]
    lists = cKDTree(pos).query_ball_point(pos, side)
    return float(np.mean([np.count_nonzero(src[v] == src[i]) - 1 for i, v in enumerate(lists)]))


def _grown(ex, region, seed: int, radius: float):
    old = G.REPEAT_RADIUS
    G.REPEAT_RADIUS = radius
    try:
        st = new_state(ex, region, rng=seed)
        fill(st)
    finally:
        G.REPEAT_RADIUS = old
    return st


@pytest.mark.slow
def test_fewer_repeated_copies_near_each_element():
    """The rule, switched on (it is off by default, see ``REPEAT_RADIUS``), copies fewer
    exemplar elements twice near each other."""
    ex = fidelity_suite().make_exemplar("three_sizes")
    x0, y0, x1, y1 = ex.region.bounds
    side = float(np.sqrt((x1 - x0) * (y1 - y0)))
    region = Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0))
    off = _grown(ex, region, 1, 0.0)
    on = _grown(ex, region, 1, 1.0)  # the radius measured in REPEAT_RADIUS's docstring
    # same fill, about the same count
    assert abs(on.n - off.n) < 0.05 * off.n
    assert _repeats(on, side) < 0.92 * _repeats(off, side)  # seeds 1, 2: 0.85, 0.73 of it


def test_repeated_candidate_goes_behind_a_fresh_one(monkeypatch):
    """Unit: a candidate copied near the seed is pushed past the ratio bound when another
    candidate within the bound is fresh; a seed whose candidates are all repeated keeps
    its costs."""
    monkeypatch.setattr(G, "REPEAT_RADIUS", 0.2)
    ex = fidelity_suite().make_exemplar("three_sizes")  # 132 interior elements (REPEAT_MIN_INTERIOR)
    st = new_state(ex, Region.rectangle(300, 300), rng=3)
    fill(st)
    seeds = np.array([st.n // 2, st.n // 3])
    pos, src = st.pos[: st.n], st.src[: st.n]
    near = cKDTree(pos).query_ball_point(pos[seeds[0]], 20.0)
    rep_src = next(src[j] for j in near if j != seeds[0])
    used = set(src[cKDTree(pos).query_ball_point(pos[seeds[0]], G.REPEAT_RADIUS * 210.0 + 1)])
    fresh_src = next(i for i in range(len(st.prep.pos)) if i not in used) if len(used) < len(st.prep.pos) else None
    if fresh_src is None:
        pytest.skip("every exemplar element is copied near the seed")
    cands = np.array([[rep_src, fresh_src], [rep_src, rep_src]])
    costs = np.array([[1.0, 1.5], [1.0, 1.2]])
    before = costs.copy()
    G._prefer_unrepeated(st, seeds[:1], cands[:1], costs[:1], 0.0, 2.0)
    assert costs[0, 1] == before[0, 1]
    assert costs[0, 0] > 2.0 * 1.0  # beyond c d_0 + slack
    assert np.argmin(costs[0]) == 1
    G._prefer_unrepeated(st, seeds[:1], cands[1:], costs[1:], 0.0, 2.0)
    np.testing.assert_array_equal(costs[1], before[1])
    # an exemplar with few interior elements (stones: 19) is left alone
    st2 = new_state(fidelity_suite().make_exemplar("stones"), Region.rectangle(200, 200), rng=3)
    fill(st2)
    c2 = np.array([[1.0, 1.5]])
    s2 = st2.src[: st2.n]
    G._prefer_unrepeated(st2, np.array([st2.n // 2]), np.array([[s2[0], s2[1]]]), c2, 0.0, 2.0)
    np.testing.assert_array_equal(c2, [[1.0, 1.5]])

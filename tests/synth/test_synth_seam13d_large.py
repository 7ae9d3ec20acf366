"""Issue 13 point 2 for three sizes: a seed far from every large element of the output
takes first the acceptable candidates whose copy brings a large element that can be
placed (``_grow._prefer_near_large``).

At 50x the exemplar's area the windows of the local fidelity map that failed mostly
failed nn[small>large]: patches of small and medium stones with no large one, which
growth never asked a large stone back into. ``python benchmarks/seam13d_diag.py
three_sizes 1,2,3,4,5,6,7,8``: failing windows 46 at 550ea99, 40 with the rule
at ``NEAR_LARGE_Q`` 0.9, 25 at 0.8 (the default since the optimisation's spread guard
came in: with it no variant row is lost at 0.8).

The 50x tests of this module live in ``test_synth_50x.py``, beside the others that
read the same draws."""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import _grow as G
from strew.synth import new_state


def test_rule_keeps_the_ratio_test_and_adds_nothing():
    """The reordering touches only candidates within the ratio test's bound, keeps d_0,
    and puts a candidate that brings a placeable large element first."""
    ex = fidelity_suite().make_exemplar("three_sizes")
    st = new_state(ex, Region.rectangle(400, 400), rng=1)
    prep = st.prep
    _, top, thr = G._near_large(prep)
    s0 = int(prep.source[prep.selected_elements][0])
    assert np.isfinite(thr[s0]) and 10.0 < thr[s0] < 40.0
    # one small element of the output, alone: far from every large one
    small = np.flatnonzero(prep.selected_elements & ~prep.void & (prep.size_class == 0))[0]
    big = np.flatnonzero(prep.selected_elements & ~prep.void & (prep.size_class == top[s0]))[:3]
    st.add(np.array([small]), np.array([[200.0, 200.0]]))
    st.add(big[:1], np.array([[200.0 + 3.0 * thr[s0], 200.0]]))  # one large element, far
    seeds = np.array([0])
    cands = np.array([[big[0], big[1], big[2], small]])
    costs = np.array([[1.0, 1.5, 100.0, 1.2]])
    # proposals: one slot per candidate; the 4th candidate's proposal is a large one
    # that passed the static checks, the others' are small ones
    out_ptr = np.arange(5)
    prop_ex = np.array([small, small, small, big[0]])
    prop_ok = np.ones(4, bool)
    c, slack = 2.0, 0.1
    got = costs.copy()
    G._prefer_near_large(st, seeds, cands, got, slack, c, prop_ok, prop_ex, out_ptr)
    assert got[0].min() == costs[0].min()  # d_0 stays
    assert got[0, 2] == 100.0  # beyond c d_0 + slack: untouched
    assert np.argmin(got[0]) == 3  # the large-bringing candidate first
    assert got[0, 0] < got[0, 1]  # the rest keep their order
    # a large proposal that failed the static checks brings nothing: no reordering
    got = costs.copy()
    prop_ok[3] = False
    G._prefer_near_large(st, seeds, cands, got, slack, c, prop_ok, prop_ex, out_ptr)
    assert np.array_equal(got, costs)
    # a large element of the output within the threshold: the seed is not far
    st.add(big[:1], np.array([[200.0 + 0.5 * thr[s0], 200.0]]))
    got = costs.copy()
    prop_ok[3] = True
    G._prefer_near_large(st, seeds, cands, got, slack, c, prop_ok, prop_ex, out_ptr)
    assert np.array_equal(got, costs)

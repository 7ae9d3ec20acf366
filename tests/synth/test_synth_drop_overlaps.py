"""synth's overlap rule as elements arrive, a library function (issue 15 point 6)."""

from __future__ import annotations

import numpy as np

from strew.io import load
from strew.metrics import overlaps
from strew.region import Region
from strew.synth import drop_new_overlaps, new_state
from strew._resources import example_path


def _state():
    ex = load(example_path("synth", "stones.json"))
    st = new_state(ex, Region.rectangle(200, 200))
    assert st.prep.overlap_free
    return st


def test_the_later_of_two_overlapping_new_elements_goes():
    st = _state()
    st.add(np.array([0]), np.array([[50.0, 50.0]]))
    n0 = st.n
    st.add(np.array([0, 0, 0]), np.array([[50.5, 50.0], [150.0, 150.0], [150.4, 150.0]]))
    gone = drop_new_overlaps(st, n0)
    assert gone == 2 and st.n == 2
    assert np.allclose(st.pos[: st.n], [[50.0, 50.0], [150.0, 150.0]])
    assert len(overlaps(st.elements())[0]) == 0


def test_a_new_element_on_a_fixed_one_goes_and_the_fixed_stays():
    st = _state()
    st.add(np.array([0]), np.array([[80.0, 80.0]]))
    fixed = st.elements(np.array([0]))
    st.remove(np.ones(st.n, bool))
    st.add(np.array([0, 0]), np.array([[80.3, 80.0], [20.0, 20.0]]))
    assert drop_new_overlaps(st, 0, fixed) == 1
    assert np.allclose(st.pos[: st.n], [[20.0, 20.0]])


def test_nothing_new_nothing_goes():
    st = _state()
    st.add(np.array([0, 0]), np.array([[50.0, 50.0], [50.2, 50.0]]))
    assert drop_new_overlaps(st, st.n) == 0 and st.n == 2

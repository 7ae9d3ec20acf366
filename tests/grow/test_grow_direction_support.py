"""The blocked count of agreeing directions equals the loop it replaced (issue 17)."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from strew.grow._analysis import DIRECTION_TOL, _direction_support


def _loop(cands, dirs):
    def diff(p, q):
        d = abs(p - q) % np.pi
        return min(d, np.pi - d)

    return [sum(1 for p in dirs if min(diff(c, p[0]), diff(c, p[1])) < DIRECTION_TOL) for c in cands]


angle = st.one_of(st.floats(0, np.pi, allow_nan=False), st.sampled_from([0.0, np.pi / 3, 2 * np.pi / 3, DIRECTION_TOL, np.pi - DIRECTION_TOL]))


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(angle, angle), min_size=1, max_size=40))
def test_support_counts_equal_the_python_loop(dirs):
    cands = [d for pair in dirs for d in pair]
    got = _direction_support(np.array(cands, float), np.array(dirs, float))
    assert list(got) == _loop(cands, dirs)

"""Proxy queries of the growth framework (issue 19.6): the bucket grid finds what a scan finds."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from strew.ornament import Circle
from strew.ornament._engine import _Placed


@settings(max_examples=25, deadline=None)
@given(
    n=st.integers(1, 700),
    seed=st.integers(0, 2**16),
    reach=st.floats(0.0, 40.0),
    bucket=st.floats(0.5, 10.0),
)
def test_near_matches_a_scan_of_every_proxy(n, seed, reach, bucket):
    rng = np.random.default_rng(seed)
    pl = _Placed(bucket=bucket)
    xy = rng.uniform(-50, 150, (n, 2))
    r = rng.uniform(0, 6, n)
    for k in range(n):
        pl.add(Circle().set(xy[k], float(r[k])), owner=k)
    for cx, cy in rng.uniform(-60, 160, (8, 2)):
        got = pl.near(float(cx), float(cy), reach)
        d = np.hypot(xy[:, 0] - cx, xy[:, 1] - cy)
        want = np.flatnonzero(d <= r + reach)
        # the same indices, sorted (the boundary case d == r + reach is decided by the
        # same squared test on both paths)
        far = np.abs(d - (r + reach)) > 1e-9
        assert np.array_equal(np.intersect1d(got, np.flatnonzero(far)), np.intersect1d(want, np.flatnonzero(far)))
        assert np.all(np.diff(got) > 0)

"""Progress and cancellation plumbing shared by long-running functions."""

from __future__ import annotations

import pytest

from strew import Cancelled
from strew._progress import Reporter
from strew._rng import as_rng


def test_reporter_calls_back_and_finishes():
    seen = []
    rep = Reporter(lambda d, t, m: seen.append((d, t, m)), total=10, message="work", interval=0.0)
    for i in range(10):
        rep.tick(i)
    rep.done()
    assert seen[0] == (0, 10, "work") and seen[-1] == (10, 10, "work")
    assert len(seen) == 11


def test_reporter_throttles():
    seen = []
    rep = Reporter(lambda d, t, m: seen.append(d), interval=3600)
    for i in range(1000):
        rep.tick(i)
    assert seen == [0]


def test_cancel_raises_at_next_tick():
    flag = {"stop": False}
    rep = Reporter(None, lambda: flag["stop"], interval=0.0)
    rep.tick(1)
    flag["stop"] = True
    with pytest.raises(Cancelled):
        rep.tick(2)


def test_as_rng_normalises():
    g = as_rng(5)
    assert as_rng(g) is g
    assert as_rng(5).random() == as_rng(5).random()
    with pytest.raises(TypeError, match="rng must be"):
        as_rng("five")

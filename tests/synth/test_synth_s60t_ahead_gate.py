"""Issue 13 point 1 (helper s60t): the ownership of ``_grow._top_ahead`` acts only on an
excess of the largest class in the output's closed area beyond the count's Poisson noise
(``_grow.OWN_AHEAD_Z`` standard errors), not on one stone over the slack in the first
small closed area. --varied three sizes 140:50:18 at ratios 1:2.5:5 (``benchmarks/
_variants.py`` VARIED set p0, variant seed 32) ends with its large stones under their
density (0.93 of it), yet with the slack alone (s46t) growth owned them in one early call
(17 large stones against 16.0 asked, one frame and a third closed) at seeds 1, 3, 4 and 6:
s46t's branch lost seed 1 (nn[small>large] 0.127 / 0.12)."""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

import strew.synth._grow as G
from strew import Region
from strew._fidelity import fidelity
from strew.metrics import overlaps
from strew.synth import synthesize

P0 = {"ratios": (1.0, 2.5, 5.0), "counts": (140, 50, 18)}


@pytest.mark.slow
def test_no_ownership_on_noise_where_large_stones_are_not_ahead(monkeypatch):
    ex = fidelity_suite().make_exemplar("three_sizes", rng=32, **P0)
    orig = G._top_ahead
    calls: list[bool] = []

    def logged(state):
        out = orig(state)
        calls.append(bool(out.any()))
        return out

    monkeypatch.setattr(G, "_top_ahead", logged)  # (main has no _top_ahead: fails there)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1, measure=False)
    # the rule is evaluated here (the exemplar passes _own_setup's gates) ...
    assert len(calls) > 5, len(calls)
    # ... but never owns: every closed-area count stays within one standard error
    # (slack alone, s46t: acted once, 17 against 16.0)
    assert not any(calls), int(np.sum(calls))
    assert len(overlaps(out)[0]) == 0
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, [(k, m.value, m.tolerance) for k, m in rep.metrics.items() if m.applicable and not m.passed]


def test_gate_bound_is_slack_plus_noise_margin():
    # the numbers of the calls above and of three sizes 60:60:26 (p4s27), whose large
    # stones run ahead (1.24 of their density after growth on main)
    def acts(have, want):
        return have > G._ahead_bound(want)

    assert not acts(17, 16.0)  # p0s32's first closed area: noise
    assert acts(31, 23.7)  # p4s27 seed 1's first: 1.5 standard errors
    assert acts(221, 195.7)  # p4s27 later: 1.8 standard errors
    # where many are asked the slack no longer decides alone (s63t: the margin is added to
    # it; s60t took the larger of the two, here 1050)
    assert G._ahead_bound(1000.0) == pytest.approx(G.OWN_AHEAD_SLACK * 1000.0 + G.OWN_AHEAD_Z * 1000.0**0.5)
    # and the margin is the count's standard error for the exemplar's dispersion
    assert G._ahead_bound(1000.0, 0.25) == pytest.approx(G.OWN_AHEAD_SLACK * 1000.0 + 0.5 * G.OWN_AHEAD_Z * 1000.0**0.5)

"""Issue 13 point 2 for three sizes: near a seed whose surroundings stray from the
output's shares of the size classes, the candidates that pass the ratio test are taken
in an order that brings the missing classes (``_grow._prefer_balanced``).

At 50x the exemplar's area the windows of the local fidelity map that failed held
36-47 medium and 31-40 large stones against window means of about 62 and 30: k-coherence
kept copying a medium-poor part of the exemplar (65 medium, 26 large stones: 2.5 medium
stones per large one). ``python benchmarks/synth.py --seams --only three_sizes --seeds
1,2,3,4``: failing windows 9 / 11 / 5 / 18 at 7c83aee, 9 / 5 / 9 / 1 with it.
"""

from __future__ import annotations

import numpy as np
import pytest

from strew import Region
from strew.synth import fill, new_state, synthesize
from strew.synth import _grow as G

from strew_testing import fidelity_suite


def _windows(out, side: float, size: float) -> np.ndarray:
    """(w, kinds) int: counts per kind in square windows of the exemplar's side, stepped
    by half a side, over the output's interior (a tenth of the side off each edge)."""
    xy = out.xy
    k = np.asarray(out["kind"])
    nk = int(k.max()) + 1
    m0 = 0.1 * size
    rows = []
    for wx in np.arange(m0, size - m0 - side + 1e-9, side / 2):
        for wy in np.arange(m0, size - m0 - side + 1e-9, side / 2):
            m = (xy[:, 0] >= wx) & (xy[:, 0] < wx + side) & (xy[:, 1] >= wy) & (xy[:, 1] < wy + side)
            rows.append(np.bincount(k[m], minlength=nk))
    return np.array(rows)


@pytest.mark.slow
def test_three_sizes_50x_medium_count_spreads_less_over_windows():
    """The medium stones' count per window of the exemplar's size spreads less: its
    standard deviation over the windows, seeds 1-4 (python, this test's ``_windows``):
    7.78-8.88 at 7c83aee, 7.62-8.34 with the kind-whole size classes alone (sizes13),
    6.10-7.29 with the rule alone, 6.18-7.30 with both (the integrated tree). Seed 1.

    (The helper's first test asked every window of seed 3 for 1.2 medium stones per
    large one; seeds 1-4 give 1.25 / 1.27 / 1.08 / 1.24 on the integrated tree against
    1.16 / 1.10 / 0.90 / 1.18 at 7c83aee: better, but one seed's poorest window is too
    noisy a verdict, so the spread over all windows is asserted instead.)"""
    ex = fidelity_suite().make_exemplar("three_sizes")
    x0, y0, x1, y1 = ex.region.bounds
    side = x1 - x0
    size = 7.07 * side
    out = synthesize(ex, Region.rectangle(size, size), rng=1, measure=False)
    names = list(out.shapes)
    med, lar = names.index("medium"), names.index("large")
    w = _windows(out, side, size)
    assert len(w) >= 90
    assert np.all(w[:, lar] > 0)
    assert w[:, med].std() <= 7.5, w[:, med].std()


@pytest.mark.slow
def test_balance_keeps_ratio_bound(monkeypatch):
    """The reordering only touches candidates that pass the ratio test: d_0 stays the
    least cost, the bound ``c d_0 + slack`` is unchanged, candidates beyond it keep their
    costs; where the seeds' surroundings hold small stones only, the candidates tried
    first bring more of the larger classes than the best matches did."""
    ex = fidelity_suite().make_exemplar("three_sizes")
    x0, y0, x1, y1 = ex.region.bounds
    side = x1 - x0
    size = 3.0 * side
    st = new_state(ex, Region.rectangle(size, size), rng=3)
    fill(st)
    prep = st.prep
    monkeypatch.setattr(G, "BALANCE_RADIUS", 0.3)
    vis = np.flatnonzero(~prep.void[st.src])
    d = np.hypot(*(st.pos[vis] - 0.5 * size).T)
    seeds = vis[d < 0.1 * side]
    assert len(seeds) >= 5
    cands = prep.co[st.origin[seeds]]
    rng = np.random.default_rng(0)
    costs = np.where(cands >= 0, rng.uniform(1.0, 4.0, cands.shape), np.inf)
    before = costs.copy()
    slack = np.full(len(seeds), 0.5)
    c = 2.0
    # the surroundings of the seeds (0.45 of a side about the centre) made small stones
    saved = st._src[: st.n].copy()
    small = np.flatnonzero((prep.size_class == 0) & ~prep.void)[0]
    hide = vis[(d < 0.45 * side)]
    hide = hide[~np.isin(hide, seeds)]
    try:
        st._src[hide] = small
        G._prefer_balanced(st, seeds, cands, costs, slack, c)
    finally:
        st._src[: st.n] = saved
    fin = np.isfinite(before)
    d0 = np.where(fin, before, np.inf).min(axis=1)
    bound = c * d0 + slack
    inside = fin & (before <= bound[:, None])
    assert np.array_equal(np.isfinite(costs), fin)
    assert np.array_equal(np.where(fin, costs, np.inf).min(axis=1), d0)
    assert np.array_equal(costs[~inside], before[~inside])
    assert np.all(costs[inside] <= np.broadcast_to(bound[:, None], costs.shape)[inside])
    changed = np.flatnonzero((costs != before).any(axis=1))
    assert len(changed) >= len(seeds) // 2, "seeds among small stones only were left as they were"
    mix = G._class_mix(prep)
    first = cands[changed, np.argmin(costs[changed], axis=1)]
    best = cands[changed, np.argmin(before[changed], axis=1)]
    assert mix[first, 1:].sum(axis=1).mean() > mix[best, 1:].sum(axis=1).mean()

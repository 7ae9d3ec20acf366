"""Issue 13 point 2 on three sizes 1:2:4 at 50x the exemplar's area: the tests that read
the same draws (``strew_testing.synth_at_50x``, seeds 1, 2, 3 and 8) live in this one
module, so that under ``pytest -n --dist loadfile`` one worker grows each draw once
(they were spread over four modules, and each worker grew its own: nine draws for four).
Each test's history is kept beside it."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from strew_testing import assert_no_window_fails_at_50x, synth_at_50x

# --- from test_synth_free_support.py (free space as the consensus of the k neighbourhoods)

@pytest.mark.slow
def test_three_sizes_at_50x_has_few_failing_windows():
    """Issue 13 point 2 on three sizes 1:2:4 at 50x the exemplar's area (seeds 1-3): the
    local fidelity map's failing windows (patches poor in medium or large stones) average
    under 7 %. With the yield window at 2 iterations they were 9.5 / 6.5 / 9.5 % (mean
    8.5 %), at 3 they are 5.3 / 6.5 / 3.0 %; none is yet free of them."""
    shares = []
    for seed in (1, 2, 3):
        rep = synth_at_50x("three_sizes", seed)[3]
        assert rep.faithful, rep.failures
        score = np.asarray(rep.local["score"], float)
        score = score[np.isfinite(score)]
        assert len(score) > 100
        shares.append(float(np.mean(score > 1.0)))
    assert np.mean(shares) < 0.07, shares


# --- from test_synth_seam13f_mix.py
# Issue 13 point 2 for three sizes: the windows of the local fidelity map at 50x the
# exemplar's area hold like mixes of the size classes (``_grow._prefer_balanced`` with a
# disc of half the exemplar's side and z 0.75).
#
# What still failed at 50x were patches of small and medium stones about half a window
# wide with too few large ones (nn[small>large]); a disc of a whole side diluted them and
# the binomial error hid them. ``python benchmarks/seam13f_diag.py --seeds 1,2,3,4,5,6,7,8``
# prints, per seed, the windows' standard deviation of each class's count: medium stones
# 5.7-6.5 at e1d86dd, 4.4-5.6 now (failing windows 18 -> 15 over the eight seeds,
# 9 -> 6 over seeds 1-4).


def _window_counts(seed: int) -> np.ndarray:
    """(windows, kinds): the output's elements by kind in each window of the local
    fidelity map (those with a score), three sizes at 50x the exemplar's area."""
    _, out, _, rep = synth_at_50x("three_sizes", seed)
    loc = rep.local
    score = np.asarray(loc["score"], float)
    side, step = loc["window"], loc["step"]
    kind = np.asarray(out.kind)
    rows = []
    for (i, j), s in np.ndenumerate(score):
        if not np.isfinite(s):
            continue
        wx, wy = loc["x0"] + j * step, loc["y0"] + i * step
        m = (out.x >= wx) & (out.x < wx + side) & (out.y >= wy) & (out.y < wy + side)
        rows.append(np.bincount(kind[m], minlength=len(out.kinds)))
    assert list(out.kinds) == ["small", "medium", "large"]
    return np.array(rows)


@pytest.mark.slow
def test_three_sizes_50x_windows_hold_like_mixes():
    # the windows' sd of the medium count, seeds 2 / 3: 6.03 / 6.49 at e1d86dd, 5.01 /
    # 4.90 now (eight seeds: 5.7-6.5 before, 4.4-5.6 now); their mean stays near 58
    sds, means = [], []
    for seed in (2, 3):
        c = _window_counts(seed)
        assert len(c) > 150
        sds.append(c[:, 1].std())
        means.append(c[:, 1].mean())
    assert float(np.mean(sds)) < 5.6, f"medium count sd over windows {np.round(sds, 2)}"
    assert 52.0 < float(np.mean(means)) < 64.0


# --- from test_synth_seam13g_owed.py
# Issue 13 point 2 for three sizes (helper seam13g): a large copy farther from every
# large stone of the output than the exemplar's spacing of its large stones (its 0.9
# quantile) is owed where it stands (``_grow.owed_here``) and displaces young small stones,
# so fronts that grew a stretch without a large stone get one back.
#
# ``python benchmarks/seam13f_diag.py --seeds 1,...,8`` (then 9-16): failing windows of
# the local map at 50x the area 15 / 11 at a12a5fb, 6 / 4 now; ``python
# benchmarks/seam13g_gaps.py``: small stones farther from every large one than the
# exemplar's 95th percentile of that distance, seeds 1-8, 0.0758-0.0838 before,
# 0.0694-0.0781 now.


def _far_share(ex, out, region) -> float:
    """Share of the output's small stones (away from the canvas edge) whose nearest large
    stone is farther than the exemplar's 95th percentile of that distance."""
    kinds = list(ex.kinds)
    s, l = kinds.index("small"), kinds.index("large")
    ek = np.asarray(ex.kind)
    xy = ex.xy[ek == s]
    d = cKDTree(ex.xy[ek == l]).query(xy)[0]
    x0, y0, x1, y1 = ex.region.bounds
    d = d[d <= np.minimum.reduce([xy[:, 0] - x0, xy[:, 1] - y0, x1 - xy[:, 0], y1 - xy[:, 1]])]
    thr, reach = np.quantile(d, 0.95), d.max()
    ok = np.asarray(out.kind)
    sm = out.xy[ok == s]
    x0, y0, x1, y1 = region.bounds
    sm = sm[np.minimum.reduce([sm[:, 0] - x0, sm[:, 1] - y0, x1 - sm[:, 0], y1 - sm[:, 1]]) >= reach]
    return float(np.mean(cKDTree(out.xy[ok == l]).query(sm)[0] > thr))


@pytest.mark.slow
def test_three_sizes_50x_fewer_small_stones_far_from_large():
    # seeds 2 / 8: 0.0812 / 0.0831 at a12a5fb, 0.0696 / 0.0747 now (0.05 in the exemplar;
    # seeds 1-8: 0.0758-0.0838 before, 0.0694-0.0781 now, lower on every seed)
    shares = []
    for seed in (2, 8):
        ex, out, region, _ = synth_at_50x("three_sizes", seed)
        shares.append(_far_share(ex, out, region))
    assert float(np.mean(shares)) < 0.076, np.round(shares, 4)


@pytest.mark.slow
def test_three_sizes_50x_seed_8_no_failing_window():
    # 5 failing windows at a12a5fb (nn[small>large] 1.03-1.14, two edge empty_circle)
    assert_no_window_fails_at_50x("three_sizes", 8)


# --- from test_synth_seam13d_large.py
# Issue 13 point 2 for three sizes: a seed far from every large element of the output
# takes first the acceptable candidates whose copy brings a large element that can be
# placed (``_grow._prefer_near_large``).
#
# At 50x the exemplar's area the windows of the local fidelity map that failed mostly
# failed nn[small>large]: patches of small and medium stones with no large one, which
# growth never asked a large stone back into. ``python benchmarks/seam13d_diag.py
# three_sizes 1,2,3,4,5,6,7,8``: failing windows 46 at 550ea99, 40 with the rule
# at ``NEAR_LARGE_Q`` 0.9, 25 at 0.8 (the default since the optimisation's spread guard
# came in: with it no variant row is lost at 0.8).


def _nn_small_large_windows(seed: int) -> tuple[int, int]:
    """(windows whose worst metric is nn[small>large] and fails, windows) of the local
    fidelity map for three sizes at 50x the exemplar's area."""
    _, _, _, rep = synth_at_50x("three_sizes", seed)
    loc = rep.local
    score = np.asarray(loc["score"], float)
    worst = np.asarray(loc["worst_metric"], dtype=object)
    ok = np.isfinite(score)
    return int(np.sum(ok & (score > 1.0) & (worst == "nn[small>large]"))), int(ok.sum())


@pytest.mark.slow
def test_three_sizes_50x_no_large_poor_windows():
    # windows failing nn[small>large] (of 169 per seed; python benchmarks/synth.py
    # --seams --only three_sizes --seeds 1,2,3,4), seeds 1 / 2 / 3 / 4: 550ea99
    # 1 / 10 / 6 / 3, now 4 / 0 / 2 / 2. One seed's count moves by a few windows with
    # any change to the stream (the helper's first form, seed 3 <= 1, failed the
    # integrated tree with 2), so two seeds are pooled: 16 at 550ea99, 2 now.
    bad, windows = 0, 0
    for seed in (2, 3):
        b, w = _nn_small_large_windows(seed)
        bad += b
        windows += w
    assert windows > 200
    assert bad <= 5, f"{bad} of {windows} windows fail nn[small>large]"

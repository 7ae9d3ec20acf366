"""Issue 13 point 2 for three sizes: the windows of the local fidelity map at 50x the
exemplar's area hold like mixes of the size classes (``_grow._prefer_balanced`` with a
disc of half the exemplar's side and z 0.75).

What still failed at 50x were patches of small and medium stones about half a window
wide with too few large ones (nn[small>large]); a disc of a whole side diluted them and
the binomial error hid them. ``python benchmarks/seam13f_diag.py --seeds 1,2,3,4,5,6,7,8``
prints, per seed, the windows' standard deviation of each class's count: medium stones
5.7-6.5 at e1d86dd, 4.4-5.6 now (failing windows 18 -> 15 over the eight seeds,
9 -> 6 over seeds 1-4).
"""

from __future__ import annotations

import numpy as np
import pytest

from strew_testing import synth_at_50x


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


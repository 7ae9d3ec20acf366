"""Issue 13 point 2 (helper syn13w): where an output window holds few large stones, the
stones far from them are not smallest ones in a greater share than in the exemplar
(``_farmix.trade_far_small``)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize


def _far_excess(ex, out) -> float:
    """Over the output's small stones beyond the exemplar's 70th percentile small-to-large
    nearest distance: the mean, in a disc of the exemplar's area around each, of the far
    small stones beyond the exemplar's far small : far medium ratio (times the disc's far
    medium stones, plus one)."""

    def split(arr):
        names = np.asarray(arr.kind_names)
        xy = np.asarray(arr.xy)
        return xy[names == "small"], xy[names == "medium"], xy[names == "large"]

    es, em, el = split(ex)
    tl = cKDTree(el)
    far = float(np.quantile(tl.query(es)[0], 0.7))
    ratio = np.count_nonzero(tl.query(es)[0] > far) / np.count_nonzero(tl.query(em)[0] > far)
    os_, om, ol = split(out)
    tl = cKDTree(ol)
    fs, fm = os_[tl.query(os_)[0] > far], om[tl.query(om)[0] > far]
    x0, y0, x1, y1 = ex.region.bounds
    wr = np.sqrt((x1 - x0) * (y1 - y0) / np.pi)
    ns = np.array([len(v) for v in cKDTree(fs).query_ball_point(fs, wr)])
    nm = np.array([len(v) for v in cKDTree(fm).query_ball_point(fs, wr)])
    return float(np.mean(np.maximum(ns - ratio * (nm + 1), 0.0)))


def test_far_small_stones_traded_for_medium_ones():
    # three sizes at 2x the exemplar's side, seeds 1/2/3: at 4882d93 1.476/0.79/2.656,
    # now 0.900/0.79/1.101 (at 50x the area, seeds 1-8, the local fidelity map's failing
    # windows 3 -> 1, benchmarks/seam13n_windows.py)
    ex = fidelity_suite().make_exemplar("three_sizes")
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    got = _far_excess(ex, out)
    assert got <= 1.2, got

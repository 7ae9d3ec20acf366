"""Issue 13 point 1 (helper syn13u): lone pebbles of a two-size exemplar whose generator
threw them to saturation get a partner copied from the exemplar's pairs, until the
output's share of lone pebbles is the exemplar's (``_pebbles.fill_partners``)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize


def _lone_share(arr, reach: float, margin: float) -> float:
    """The share of pebbles at least ``margin`` inside the frame with no other pebble
    within ``reach``."""
    xy = np.asarray(arr.xy)
    p = xy[np.asarray(arr.kind_names) == "pebble"]
    x0, y0, x1, y1 = arr.region.bounds
    inn = (p[:, 0] > x0 + margin) & (p[:, 0] < x1 - margin) & (p[:, 1] > y0 + margin) & (p[:, 1] < y1 - margin)
    d = cKDTree(p).query(p[inn], k=2)[0][:, 1]
    return float(np.mean(d > reach))


@pytest.mark.slow  # 3.5 s on the loaded machine
def test_lone_saturated_pebbles_get_a_partner():
    # two sizes ratio 0.65, 30 stones and 150 pebbles asked, variant seed 8
    # (grow_variants.HARDER["two_sizes"][11]): the generator fits 30 and 50, pebbles in
    # groups in the gaps. Lone: no pebble within the exemplar's 90th percentile of the
    # pebbles' nearest-pebble distance (exemplar 0.11 away from the frame). At a2b29a1,
    # seeds 1 and 2 at 2x: 0.242 and 0.291 (mean 0.267); now 0.198 and 0.218 (0.208)
    ex = fidelity_suite().make_exemplar("two_sizes", rng=8, ratio=0.65, n_large=30, n_small=150)
    x0, y0, x1, y1 = ex.region.bounds
    margin = 24.0  # two of the largest stones' radii
    p = np.asarray(ex.xy)[np.asarray(ex.kind_names) == "pebble"]
    d = cKDTree(p).query(p, k=2)[0][:, 1]
    inn = (p[:, 0] > x0 + margin) & (p[:, 0] < x1 - margin) & (p[:, 1] > y0 + margin) & (p[:, 1] < y1 - margin)
    reach = float(np.quantile(d[inn], 0.9))
    lone = []
    for seed in (1, 2):
        out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed, measure=False)
        lone.append(_lone_share(out, reach, margin))
    assert np.mean(lone) <= 0.24, lone

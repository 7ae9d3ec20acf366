"""Issue 13 point 2 (helper syn13v): an exemplar's smallest stones stand snug against
its largest ones in the output as in the exemplar (``_shell.fill_beside_largest``)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize


def _shell_density(arr, lo: float, hi: float, margin: float) -> float:
    """Small stones per unit area among the points whose nearest large stone's centre
    lies between ``lo`` and ``hi`` (a 1-unit grid, away from the frame by ``margin``)."""
    names = np.asarray(arr.kind_names)
    xy = np.asarray(arr.xy)
    x0, y0, x1, y1 = arr.region.bounds
    tree = cKDTree(xy[names == "large"])
    g = np.mgrid[x0 + margin : x1 - margin : 1.0, y0 + margin : y1 - margin : 1.0].reshape(2, -1).T
    dg = tree.query(g)[0]
    sm = xy[names == "small"]
    sm = sm[(sm[:, 0] >= x0 + margin) & (sm[:, 0] < x1 - margin) & (sm[:, 1] >= y0 + margin) & (sm[:, 1] < y1 - margin)]
    ds = tree.query(sm)[0]
    return float(np.count_nonzero((ds >= lo) & (ds < hi))) / float(np.count_nonzero((dg >= lo) & (dg < hi)))


@pytest.mark.slow
def test_small_stones_snug_against_large_ones():
    # three sizes: small stones touching a large one (nearest large centre 14-16 away,
    # contact is at about 14.3) per unit area of that shell, output / exemplar, at 2x
    # the exemplar's side. At a2b29a1 seeds 1-4: 0.756, 0.894, 0.853, 0.802 (12x the
    # area, seeds 1-2: 0.83, 0.87; the exemplar's generator at 50x: 1.07); now 1.072,
    # 1.138, 0.967, 1.002
    ex = fidelity_suite().make_exemplar("three_sizes")
    margin = 2.0 * float(np.max(ex.radii))
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    got = _shell_density(out, 14.0, 16.0, margin) / _shell_density(ex, 14.0, 16.0, margin)
    assert got >= 0.93, got

"""One kind with scattered sizes: elements keep the reference's gap for their sizes
(issue 14 point 1, stones drawn with seed 1: nn[stone>stone] failed on every seed).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def test_stones_of_a_variant_nobody_tuned_on_keep_their_gap():
    # stones 1 +- 0.2 in scale: the outlines fit closer than the reference's bounding
    # discs ever come, and two small stones came closer than any pair in the reference.
    # At 2.2x, nn[stone>stone] was 0.036 of a tolerance of 0.05 (0.055 at 3.5x) and is
    # 0.009 now. Placement keeps every pair at 0.95 of the reference's smallest gap for
    # their two sizes or more; the relaxation (§5.5) then moves a few a little closer
    # (the 5 % quantile of the ratio was 0.89 of the reference's smallest, now 1.04)
    ex = fidelity_suite().make_exemplar("stones", rng=1)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2.2 * (x1 - x0), 2.2 * (y1 - y0))
    out = grow(ex, region=region, rng=1)
    assert len(out) >= 4 * len(ex)
    m = fidelity(ex, out, eq5=False, local=False).metrics["nn[stone>stone]"]
    assert m.value <= 0.5 * m.tolerance, m
    r = ex.shapes["stone"].radius

    def ratios(arr):
        d, q = cKDTree(arr.xy).query(arr.xy, 2)
        return d[:, 1] / (r * (arr.scale + arr.scale[q[:, 1]]))

    least = ratios(ex).min()
    assert np.quantile(ratios(out), 0.05) >= 0.95 * least
    unrelaxed = grow(ex, region=region, rng=1, relax=False)
    assert ratios(unrelaxed).min() >= 0.95 * least * (1 - 1e-9)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))

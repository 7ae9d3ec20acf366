"""Several sizes: a ring slot of the largest kind is not lost to seeds of smaller kinds
(§5.1 after Wong: larger elements first, smaller ones fill around them; issue 14 point 1).
"""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow


@pytest.mark.slow
def test_large_stones_come_as_densely_as_in_the_reference_interior():
    # three sizes 1:2:4: the exemplar's large stones lie inside its frame less 1.1 of
    # their radius (the generator's dart box); grown at 2.2x, the share of that interior
    # density kept away from the region's edge was 0.83-0.91 (mean 0.867, seeds 1-3)
    # while large slots were merged into small seeds, and is 0.86-0.97 (mean 0.917) now
    ex = fidelity_suite().make_exemplar("three_sizes")
    x0, _, x1, _ = ex.region.bounds
    w = x1 - x0
    big = ex.kinds.index("large")
    m = 1.1 * ex.shapes["large"].radius
    ref = float((ex.kind == big).sum()) / (w - 2 * m) ** 2
    side = 2.2 * w
    region = Region.rectangle(side, side)
    kept = []
    for seed in (1, 2, 3):
        out = grow(ex, region=region, rng=seed)
        assert len(out) >= 4 * len(ex)
        inner = region.distance_to_boundary(out.xy) > 3 * m
        kept.append(float(((out.kind == big) & inner).sum()) / (side - 6 * m) ** 2 / ref)
    assert np.mean(kept) >= 0.89, kept
    assert min(kept) >= 0.8, kept

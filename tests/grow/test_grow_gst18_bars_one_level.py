"""Long thin bars are no larger a kind than dots of about their area (issue 14 point 1,
held-out exemplars: ``grow_variants.py --varied-variants 9,10``, stripes p2s10 failed on
every seed: bars over-produced, dots too sparse).

The EDGE set "wide near-vertical bands, long bars" draws dots of radius 2.5 and bars of
12 x 2.5: the bars' bounding radius (6.1) is 2.45 times the dots', their equal-area radius
only 1.25 times. :func:`size_priority` put the bars a size level above the dots (now
:func:`size_levels` for growth's rules), and the
size-level rules of growth over-produced them.
"""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow, size_priority
from strew.grow._analysis import size_levels


def _exemplar():
    return fidelity_suite().make_exemplar("stripes", rng=10, band=45.0, angle=1.4, dot=2.5, bar=(12.0, 2.5))


def _inner_density(arr, kind, margin):
    x0, y0, x1, y1 = arr.region.bounds
    m = (arr.x > x0 + margin) & (arr.x < x1 - margin) & (arr.y > y0 + margin) & (arr.y < y1 - margin)
    return np.count_nonzero(m & (arr.kind == arr.kinds.index(kind))) / ((x1 - x0 - 2 * margin) * (y1 - y0 - 2 * margin))


def test_bars_and_dots_of_like_area_are_one_size_level():
    ex = _exemplar()
    assert size_levels(ex) == {}
    assert size_priority(ex) == {"dot": 0.0, "bar": 1.0}  # priorities keep bounding radii
    # discs SIZE_STEP apart stay two levels (the suite's three sizes, 1 : 1.5 : 3)
    ex3 = fidelity_suite().make_exemplar("three_sizes", rng=7, ratios=(1.0, 1.5, 3.0), counts=(150, 80, 30))
    assert size_levels(ex3) == size_priority(ex3) == {"small": 0.0, "medium": 1.0, "large": 2.0}


@pytest.mark.slow
def test_bars_not_over_produced():
    # the bars' share against the dots', output over exemplar (inner densities), seeds
    # 1-3 at 3x the exemplar: at 091af61 1.25, 1.16, 1.37 (mean 1.26; bars 1.16-1.25 of
    # the exemplar's density, dots 0.91-1.0); with one level 0.99, 1.02, 1.07 (mean 1.03)
    ex = _exemplar()
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.0 * (x1 - x0), 3.0 * (y1 - y0))
    ratios = []
    for seed in (1, 2, 3):
        out = grow(ex, region=region, rng=seed)
        assert len(out) >= 6 * len(ex)
        bar = _inner_density(out, "bar", 10.0) / _inner_density(ex, "bar", 0.0)
        dot = _inner_density(out, "dot", 10.0) / _inner_density(ex, "dot", 0.0)
        ratios.append(bar / dot)
    assert float(np.mean(ratios)) <= 1.12, ratios

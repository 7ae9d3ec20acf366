"""Issue 13 point 1 (helper ssz): kinds of a three-size ladder about 1.5 apart in radius are
separate size classes at every draw.

A kind's stones are one outline scaled 0.9-1.1, so kinds drawn 1 : 3 : 4.5 apart (--harder
three_sizes h11) have medians of area radius 1.44-1.64 apart; at a kind step of 1.5 the
medium and large stones fell into one class at variant seeds 11 and 13, were placed
together, and the medium took the large stones' places (large 0.85-0.90x their density,
medium 1.20-1.29x; nn[medium>large] failing at 4 of 6 seeds of h11s11 at 3.5x)."""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize
from strew.synth._prepare import area_radii, size_classes

LADDER = dict(ratios=(1.0, 3.0, 4.5), counts=(80, 80, 30))


def _classes(ex):
    r = np.array([ex.shapes[k].radius for k in ex.kinds])[ex.kind] * np.abs(np.asarray(ex.scale, float))
    cls = size_classes(r, area_radii(ex.with_columns(radius=r)), ex.kind)
    return [sorted(set(cls[ex.kind == k].tolist())) for k in range(len(ex.kinds))]


@pytest.mark.parametrize("variant", [11, 13])
def test_ladder_kinds_are_three_classes(variant):
    # main (AREA_STEP 1.5 for kinds): [[0], [1], [1]] at both variants (medians 1.46 / 1.445 apart)
    ex = fidelity_suite().make_exemplar("three_sizes", rng=variant, **LADDER)
    assert list(ex.kinds) == ["small", "medium", "large"]
    assert _classes(ex) == [[0], [1], [2]]


@pytest.mark.slow
@pytest.mark.parametrize("variant", [11, 13])
def test_ladder_large_stones_keep_their_density(variant):
    # 2x the exemplar's side, seed 1; the fidelity metric's density over the exemplar's.
    # main: medium 1.219 / 1.224, large 0.901 / 0.884 (variant 11 / 13); split: medium
    # 0.900 / 0.928, large 0.962 / 1.048
    from strew.metrics import fidelity

    ex = fidelity_suite().make_exemplar("three_sizes", rng=variant, **LADDER)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    rep = fidelity(ex, out, eq5=False, local=False)
    ratio = {k: rep.metrics[f"density[{k}]"].result / rep.metrics[f"density[{k}]"].exemplar for k in ex.kinds}
    assert abs(ratio["medium"] - 1.0) <= 0.15, ratio
    assert ratio["large"] >= 0.92, ratio


@pytest.mark.slow
@pytest.mark.parametrize("variant", [9, 13])
def test_a_handful_of_large_stones_is_not_doubled(variant):
    # three sizes 200:60:5 (--harder h13): two standard errors are 0.89 of the large
    # stones' share, and owed_classes let them grow toward 1.9x it. 2x the exemplar's
    # side, seed 1, large stones per area over the exemplar's: main 1.55 / 1.60 (variant
    # 9 / 13); with no margin for so rare a largest class (LARGEST_RARE) 1.25 / 0.95
    ex = fidelity_suite().make_exemplar("three_sizes", rng=variant, counts=(200, 60, 5))
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    assert list(out.kinds) == ["small", "medium", "large"]
    per_area = np.bincount(out.kind, minlength=3) / 4.0 / np.bincount(ex.kind, minlength=3)
    assert per_area[2] <= 1.35, per_area
    assert per_area[0] >= 0.85 and per_area[1] >= 0.85, per_area

"""Issue 13 point 1 (helper tsz13m): small stones do not keep the places of a saturated
medium kind the output is short of (``_displace.fill_displaced``)."""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.metrics import overlaps
from strew.synth import synthesize


def _three_sizes():
    # grow_variants.HARDER["three_sizes"][4], variant seed 7 (h4s7): medium stones thrown
    # to saturation between 15 large ones
    return fidelity_suite().make_exemplar("three_sizes", rng=7, ratios=(1.0, 2.5, 4.0), counts=(100, 100, 15))


def _density(arr, name, box, margin):
    x0, y0, x1, y1 = box
    xy = arr.xy[np.asarray(arr.kind_names) == name]
    inside = (xy[:, 0] > x0 + margin) & (xy[:, 0] < x1 - margin) & (xy[:, 1] > y0 + margin) & (xy[:, 1] < y1 - margin)
    return inside.sum() / ((x1 - x0 - 2 * margin) * (y1 - y0 - 2 * margin))


def test_displaced_only_for_one_saturated_exemplar():
    from strew.synth._api import as_selection
    from strew.synth._displace import _inner_density
    from strew.synth._prepare import prepare

    ex = _three_sizes()
    prep = prepare(as_selection(ex, None))
    d = _inner_density(prep, 20.0)
    kinds = list(ex.kinds)
    # away from the frame (where the largest stones cannot stand) each kind's count per area
    assert np.all(np.isfinite(d)) and np.all(d > 0)
    x0, y0, x1, y1 = ex.region.bounds
    assert d[kinds.index("large")] > 15 / ((x1 - x0) * (y1 - y0))


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2])
def test_small_stones_give_back_medium_places(seed):
    ex = _three_sizes()
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = synthesize(ex, region, rng=seed, measure=False)
    m = 25.0
    ratio = {k: _density(out, k, region.geometry.bounds, m) / _density(ex, k, ex.region.bounds, m) for k in ("small", "medium")}
    # at 61d61c7: medium stones 0.81x (seed 1) and 0.76x (seed 2) their exemplar density
    # here, small ones 1.24x (in the places medium copies could not take); with
    # fill_displaced 0.87x / 0.84x and 1.08x / 1.07x
    assert ratio["medium"] >= 0.83, ratio
    assert ratio["small"] <= 1.15, ratio
    assert len(overlaps(out)[0]) == 0

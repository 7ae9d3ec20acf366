"""Issue 13 point 1 (helper s25t): a largest size class of about ten stones among three
sizes is owed only below the exemplar's share (``_grow.LARGEST_RARE`` 0.6).

Two standard errors of ten large stones among 330 (--harder three_sizes h0, 300:20:10) or
260 (h8, 100:150:10) are 0.62 of their share; with that margin (LARGEST_RARE 0.75 kept it)
the large stones grew to 1.39x the count of the generator drawn at the output size
(h0s15, 3.5x side, seed 1: 169 against 122) and the medium stones fell to 0.80x."""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize


@pytest.mark.parametrize(("counts", "variant"), [((300, 20, 10), 15), ((100, 150, 10), 9)])
def test_ten_large_stones_stay_near_their_share(counts, variant):
    # 2x the exemplar's side, seed 1; elements per area over the exemplar's (whole frame,
    # so about 1.1 is the frame's own bias). LARGEST_RARE 0.75 (main): large 1.40 / 1.30,
    # medium 0.80 / 0.935; 0.6: large 1.225 / 1.15, medium 0.95 / 0.963. At variant 13
    # both rules leave h0's large at 1.35-1.375: the rule bounds displacement only, and
    # copies still place large stones into free space beyond the share.
    ex = fidelity_suite().make_exemplar("three_sizes", rng=variant, counts=counts)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    assert list(out.kinds) == ["small", "medium", "large"]
    per_area = np.bincount(out.kind, minlength=3) / 4.0 / np.bincount(ex.kind, minlength=3)
    assert per_area[2] <= 1.28, per_area
    assert per_area[0] >= 0.85 and per_area[1] >= 0.85, per_area

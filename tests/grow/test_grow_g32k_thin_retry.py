"""Long thin sticks keep the exemplar's density (issue 14 point 1, held-out exemplar
sticks p0s21: ``grow_variants.py --varied-variants 21,22`` failed density[stick] on seeds
1-3, 0.124 / 0.161 / 0.148 against 0.1, grown too sparse).

A stick whose chosen reference (§5.2) overlapped a placed stick killed its seed: on
p0s21 at 3.5x, seed 1, 831 placements were refused so against 742 made. The seed of a
thin kind now tries the next references by Eq. 3 error (``_Place.place_next``).
"""

from __future__ import annotations

import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


@pytest.mark.parametrize("seed", [1, 2])
def test_long_thin_sticks_keep_their_density(seed):
    # the audit's VARIED set "long thin sticks" drawn at variant seed 21, grown at 2x
    ex = fidelity_suite().make_exemplar("sticks", rng=21, length=36.0, width=2.0, count=80)
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed)
    # at ae56422 (main): 0.107 and 0.134 against 0.1 (233 and 228 sticks); with two retries
    # (THIN_RETRY = 2) 0.063 and 0.021 (243 and 255); with eight 0.035
    # and 0.007 (266 and 258)
    m = fidelity(ex, out, eq5=False, local=False).metrics["density[stick]"]
    assert m.passed, m

"""Issue 14 point 1 on fresh exemplars (helper g3e): the canopy (``_Place.try_larger``,
a seed that misses a larger kind becomes one) gated at the reference's share of that kind.

Three sizes at radius ratios 1 : 1.5 : 3 (``--harder`` three_sizes h3, variant 12) grow
their large stones at the exemplar's density without the canopy; with it ungated the
conversions came on top (9.8 large stones per 1e4 against the exemplar's 8.4, and
nn[medium>large] failed on seeds 1-2). The suite's three sizes, whose growth makes too
few large stones without the canopy (6.0 per 1e4 against 7.06), must keep it: its frame
is a wall that the large stones keep off, and over the whole frame it holds 5.9 per 1e4,
so the reference's share is counted as the judge counts it (minus sampling beyond the
wall's reach), not over the frame; and a kind it counts too few of to know its share
(``CANOPY_MIN_REF``: the suite's 18 large stones) is not gated.
"""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite, grow_keeping_grower

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def _h3s12():
    return fidelity_suite().make_exemplar("three_sizes", rng=12, ratios=(1.0, 1.5, 3.0), counts=(150, 80, 30))


def test_canopy_does_not_over_produce_large_stones():
    ex = _h3s12()
    x0, y0, x1, y1 = ex.region.bounds
    dens, faithful = [], []
    for seed in (1, 2):
        # the audit's 3.5x the frame's side: the gate counts only elements behind the
        # growth front (about 11 mean edges behind), which a 2x region hardly has
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        rep = fidelity(ex, out, eq5=False, local=False)
        d = rep.metrics["density[large]"]
        dens.append(d.result / d.exemplar)
        faithful.append(rep.faithful)
    # main at 79a8da8: 1.16 and 1.15 of the exemplar's large density, nn[medium>large]
    # 0.249 and 0.213 against 0.187 (neither seed faithful); gated 1.10 and 1.07, both pass
    assert float(np.mean(dens)) <= 1.12
    assert all(faithful)


def test_canopy_reference_share_counts_as_the_judge():
    ex = fidelity_suite().make_exemplar("three_sizes", rng=0)
    out, g = grow_keeping_grower(ex, region=Region.rectangle(1.2 * ex.region.bounds[2], 1.2 * ex.region.bounds[3]), rng=1)
    rep = fidelity(ex, out, eq5=False, local=False)
    # the frame is a wall (large stones keep about their radius off it): minus sampling
    assert g.canopy_wall > 0
    gated = [k for k in range(len(ex.kinds)) if np.isfinite(g.canopy_ref_share[k])]
    assert gated
    for k in gated:
        name = ex.kinds[k]
        assert abs(g.canopy_ref_share[k] - rep.metrics[f"fraction[{name}]"].exemplar) < 1e-9
    # the suite's 26 large stones: 18 counted beyond the wall, fewer than CANOPY_MIN_REF
    large = list(ex.kinds).index("large")
    assert np.isnan(g.canopy_ref_share[large])

"""Issue 13 point 1 (helper syn15, fresh held-out draws): a kind is placed before the
others of its size class only where it is larger by area as well as by bounding radius
(``_grow._larger_in_class``). Stripes of dots (radius 4) and bars (10 x 4, bounding
radius 5.4, area radius 3.6; ``synth_variants.py --harder-variants 9,10`` stripes h3s9)
gave the bars the bonus, so they took the band borders from the dots: bars at 1.12-1.16
of what the exemplar's generator draws at 3.5x (h3s8, h3s9; 1.07 at h3s7) and
density[bar] 0.175-0.21 against 0.121 on seeds 1-6 at h3s9."""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite, synth_inner_density_ratios

from strew.synth._api import new_state
from strew.synth._grow import _larger_in_class

STRIPES_H3 = {"band": 22.0, "angle": 1.1, "dot": 4.0, "bar": (10.0, 4.0), "count": 160}


def test_bars_not_placed_before_dots_of_larger_area():
    ex = fidelity_suite().make_exemplar("stripes", rng=9, **STRIPES_H3)
    prep = new_state(ex).prep
    assert len(np.unique(prep.size_class)) == 1  # dots and bars: one size class
    assert not _larger_in_class(prep).any()
    # a kind larger by both measures keeps the bonus: stripes with bars 14 x 4 (area
    # radius 4.2 against the dots' 3.2)
    ex2 = fidelity_suite().make_exemplar("stripes", rng=9, bar=(14.0, 4.0))
    prep2 = new_state(ex2).prep
    bar = list(ex2.kinds).index("bar")
    bonus = _larger_in_class(prep2)
    assert len(np.unique(prep2.size_class)) == 1
    assert np.all(bonus[prep2.kind == bar] > 0) and not bonus[prep2.kind != bar].any()


@pytest.mark.slow
def test_bars_keep_their_exemplar_density():
    # 2x the exemplar's side, seed 1; bars per area away from the region's edge against
    # the exemplar's inner-frame density (margin two of the largest collision radii)
    ex = fidelity_suite().make_exemplar("stripes", rng=9, **STRIPES_H3)
    ratio = synth_inner_density_ratios(ex, rng=1)
    assert ratio["bar"] <= 1.12, ratio

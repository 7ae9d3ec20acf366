"""Issue 13 point 1 (helper s26o): one kind whose sizes are a continuum is one size class
(``_prepare.ONE_KIND_GAP``).

Stones of one outline scaled 0.65-1.35 (--harder stones h2: count 120, spread 0.35) reach
twice the smallest radius with their largest few; split there, the largest stone of variant
17 stood alone in a class of its own, was placed first and leant on, and growth stalled:
326 stones at 3.5x the side where the generator gives 1095-1291."""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import new_state, synthesize
from strew.synth._prepare import size_classes


def test_one_kind_continuum_is_one_class_and_a_gap_keeps_two():
    # radii 1.0 .. 2.1 in steps of 3 %: the 2x step alone cuts the top two off
    r = 1.03 ** np.arange(26)
    assert size_classes(r).max() == 1
    assert size_classes(r, r, np.zeros(len(r), np.int64)).tolist() == [0] * len(r)
    # one kind at two sizes (a gap of 1.6x between them) keeps its two classes
    two = np.array([1.0, 1.05, 1.1, 1.2, 1.92, 2.0, 2.1])
    assert size_classes(two, two, np.zeros(len(two), np.int64)).tolist() == [0, 0, 0, 0, 0, 1, 1]


def test_spread_stones_grow_to_their_density():
    ex = fidelity_suite().make_exemplar("stones", rng=17, count=120, spread=0.35)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0))
    out = synthesize(ex, region, rng=1, measure=False)
    # the whole frame over 4 frames' area: about 1.1 is the frame's own edge bias (main: 0.36)
    assert len(out) / 4.0 / len(ex) >= 0.85, len(out)
    assert len(np.unique(new_state(ex, region, rng=1).prep.size_class)) == 1

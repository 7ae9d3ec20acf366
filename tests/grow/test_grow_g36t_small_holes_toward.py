"""Issue 14 point 1 on a fresh draw (helper g36t, after g35t): three sizes whose small
stones sit snug against the large ones (``--harder`` three_sizes h9, counts 30:60:60,
exemplar drawn with seed 25; nobody tuned on it).

The hole pass (``fill_void_holes`` with ``small_fill``) puts a small stone in a hole
wider than any the exemplar leaves only where each kind is within the reference's small
stones' upper-decile nearest distance of it. Asked at the circle's centre, that refused
124 of 124 holes here: the small stones' nearest large one lies within 1.21 s at that
decile, the holes are 1.24-1.5 s wide, and no element is nearer an empty circle's centre
than its radius (§5.4's fit moves the seed 0-0.09 l, so asking at the fitted position
alone refused them too). A second round, after the lone-element passes, moves the
spot toward the kind the centre lacks (``_toward_kinds``, at most half the hole's
radius) and asks every kind's reach there and again where the fit puts the element.
"""

from __future__ import annotations

import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


@pytest.mark.parametrize("seed", [1, 2])
def test_holes_between_large_stones_get_small_ones(seed):
    ex = fidelity_suite().make_exemplar("three_sizes", rng=25, counts=(30, 60, 60))
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0)), rng=seed)
    rep = fidelity(ex, out, eq5=False, local=False)
    # the judge's empty_circle (|q95 ratio - 1|, tolerance 0.1): integ30 0.103 / 0.111
    # (seeds 1 / 2), now 0.080 / 0.087
    assert rep.metrics["empty_circle"].value < 0.1
    assert rep.faithful

"""Issue 13 point 1 (helper syn13a): growth does not over-place an exemplar's largest size
class. Seeds are 0.75 r-bar apart, so several seeds' copies overlap at every point, and
with the largest class placed first a large stone any of them brings took its place;
each place now takes its largest-class element from the copy of its nearest seed only
(``_grow._not_owned``; three sizes --harder h4s7, 100:100:15, ratios 1:2.5:4)."""

from __future__ import annotations

from strew_testing import fidelity_suite, synth_inner_density_ratios


def test_largest_stones_keep_their_exemplar_density():
    # 2x the exemplar's side, seed 1; large / medium stones per area away from the
    # region's edge against the exemplar's inner-frame density (margin two of the largest
    # collision radii, as _grow._room_cap counts): d67a7c3 1.314 / 0.859 (seeds 2-4 large
    # 1.24-1.37), now 1.014 / 0.997 (seeds 2-4 large 1.01-1.15)
    ex = fidelity_suite().make_exemplar("three_sizes", rng=7, ratios=(1.0, 2.5, 4.0), counts=(100, 100, 15))
    ratio = synth_inner_density_ratios(ex, rng=1)
    assert ratio["large"] <= 1.2, ratio
    assert ratio["medium"] >= 0.93, ratio

"""Tiled synth hands over its dropped medium elements too (issue 19 point 4, helper synth19f).

A finished synth tile hands the later tile the discs of the elements it dropped near its
rectangle (``strew.tiles._synth_holes_out``, ``meta["synth_holes"]``), and the later tile
seeds a copy of each one's kind there. Only the large ones were handed over (half the
largest bounding radius and more): three_sizes' medium elements were then short 2-4.5
spacings into the later tile. Every kind but the smallest is now handed over; the
smallest, which fill the gaps, never are.
"""

from __future__ import annotations

import numpy as np
import pytest

from strew.tiles import _radii, _synth_holes_out
from strew_testing import fidelity_suite


def _dropped_holes(name: str):
    ex = fidelity_suite().make_exemplar(name)
    x, y = np.asarray(ex.x, float), np.asarray(ex.y, float)
    rect, band = (0.0, 0.0, 100.0, float(y.max()) + 1.0), 25.0
    keep = x <= 100.0  # what the tile kept; the rest is dropped
    holes = _synth_holes_out(ex, keep, rect, band)
    names = np.asarray(ex.kinds, dtype=object)[np.asarray(ex.kind, np.int64)]
    return ex, x, keep, names, holes


def test_three_sizes_hands_over_medium_and_large_never_small():
    ex, x, keep, names, holes = _dropped_holes("three_sizes")
    got = {(round(h[0], 9), round(h[1], 9)) for h in holes}
    handed = {str(h[3]) for h in holes}
    assert handed == {"medium", "large"}
    # every dropped medium or large element within the reach is handed over, at its
    # place with its radius and kind; nothing kept, nothing small
    reach = ~keep & (x <= 150.0)
    want = reach & np.isin(names, ["medium", "large"])
    assert want.sum() >= 5 and (want & (names == "medium")).any()
    assert got == {(round(float(ex.x[i]), 9), round(float(ex.y[i]), 9)) for i in np.flatnonzero(want)}
    r = _radii(ex)
    for h in holes:
        i = int(np.flatnonzero((np.asarray(ex.x) == h[0]) & (np.asarray(ex.y) == h[1]))[0])
        assert h[2] == r[i] and h[3] == names[i] and not keep[i]


def test_two_sizes_never_hands_over_pebbles():
    _ex, x, keep, names, holes = _dropped_holes("two_sizes")
    assert holes and {str(h[3]) for h in holes} == {"stone"}
    assert len(holes) == int((~keep & (x <= 150.0) & (names == "stone")).sum())


@pytest.mark.slow  # a 240 x 240 three_sizes synthesis: about 3 s
def test_a_large_hole_wins_over_a_medium_one_in_its_place():
    """The later tile adds the copies of larger kinds first: a medium copy listed first
    no longer takes the place of the large one it collides with."""
    import shapely

    import strew
    from strew.synth import synthesize
    from strew.synth._api import new_state
    from strew.synth._context import add_context

    ex = fidelity_suite().make_exemplar("three_sizes")
    arr = synthesize(ex, strew.Region.rectangle(240.0, 240.0), rng=1, measure=False)
    x = np.asarray(arr.x, float)
    names = np.asarray(arr.kinds, dtype=object)[np.asarray(arr.kind, np.int64)]
    r = _radii(arr)
    left = x < 100.0
    large = np.flatnonzero((x > 140.0) & (x < 200.0) & (names == "large"))
    assert len(large) >= 2
    # a medium hole at each large hole's centre, listed first
    holes = [[float(arr.x[i]), float(arr.y[i]), 0.5 * float(r[i]), "medium"] for i in large]
    holes += [[float(arr.x[i]), float(arr.y[i]), float(r[i]), "large"] for i in large]
    state = new_state(ex, strew.Region(shapely.box(100.0, 0.0, 220.0, 240.0)), rng=1)
    add_context(state, arr.select(left).with_meta(synth_holes=holes))
    mine = np.flatnonzero(~state.fixed)
    kinds = [list(state.prep.shapes)[k] for k in state.prep.kind[state.src[mine]]]
    assert len(mine) == len(large)  # one copy a place: the two collide
    assert kinds == ["large"] * len(large)
    np.testing.assert_allclose(state.pos[mine], np.c_[x[large], np.asarray(arr.y, float)[large]])

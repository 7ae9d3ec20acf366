"""A later ornament tile refills the room a finished willow tile dropped at the scale
that tile grew at there (issue 19 point 4; strew.tiles._ornament_holes,
strew.ornament._engine._handed_over).

The finished tile hands over the empty circles of the successes it drops
(``meta["ornament_holes"]``); a later tile's rule grows into a circle centred in one of
them at that circle's radius where it is the larger. Without it the refill grew into
narrower circles (0.85 s against 1.35 s in the interior), in shorter stems, and the
+-2 s strips came out denser than the interior.
"""

from __future__ import annotations

import math

import numpy as np

import strew
import strew.tiles as T
from strew.ornament._engine import Goal, grow_elements
from strew.ornament._pattern import load_pattern

from strew_testing import TileRows, willow_stem_records


def test_goal_takes_the_largest_handed_over_circle_that_holds_it():
    from strew.ornament._engine import _handed_over

    holes = np.array([[0.0, 0.0, 5.0], [1.0, 0.0, 8.0], [30.0, 0.0, 50.0]])
    g = _handed_over(Goal(np.array([0.5, 0.0]), 1.0), holes[:2])
    assert g.radius == 8.0 and np.array_equal(g.center, [0.5, 0.0])
    # outside every circle, or in a smaller one: the empty circle itself
    far = Goal(np.array([20.0, 0.0]), 1.0)
    assert _handed_over(far, holes[:2]) is far
    big = Goal(np.array([0.5, 0.0]), 9.0)
    assert _handed_over(big, holes[:2]) is big


def _stems(orn):
    return np.array([math.hypot(*(e.proxy.points[-1] - e.proxy.points[0])) for e in orn.elements if e.type == "stem"])


def test_willow_grows_fewer_longer_stems_in_handed_over_room():
    reg = strew.Region.rectangle(30.0, 30.0)
    plain = grow_elements("willow", reg, seeds=[[15.0, 15.0]], rng=1)
    # the panel handed over whole, in circles of radius 6 (the plain run's circles: 5.4 on average)
    grid = np.arange(0.0, 31.0, 5.0)
    held = grow_elements("willow", reg, seeds=[[15.0, 15.0]], rng=1, _holes=[[x, y, 6.0] for x in grid for y in grid])
    assert len(held.elements) < len(plain.elements)
    assert _stems(held).mean() > 1.1 * _stems(plain).mean()
    # the circles recorded for the hand-over stay the empty circles grown into
    r = [e.goal_circle[2] for e in held.elements if hasattr(e, "goal_circle")]
    assert r and min(r) < 6.0
    # no handed-over circle near: the same growth, byte for byte
    away = grow_elements("willow", reg, seeds=[[15.0, 15.0]], rng=1, _holes=[[500.0, 500.0, 10.0]])
    assert [tuple(np.round(e.proxy.points.ravel(), 12)) for e in away.elements if e.type == "stem"] == \
        [tuple(np.round(e.proxy.points.ravel(), 12)) for e in plain.elements if e.type == "stem"]


def test_finished_tile_hands_over_the_circles_of_what_it_drops():
    pat = load_pattern("willow")
    segs = [((60.0, 50.0), (90.0, 50.0)), ((95.0, 50.0), (125.0, 50.0)), ((120.0, 55.0), (70.0, 70.0))]
    recs = willow_stem_records(pat, segs)
    goal = np.empty(3, dtype=object)
    goal[:] = [(75.0, 50.0, 9.0), (110.0, 50.0, 8.0), (95.0, 62.0, 7.0)]
    rows = TileRows({"x": [75.0, 110.0, 95.0], "y": [50.0, 50.0, 62.5], "ornament_group": [1, 2, 3], "element": [1, 2, 3],
                  "parent": [0, 1, 2], "phase": [""] * 3, "ornament_proxies": recs, "ornament_goal": goal})
    tiles, nx, ny = T.plan((200.0, 200.0), 100.0)
    job = T._Job("ornament", "willow", {}, (200.0, 200.0), 25.0, 1, (100.0, 100.0), (nx, ny))
    kept = T._keep_groups(rows, np.ones(3, bool), tiles[0], job, {})
    assert kept.tolist() == [True, True, False]
    assert T._ornament_holes(rows, kept, job, tiles[0].rect) == [[95.0, 62.0, 7.0]]

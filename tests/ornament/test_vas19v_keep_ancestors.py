"""A finished ornament tile keeps the ancestors of a success it keeps beyond every later
tile's region (issue 19 point 4; strew.tiles._keep_groups,
strew.ornament._context.keep_ancestors).

A success was kept only with its parent's (keep_whole): where the parent lay past the
border (or, for a late phase, within half a halo of it), the whole subtree grown from it
back into the finished tile was dropped, also its rows deeper than the later tile's
region reaches, a hole no tile refills (vase, tiles of 84, seed 1: 162 rows 21 units or
more from the later tile in tiles 0, 2 and 8).
"""

from __future__ import annotations

import math

import numpy as np

import strew.tiles as T
from strew.ornament._context import keep_ancestors, keep_whole
from strew.ornament._pattern import load_pattern

from strew_testing import TileRows, willow_stem_records


def _world_rows():
    """Tile 0 of a 200 x 200 world in tiles of 100 (halo 25): four willow successes, each
    one stem: A inside the tile, B grown from A across the border x = 100, C grown from B's
    far end back into the tile, D grown from C, 35 units or more from every later tile."""
    pat = load_pattern("willow")
    segs = [((60.0, 50.0), (90.0, 50.0)), ((95.0, 50.0), (125.0, 50.0)), ((120.0, 55.0), (70.0, 70.0)), ((70.0, 70.0), (30.0, 60.0))]
    recs = willow_stem_records(pat, segs)
    goal = np.empty(4, dtype=object)
    goal[:] = [(math.nan, math.nan, math.nan)] * 4
    rows = TileRows({"x": [0.5 * (a[0] + b[0]) for a, b in segs], "y": [0.5 * (a[1] + b[1]) for a, b in segs],
                     "ornament_group": [1, 2, 3, 4], "element": [1, 2, 3, 4], "parent": [0, 1, 2, 3],
                     "phase": [""] * 4, "ornament_proxies": recs, "ornament_goal": goal})
    tiles, nx, ny = T.plan((200.0, 200.0), 100.0)
    job = T._Job("ornament", "willow", {}, (200.0, 200.0), 25.0, 1, (100.0, 100.0), (nx, ny))
    return rows, tiles[0], job


def test_a_success_beyond_the_later_tiles_reach_keeps_its_ancestors():
    rows, t, job = _world_rows()
    kept = T._keep_groups(rows, np.ones(4, bool), t, job, {})
    # C is placed at its parent B's centre, past the border: left to the later tile. D
    # grew from C 35 units deep in tile 0, where tile 1's region (a halo) never reaches:
    # kept, and C with it (d6d394e: [True, True, False, False])
    assert kept.tolist() == [True, True, True, True]


def test_a_success_within_the_later_tiles_reach_goes_with_its_parent():
    rows, t, job = _world_rows()
    # D moved next to the border (its centre 10 units from tile 1): the later tile's
    # region covers it, so C and D still go to the later tile
    rows.x[3] = 90.0
    kept = T._keep_groups(rows, np.ones(4, bool), t, job, {})
    assert kept.tolist() == [True, True, False, False]


def test_keep_ancestors_marks_the_chain_up_to_a_kept_success():
    # groups {0}, {1} child of 0, {2} child of 1, {3} child of 2, {4} child of 1
    element = np.arange(5)
    parent = np.array([-1, 0, 1, 2, 1])
    group = np.arange(5)
    placed = np.array([True, False, False, True, True])
    far = np.array([False, False, False, True, False])
    out = keep_ancestors(element, parent, group, placed, far)
    # 3 is placed and far, dropped for 1 and 2: both are kept; 4 (placed, not far) is
    # kept with its parent 1 now
    assert out.tolist() == [True, True, True, True, True]
    assert keep_whole(element, parent, group, out).all()
    # nothing far: placed unchanged
    assert keep_ancestors(element, parent, group, placed, np.zeros(5, bool)).tolist() == placed.tolist()

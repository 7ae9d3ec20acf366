"""A tiled vase places a vine's success at the flower it delivers (issue 19 point 4;
strew.ornament._context.anchor_rows, strew.tiles._keep_groups).

The vase's flowers sit on a grid fixed in the world (Wong et al. §5). Placed at its parent
(strew.tiles._at_parent), a success growing from a finished tile's flower across the border
was kept with its flower on a grid point past the border, and those vines crossed the border
side by side (tiles of 72, seed 1: 24 vines within 1 s of a border, the untiled control 10).
"""

from __future__ import annotations

import math

import numpy as np

import strew.tiles as T
from strew.ornament._context import anchor_rows, element_record
from strew.ornament._pattern import Element, load_pattern

from strew_testing import TileRows


def _flower(pat, kind, c):
    el = Element(pat.types[kind])
    el.proxy.set(np.asarray(c, float), 6.0)
    return el


def _vine(pat, a, b):
    el = Element(pat.types["vine"])
    a, b = np.asarray(a, float), np.asarray(b, float)
    el.proxy.set_points(a, a + (b - a) / 3, a + 2 * (b - a) / 3, b)
    el.depth = 0
    return el


def _rows(flower_x):
    """Tile 0 of a 200 x 200 world in tiles of 100 (halo 25): a lotus at (88, 44) (element
    1, its own success) and a success grown from it: a vine (element 2) to a peony (element
    3) at (flower_x, 66)."""
    pat = load_pattern("vase")
    els = [_flower(pat, "lotus", (88.0, 44.0)), _vine(pat, (94.0, 44.0), (flower_x - 6.0, 66.0)), _flower(pat, "peony", (flower_x, 66.0))]
    recs = np.empty(3, dtype=object)
    recs[:] = [(element_record(e, pat),) for e in els]
    goal = np.empty(3, dtype=object)
    goal[:] = [(math.nan, math.nan, math.nan)] * 3
    rows = TileRows({"x": [88.0, 0.5 * (94.0 + flower_x - 6.0), flower_x], "y": [44.0, 55.0, 66.0], "ornament_group": [1, 2, 2],
                     "element": [1, 2, 3], "parent": [0, 1, 1], "phase": ["vines"] * 3, "ornament_proxies": recs, "ornament_goal": goal})
    tiles, nx, ny = T.plan((200.0, 200.0), 100.0)
    job = T._Job("ornament", "vase", {}, (200.0, 200.0), 25.0, 1, (100.0, 100.0), (nx, ny))
    return rows, tiles[0], job


def test_vase_flowers_are_tile_anchors():
    rows, _, _ = _rows(110.0)
    assert anchor_rows("vase", rows["ornament_proxies"]).tolist() == [True, False, True]
    assert not anchor_rows("willow", rows["ornament_proxies"]).any()


def test_a_vine_delivering_its_flower_past_the_border_goes_to_the_later_tile():
    rows, t, job = _rows(110.0)
    kept = T._keep_groups(rows, np.ones(3, bool), t, job, {})
    # the peony's grid point lies in tile 1: the vine and the peony go to it, though the
    # vine grew from tile 0's lotus (d6d394e, placed at the lotus: [True, True, True])
    assert kept.tolist() == [True, False, False]


def test_a_vine_delivering_its_flower_inside_the_tile_is_kept():
    rows, t, job = _rows(96.0)
    kept = T._keep_groups(rows, np.ones(3, bool), t, job, {})
    assert kept.tolist() == [True, True, True]

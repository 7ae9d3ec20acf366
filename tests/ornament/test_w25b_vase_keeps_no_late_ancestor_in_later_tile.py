"""A finished vase tile keeps no hook ancestor inside a later tile (issue 19 point 4, w25b).

With the halo's open edges (strew.tiles._open_edges) a vase tile's hooks phase grows
chains from circles past its border back into the tile. strew.ornament._context.
keep_ancestors kept the ancestors, past the border, of a hook kept deep in the tile: hooks
8 units into the later tile, over grid points whose flowers that tile's vines phase had
not delivered yet, so those grid points stayed empty for good (world seeds 15 and 16,
tile 48: 5 of 128 grid points; benchmarks/w25_keep.py). For a pattern with tile anchors
(the vase's grid flowers) an ancestor inside a later tile within a flower's radius of a
grid point is barred (strew.ornament._context.covers_anchor_grid); hierarchy and the rest
keep theirs.
"""

from __future__ import annotations

import math

import numpy as np
from strew_testing import TileRows

import strew.tiles as T
from strew.ornament._context import element_record, keep_ancestors
from strew.ornament._pattern import Element, load_pattern


def _hook_records(pat, segs):
    recs = np.empty(len(segs), dtype=object)
    for i, (a, b) in enumerate(segs):
        el = Element(pat.types["hook"])
        a, b = np.asarray(a, float), np.asarray(b, float)
        el.proxy.set_points(a, a + (b - a) / 3, a + 2 * (b - a) / 3, b)
        el.phase = "hooks"
        recs[i] = (element_record(el, pat),)
    return recs


def _vase_rows():
    """Tile 0 of a 200 x 200 vase world in tiles of 100 (halo 25): four hooks-phase
    successes, one hook each: A inside the tile, B grown from A across the border x = 100
    (its centre 10 units into tile 1, 2 units from the grid point (110, 44)), C grown from
    B back into the tile, D from C, 40 units or more from every later tile."""
    pat = load_pattern("vase")
    segs = [((60.0, 46.0), (90.0, 46.0)), ((100.0, 46.0), (120.0, 46.0)), ((100.0, 55.0), (70.0, 70.0)), ((70.0, 70.0), (40.0, 60.0))]
    goal = np.empty(4, dtype=object)
    goal[:] = [(math.nan, math.nan, math.nan)] * 4
    rows = TileRows({"x": [0.5 * (a[0] + b[0]) for a, b in segs], "y": [0.5 * (a[1] + b[1]) for a, b in segs],
                     "ornament_group": [1, 2, 3, 4], "element": [1, 2, 3, 4], "parent": [0, 1, 2, 3],
                     "phase": ["hooks"] * 4, "ornament_proxies": _hook_records(pat, segs), "ornament_goal": goal})
    tiles, nx, ny = T.plan((200.0, 200.0), 100.0)
    job = T._Job("ornament", "vase", {}, (200.0, 200.0), 25.0, 1, (100.0, 100.0), (nx, ny))
    return rows, tiles[0], job


def test_vase_tile_keeps_no_hook_ancestor_over_a_later_tiles_grid_point():
    rows, t, job = _vase_rows()
    kept = T._keep_groups(rows, np.ones(4, bool), t, job, {})
    # B lies inside tile 1 over its grid point (110, 44), whose flower that tile's vines
    # phase has yet to deliver: not kept for D's sake, and so neither C nor D (h/w25:
    # [True, True, True, True])
    assert kept.tolist() == [True, False, False, False]
    later = [r for r in T._later_rects(t, job)]
    inside = [any(x0 <= x <= x1 and y0 <= y <= y1 for x0, y0, x1, y1 in later) for x, y in zip(rows.x, rows.y)]
    assert not (kept & np.array(inside)).any()
    # B moved 8 units off the grid row y = 44 (its nearest grid point 8 away, past a
    # flower's radius 6): it covers no grid point and is kept for D's sake, with C
    rows.y[1] = 52.0
    pat = load_pattern("vase")
    rows.columns["ornament_proxies"][1] = _hook_records(pat, [((100.0, 52.0), (120.0, 52.0))])[0]
    kept = T._keep_groups(rows, np.ones(4, bool), t, job, {})
    assert kept.tolist() == [True, True, True, True]


def test_keep_ancestors_leaves_a_chain_with_a_barred_row():
    # groups {0}, {1} child of 0, {2} child of 1, {3} child of 2, {4} child of 0, {5} child of 4
    element = np.arange(6)
    parent = np.array([-1, 0, 1, 2, 0, 4])
    group = np.arange(6)
    placed = np.array([True, False, False, True, False, True])
    far = np.array([False, False, False, True, False, True])
    barred = np.array([False, True, False, False, False, False])
    # 3's chain holds the barred 1: none of it kept; 5's chain (4) is kept
    out = keep_ancestors(element, parent, group, placed, far, barred)
    assert out.tolist() == [True, False, False, True, True, True]
    # without bars both chains are kept, as before
    assert keep_ancestors(element, parent, group, placed, far).all()
    # a barred row that is placed by itself does not bar its chain
    placed2 = placed.copy()
    placed2[1] = True
    assert keep_ancestors(element, parent, group, placed2, far, barred).all()

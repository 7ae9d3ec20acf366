"""A finished ornament tile leaves to a later tile the successes that a dropped element
had bounded (issue 19 point 4; strew.ornament._context.cut_touching).

Wong et al. grow into the largest empty circle first (§4.1). A success whose empty
circle touched an element the tile then drops (it lay beyond the border) filled a
pocket that, once that element is gone, is part of a larger gap; kept, it left the later
tile a ragged front whose pockets its flowers grew into on stems too short for a leaf.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import strew.ornament._context as C
from strew.ornament._context import cut_touching, element_record
from strew.ornament._pattern import Element, load_pattern


def _flower(pat, x, y):
    el = Element(pat.types["flower"])
    el.proxy.set(np.array([x, y], float), 3.0)
    el.phase = "flowers"
    return el


def _records(pat, centres):
    col = np.empty(len(centres), dtype=object)
    for i, (x, y) in enumerate(centres):
        col[i] = (element_record(_flower(pat, x, y), pat),)
    return col


def _goals(circles):
    col = np.empty(len(circles), dtype=object)
    col[:] = circles
    return col


def test_cut_touching_marks_kept_successes_bounded_by_an_earlier_dropped_element():
    pat = load_pattern("flowers")
    # row 0: dropped (beyond the border), placed first (group 0). Its rim is at x = 47.
    # rows 1-4 kept, each a success with its empty circle (x, y, radius):
    centres = [(50.0, 0.0), (40.0, 0.0), (40.0, 20.0), (40.0, -20.0), (30.0, 0.0)]
    goals = _goals([
        (math.nan, math.nan, math.nan),
        (43.5, 0.0, 3.5),  # touches row 0's rim (3.5 from x = 43.5 to 47): bounded by it
        (43.5, 20.0, 3.5),  # the same circle 20 units away: untouched
        (43.5, 0.3, 3.5),  # touches it, but placed before it (group -1 < 0)
        (37.0, 0.0, 3.0),  # 7 units short of its rim: beyond CUT_TOUCH
    ])
    group = np.array([0, 1, 2, -1, 3])
    kept = np.array([False, True, True, True, True])
    got = cut_touching("flowers", _records(pat, centres), group, goals, kept)
    assert got.tolist() == [False, True, False, False, False]
    # nothing dropped, or the rule off: nothing handed over
    assert not cut_touching("flowers", _records(pat, centres), group, goals, np.ones(5, bool)).any()


def test_cut_touching_off(monkeypatch):
    pat = load_pattern("flowers")
    monkeypatch.setattr(C, "CUT_TOUCH", 0.0)
    centres = [(50.0, 0.0), (40.0, 0.0)]
    goals = _goals([(math.nan, math.nan, math.nan), (43.5, 0.0, 3.5)])
    assert not cut_touching("flowers", _records(pat, centres), np.array([0, 1]), goals, np.array([False, True])).any()


def _tile0(monkeypatch, touch):
    """Tile 0 of a 160 x 160 flowers world in tiles of 80 (halo 20): its grown rows and
    the rows it keeps (strew.tiles.run_tile, _keep_groups recorded)."""
    import strew.tiles as T

    monkeypatch.setattr(C, "CUT_TOUCH", touch)
    seen = {}
    orig = T._keep_groups

    def spy(arr, keep, t, job, links):
        out = orig(arr, keep, t, job, links)
        seen["arr"], seen["kept"] = arr, out
        return out

    monkeypatch.setattr(T, "_keep_groups", spy)
    tiles, nx, ny = T.plan((160.0, 160.0), 80.0)
    job = T._Job("ornament", "flowers", {}, (160.0, 160.0), 20.0, 1, (80.0, 80.0), (nx, ny))
    T.run_tile(job, tiles[0])
    return seen["arr"], seen["kept"], T._later_rects(tiles[0], job), job


@pytest.mark.slow
def test_finished_tile_leaves_the_pockets_of_its_cut_to_the_later_tiles(monkeypatch):
    arr, kept, later, job = _tile0(monkeypatch, 0.1)
    arr0, kept0, _, _ = _tile0(monkeypatch, 0.0)
    assert np.array_equal(arr.x, arr0.x) and np.array_equal(arr.y, arr0.y)  # the same growth
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    d = np.full(len(arr), np.inf)
    for x0, y0, x1, y1 in later:
        d = np.minimum(d, np.hypot(np.maximum(np.maximum(x0 - x, x - x1), 0.0), np.maximum(np.maximum(y0 - y, y - y1), 0.0)))
    extra = kept0 & ~kept
    assert not (kept & ~kept0).any()  # the rule only hands more over
    assert extra.sum() >= 5  # it hands over pockets of the cut...
    # ...within the later tiles' reach (they refill a halo into this tile), so no hole
    # is left that no tile refills
    assert (d[extra] < 0.9 * job.halo).all()
    group = np.asarray(arr["ornament_group"])
    # and fewer kept successes there are left bounded by a dropped element placed before
    # them (one round of the rule, _CUT_ROUNDS: a handed-over row can bound another)
    monkeypatch.setattr(C, "CUT_TOUCH", 0.1)

    def bounded(k):
        near = k & (d < 0.5 * job.halo)
        return int((cut_touching("flowers", arr["ornament_proxies"], group, arr["ornament_goal"], k) & near).sum())

    assert bounded(kept) < bounded(kept0)

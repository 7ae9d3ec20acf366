"""A finished ornament tile places a willow success where it grows from (issue 19 point 4;
strew.tiles._keep_groups, _at_parent).

Every willow type parents a rule, so a success's growing tip is all of it: by its rows'
mean, a stem that grew from the finished side across the border was dropped, and with
it every success grown from it, back into the finished side too. The later tile
refilled those holes at a finer scale (shorter stems, Wong et al. §5), and the border
strips came out denser than the interior and short of stems.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import strew.tiles as T
from strew.ornament._pattern import load_pattern

from strew_testing import TileRows, willow_stem_records


def _world_rows():
    """Tile 0 of a 200 x 200 world in tiles of 100 (halo 25): three willow successes, each
    one stem (a row): A from the seed inside the tile, B grown from A across the border
    x = 100 (its centre at x = 110), C grown from B's far end, back across the border
    (its centre at x = 95)."""
    pat = load_pattern("willow")
    segs = [((60.0, 50.0), (90.0, 50.0)), ((95.0, 50.0), (125.0, 50.0)), ((120.0, 55.0), (70.0, 70.0))]
    recs = willow_stem_records(pat, segs)
    goal = np.empty(3, dtype=object)
    goal[:] = [(math.nan, math.nan, math.nan)] * 3
    cx = [0.5 * (a[0] + b[0]) for a, b in segs]
    cy = [0.5 * (a[1] + b[1]) for a, b in segs]
    rows = TileRows({"x": cx, "y": cy, "ornament_group": [1, 2, 3], "element": [1, 2, 3], "parent": [0, 1, 2],
                  "phase": [""] * 3, "ornament_proxies": recs, "ornament_goal": goal})
    tiles, nx, ny = T.plan((200.0, 200.0), 100.0)
    job = T._Job("ornament", "willow", {}, (200.0, 200.0), 25.0, 1, (100.0, 100.0), (nx, ny))
    return rows, tiles[0], job


def test_finished_tile_keeps_a_willow_stem_grown_from_its_side():
    rows, t, job = _world_rows()
    kept = T._keep_groups(rows, np.ones(3, bool), t, job, {})
    # B's centre lies in the later tile 1, but it grew from A, drawn in tile 0: kept (by
    # its rows' mean it was dropped, and C with it). C grew from B, whose centre lies past
    # the border: left to the later tile, though its own centre lies at x = 95
    assert kept.tolist() == [True, True, False]
    # the rule up to 61d61c7 for willow (a success's rows' mean): B dropped, C with it
    kept_mean = _mean_rule(rows, t, job)
    assert kept_mean.tolist() == [True, False, False]


def _mean_rule(rows, t, job):
    with pytest.MonkeyPatch.context() as m:
        m.setattr(T, "_GROUP_AT", "mean")
        return T._keep_groups(rows, np.ones(len(rows), bool), t, job, {})


def test_willow_success_past_the_border_with_its_parent_goes_to_the_later_tile():
    rows, t, job = _world_rows()
    # A moved past the border as well (its parent, the seed, is not drawn: its own
    # rows' mean places it): then A, B and C go to the later tile whole
    rows.x[0] += 50.0
    kept = T._keep_groups(rows, np.ones(3, bool), t, job, {})
    assert kept.tolist() == [False, False, False]


@pytest.mark.slow
def test_willow_tile_keeps_its_border(monkeypatch):
    """Tile 0 of a 240 x 240 willow world in tiles of 120 (halo 30): it keeps more of
    its rows near the later tiles than by the successes' rows' mean (_GROUP_AT "mean",
    the willow rule up to 61d61c7), and the same growth."""
    seen = {}
    orig = T._keep_groups

    def spy(arr, keep, t, job, links):
        out = orig(arr, keep, t, job, links)
        seen[T._GROUP_AT] = (arr, out)
        return out

    monkeypatch.setattr(T, "_keep_groups", spy)
    tiles, nx, ny = T.plan((240.0, 240.0), 120.0)
    job = T._Job("ornament", "willow", {}, (240.0, 240.0), 30.0, 1, (120.0, 120.0), (nx, ny))
    T.run_tile(job, tiles[0])
    monkeypatch.setattr(T, "_GROUP_AT", "mean")
    T.run_tile(job, tiles[0])
    (arr, kept), (arr0, kept0) = seen["parents"], seen["mean"]
    assert np.array_equal(arr.x, arr0.x)
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    x0, y0, x1, y1 = tiles[0].rect
    own = (x < x1) & (y < y1)
    near = own & (np.minimum(x1 - x, y1 - y) < 0.25 * job.halo)  # within 7.5 units of a later tile
    assert near.sum() > 50
    # by the rows' mean it kept a minority of them (the later tile refilled the rest)
    assert kept0[near].mean() < 0.5
    assert kept[near].mean() > 1.3 * kept0[near].mean()
    # a success's rows go together, and none dangles from a dropped parent
    group = np.asarray(arr["ornament_group"])
    for g in np.unique(group):
        assert len(set(kept[group == g].tolist())) == 1
    row_of = {int(e): i for i, e in enumerate(np.asarray(arr["element"]))}
    for i in np.flatnonzero(kept):
        p = row_of.get(int(arr["parent"][i]), -1)
        assert p < 0 or kept[p]

"""A tiled ornament world grows on from its finished tiles' elements (issue 19 point 4).

A later tile used to meet its finished neighbours' ornament as the panel's edge: circles
that touched only them were discarded (Wong et al. §4.1), and a flower dropped beyond a
border left its stem and leaf dangling from the kept parent. Within about half a spacing
of a border there were then only buds (flowers 480 x 480 in tiles of 120: leaves 0.54x,
buds 1.28x the interior's share in the +-2 s strips, benchmarks/worlds_strips.py).
"""

from __future__ import annotations

import numpy as np
import pytest

from strew.ornament import grow_ornament
from strew.ornament._context import GROUP_COLUMN, PROXIES_COLUMN, keep_whole
from strew.region import Region
from strew.tiles import world


def _centres(arr, types):
    m = np.isin(np.asarray(arr["type"]), types)
    return np.c_[arr.x[m], arr.y[m]]


def _stem_ends(arr):
    ends = []
    for g, t in zip(arr.geometry_of("geometry"), np.asarray(arr["type"])):
        if t == "stem":
            c = np.asarray(g.coords) if g.geom_type == "LineString" else np.asarray(g.exterior.coords)
            ends.append((c[0], c[-1]))
    return ends


def _near(p, pts, tol=1e-6):
    return len(pts) and float(np.min(np.hypot(pts[:, 0] - p[0], pts[:, 1] - p[1]))) < tol


@pytest.fixture(scope="module")
def flowers_world():
    tiles = {}
    world("ornament", "flowers", (120, 60), tile_size=60, seed=1, sink=tiles.__setitem__)
    return tiles


@pytest.mark.slow
def test_later_tile_grows_stems_from_the_finished_tiles_flowers(flowers_world):
    # tile 1 (phase 1) runs after tile 0: some of its stems start at the centre of one
    # of tile 0's flowers (on 82a4322 none can: tile 0's flowers were the panel's edge)
    first, later = flowers_world[0], flowers_world[1]
    finished = _centres(first, ["flower"])
    own = _centres(later, ["flower", "bud"])
    from_finished = [a if _near(a, finished) else b for a, b in _stem_ends(later) if _near(a, finished) or _near(b, finished)]
    assert len(from_finished) >= 2
    # and each of those stems ends at one of tile 1's own flowers or buds
    grown = [(a, b) for a, b in _stem_ends(later) if _near(a, finished) or _near(b, finished)]
    assert all(_near(b, own) or _near(a, own) for a, b in grown)


@pytest.mark.slow
def test_no_stem_dangles_across_a_tile_border(flowers_world):
    # every stem joins two drawn flowers or buds of the world: a tile keeps or drops a
    # flower with its stem and leaf, and a flower only with its parent (on 82a4322 a
    # flower dropped beyond the border left its stem hanging from the kept parent)
    from strew.arrangement import concat
    from strew.tiles import _harmonize

    arr = concat(_harmonize([flowers_world[k] for k in sorted(flowers_world) if len(flowers_world[k])]))
    heads = _centres(arr, ["flower", "bud"])
    ends = _stem_ends(arr)
    assert len(ends) > 100
    dangling = sum(not (_near(a, heads) and _near(b, heads)) for a, b in ends)
    assert dangling == 0
    # the private columns that carry the proxies never reach the sink
    assert all(PROXIES_COLUMN not in a.columns and GROUP_COLUMN not in a.columns for a in flowers_world.values())


def test_untiled_ornament_has_no_private_columns():
    arr = grow_ornament("dots", Region.rectangle(30, 20), rng=1)
    assert PROXIES_COLUMN not in arr.columns and GROUP_COLUMN not in arr.columns


def test_keep_whole_cuts_the_tree_of_rule_successes():
    # elements 0..6; groups (rule successes): {0} root, {1, 2} child of 0, {3, 4} child
    # of 2, {5, 6} child of 4
    element = np.arange(7)
    parent = np.array([-1, 0, 0, 2, 2, 4, 4])
    group = np.array([0, 1, 1, 3, 3, 5, 5])
    placed = np.array([True, True, True, False, False, True, True])
    keep = keep_whole(element, parent, group, placed)
    # group 3 is placed beyond the border: dropped whole, and group 5 (its child) with it
    assert keep.tolist() == [True, True, True, False, False, False, False]
    # a group's rows go together even when the caller's mask splits them
    keep = keep_whole(element, parent, group, np.array([True, True, True, True, True, True, True]))
    assert keep.all()
    assert keep_whole(element[:0], parent[:0], group[:0], placed[:0]).shape == (0,)

"""The spray as one growth along a stroke (Ijiri et al. §3, §5.1): SprayGrowth."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import InputError, Region, metrics
from strew.arrangement import concat
from strew.grow import SprayGrowth, analyze, grow
from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

PATH = np.array([(20.0 + 8.0 * i, 100.0 + 30.0 * np.sin(i / 8)) for i in range(40)])
RADIUS = 30.0
MAKERS = [hex_exemplar, stone_exemplar, tile_exemplar]


def _paint(ref, path=PATH, radius=RADIUS, step=3, max_new=None, rng=1, **kw):
    g = SprayGrowth(ref, radius=radius, rng=rng, **kw)
    parts = []
    for i in range(0, len(path), step):
        g.add_points(path[i : i + step])
        while True:
            parts.append(g.grow(max_new))
            if not g.pending:
                break
    return g, parts


def _dist(xy, path):
    return shapely.distance(shapely.LineString(path), shapely.points(xy))


@pytest.mark.parametrize("make", MAKERS)
def test_incremental_spray_matches_one_shot_growth_in_count(make):
    ref = analyze(make())
    g, _ = _paint(ref)
    one = grow(ref, spray=PATH, spray_radius=RADIUS, rng=1)
    n = len(g.arrangement())
    assert n > 50
    assert abs(n - len(one)) <= 0.15 * len(one)


@pytest.mark.parametrize("make", MAKERS)
def test_spray_stays_in_the_disc_and_region_without_overlaps(make):
    ref = analyze(make())
    region = Region.rectangle(250, 150)
    g, parts = _paint(ref, region=region)
    out = g.arrangement()
    # §5.1: only seeds within the radius of the cursor's path grow, and the relaxation
    # never takes an element out of the spray area (its polygon lies inside the disc)
    assert np.all(_dist(out.xy, PATH) <= RADIUS + 1e-6)
    assert region.contains(out.xy).all()
    assert len(metrics.overlaps(out)[0]) == 0
    assert sum(len(p) for p in parts) == len(out)


@pytest.mark.parametrize("make", MAKERS)
def test_spray_is_deterministic_and_chunking_does_not_change_it(make):
    ref = analyze(make())
    a = _paint(ref)[0].arrangement()
    b = _paint(ref)[0].arrangement()
    c, parts = _paint(ref, max_new=7)
    c = c.arrangement()
    assert np.array_equal(a.xy, b.xy) and np.array_equal(a.rotation, b.rotation)
    # pausing every few elements (at relaxation windows) gives the same growth
    assert np.array_equal(a.xy, c.xy) and np.array_equal(a.kind, c.kind)
    assert max(len(p) for p in parts) < len(c)
    assert not np.array_equal(a.xy, _paint(ref, rng=2)[0].arrangement().xy)


def test_handed_out_elements_hold_their_positions():
    ref = analyze(stone_exemplar())
    g = SprayGrowth(ref, radius=RADIUS, rng=1)
    given = []
    for i in range(0, len(PATH), 4):
        g.add_points(PATH[i : i + 4])
        given.append(g.grow())
    first = concat([p for p in given if len(p)])
    assert np.array_equal(first.xy, g.arrangement().xy)


def test_each_move_grows_only_near_the_new_points():
    ref = analyze(hex_exemplar())
    g = SprayGrowth(ref, radius=RADIUS, rng=1)
    g.add_points(PATH[:1])
    first = g.grow()
    assert len(first) and np.all(np.hypot(*(first.xy - PATH[0]).T) <= RADIUS + 1e-6)
    g.add_points(PATH[1:10])
    more = g.grow()
    assert len(more) and np.all(_dist(more.xy, PATH[:10]) <= RADIUS + 1e-6)


@pytest.mark.parametrize("make", MAKERS)
def test_obstacles_are_not_overlapped_and_growth_reseeds_past_them(make):
    ref = analyze(make())
    # a full disc of elements where the stroke starts
    scene = grow(ref, spray=PATH[:1], spray_radius=40.0, rng=5)
    g = SprayGrowth(ref, radius=RADIUS, rng=1)
    g.add_obstacles(scene)
    for i in range(0, len(PATH), 3):
        g.add_points(PATH[i : i + 3])
        g.grow()
    out = g.arrangement()
    assert len(out) > 50  # the growth went on beyond the obstacles
    both = concat([scene, out])
    pairs, _ = metrics.overlaps(both)
    assert len(pairs) == 0


def test_bad_input_is_refused():
    ref = analyze(hex_exemplar())
    with pytest.raises(InputError, match="radius"):
        SprayGrowth(ref, radius=0.0)
    with pytest.raises(InputError, match="mode"):
        SprayGrowth(ref, radius=5.0, mode="sideways")
    with pytest.raises(InputError, match="flow"):
        SprayGrowth(ref, radius=5.0, mode="flow")
    with pytest.raises(InputError, match="points"):
        SprayGrowth(ref, radius=5.0).add_points([[0.0, np.nan]])
    with pytest.raises(InputError, match="exemplar"):
        SprayGrowth("stones", radius=5.0)


def test_outside_the_region_nothing_grows():
    ref = analyze(hex_exemplar())
    g = SprayGrowth(ref, radius=RADIUS, region=Region.rectangle(50, 50), rng=1)
    g.add_points([[500.0, 500.0], [600.0, 500.0]])
    assert len(g.grow()) == 0 and not g.pending


def test_a_cancelled_call_keeps_what_it_placed():
    from strew._errors import Cancelled

    ref = analyze(hex_exemplar())
    g = SprayGrowth(ref, radius=RADIUS, rng=1)
    g.add_points(PATH[:10])
    with pytest.raises(Cancelled):  # asked to stop at the first check, after one step
        g.grow(should_cancel=lambda: True)
    kept = g.grow(0)
    assert len(kept) == len(g.arrangement()) > 0
    assert np.all(_dist(kept.xy, PATH[:10]) <= RADIUS + 1e-6)
    assert len(metrics.overlaps(kept)[0]) == 0

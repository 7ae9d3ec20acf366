"""Region growing end to end and the tools of §5.4-5.6: brush, filler, eraser, voids."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import Region
from strew.metrics import overlaps
from strew.synth import Palette, brush, erase, fill, new_state, set_selection, synthesize
from strew.synth._exemplars import apples, grid, stones, stripes


def _no_close_pairs(state):
    """Every pair respects the bounding discs and the exemplar's closest approach."""
    from scipy.spatial import cKDTree

    pos, r = state.pos, state.r
    prep = state.prep
    sk = prep.skind[state.src]
    pairs = cKDTree(pos).query_pairs(max(2 * r.max(), prep.min_dist.max()), output_type="ndarray")
    if len(pairs) == 0:
        return True
    a, b = pairs.T
    d = np.hypot(*(pos[a] - pos[b]).T)
    lim = np.maximum(prep.factor * (r[a] + r[b]), prep.min_dist[sk[a], sk[b]])
    return bool(np.all(d >= lim - 1e-9))


@pytest.mark.parametrize("make", [grid, stripes])
def test_fill_whole_region_no_overlaps_inside_and_dense(make):
    ex = make()
    region = Region.rectangle(220, 180)
    out = synthesize(ex, region, rng=4)
    assert len(overlaps(out)[0]) == 0 == len(overlaps(ex)[0])
    assert region.contains_geometry(out.geometry).all()
    # density: the interior (away from the border) holds the exemplar's density
    from strew.synth._prepare import exemplar_domain, _spacing

    dom, _ = exemplar_domain(ex.xy, _spacing(ex.xy))
    dens_ex = len(ex) / dom.area
    inner = Region.rectangle(160, 120, 30, 30)
    n_in = inner.contains(out.xy).sum()
    assert n_in >= 0.9 * dens_ex * inner.area
    assert n_in <= 1.1 * dens_ex * inner.area
    # per-element parameters copied from the exemplar (§4.1)
    pal = Palette({"e": ex})["e"]
    for name in ex.kinds:
        want = pal["radius"][pal.kind_names == name][0]
        assert np.allclose(out["radius"][out.kind_names == name], want)


def test_determinism_same_seed_same_output():
    ex = stripes()
    a = synthesize(ex, Region.rectangle(150, 150), rng=7)
    b = synthesize(ex, Region.rectangle(150, 150), rng=7)
    assert a.equals(b)
    c = synthesize(ex, Region.rectangle(150, 150), rng=8, init="patch", patch_rounds=2)
    d = synthesize(ex, Region.rectangle(150, 150), rng=8, init="patch", patch_rounds=2)
    assert c.equals(d)


def test_filler_stops_when_full_and_stays_in_the_region():
    ex = grid()
    region = Region.circle(100, 100, 70)
    s = new_state(ex, region, rng=1)
    added = fill(s, (100, 100))
    assert added > 100
    assert s.region.contains(s.pos).all()
    assert not s.horizon.any()
    assert _no_close_pairs(s)
    # no room is left: filling again adds nothing
    assert fill(s, (100, 100)) == 0
    assert fill(s, (60, 110)) == 0


def test_filler_outside_region_is_an_input_error():
    from strew import InputError

    s = new_state(grid(), Region.rectangle(50, 50), rng=1)
    with pytest.raises(InputError, match="outside the region"):
        fill(s, (80, 80))


def test_brush_confines_synthesis_to_the_stroke():
    ex = stripes()
    s = new_state(ex, Region.rectangle(400, 400), rng=2)
    pts = np.c_[np.linspace(50, 350, 41), 200 + 40 * np.sin(np.linspace(0, 3, 41))]
    added = brush(s, pts, 20.0)
    assert added > 50
    d = shapely.distance(shapely.LineString(pts), shapely.points(s.pos))
    assert np.all(d <= 20.0 + 1e-9)
    # the stroke is covered end to end
    for p in pts[::8]:
        assert np.min(np.hypot(*(s.pos - p).T)) < 10
    assert _no_close_pairs(s)


def test_brush_segments_continue_a_stroke():
    ex = grid()
    s = new_state(ex, Region.rectangle(400, 200), rng=3)
    pts = np.c_[np.linspace(30, 370, 60), np.full(60, 100.0)]
    first = brush(s, pts[:30], 15.0)
    n1 = s.n
    second = brush(s, pts[30:], 15.0)
    assert first > 0 and second > 0
    # the second segment grows from the first (no new random patch: one coherent band)
    assert s.pos[n1:, 0].min() > 150
    assert _no_close_pairs(s)


def test_eraser_removes_elements_and_brush_points_near_the_path():
    ex = grid()
    s = new_state(ex, Region.rectangle(200, 200), rng=5)
    fill(s)
    s.brush_points = np.array([[100.0, 20.0], [10.0, 190.0]])
    s.brush_radii = np.array([5.0, 5.0])
    path = np.array([[20.0, 20.0], [180.0, 20.0], [180.0, 180.0]])
    line = shapely.LineString(path)
    near = shapely.distance(line, shapely.points(s.pos)) <= 12.0
    before = s.n
    kept = s.pos[~near].copy()
    removed = erase(s, path, 12.0)
    assert removed == near.sum() > 0
    assert s.n == before - removed
    assert np.array_equal(s.pos, kept)
    assert np.all(shapely.distance(line, shapely.points(s.pos)) > 12.0)
    assert s.brush_points.tolist() == [[10.0, 190.0]]
    # the hole can be filled again
    assert fill(s, (100, 20)) > 0


def test_voids_steer_growth_and_are_hidden():
    ex = apples()
    assert ex["void"].any()
    hidden = synthesize(ex, Region.rectangle(250, 250), rng=1)
    shown = synthesize(ex, Region.rectangle(250, 250), rng=1, keep_voids=True)
    assert "void" not in hidden.columns
    assert set(hidden.kind_names) == {"apple"}
    assert shown["void"].any()
    assert np.array_equal(shown.select(~shown["void"]).xy, hidden.xy)
    assert set(shown.select(shown["void"]).kind_names) == {"void"}
    # voids keep apples apart as in the exemplar
    from scipy.spatial import cKDTree

    ea = ex.select(~ex["void"]).xy
    d_ex = cKDTree(ea).query(ea, k=2)[0][:, 1].min()
    d_out = cKDTree(hidden.xy).query(hidden.xy, k=2)[0][:, 1].min()
    assert d_out >= 0.9 * d_ex


def test_voids_give_way_to_visible_elements_and_keep_the_density():
    """Visible elements are placed before voids (§5.6 extension): the visible density
    reaches the exemplar's, the apples keep their spacing, and no void intersects."""
    from scipy.spatial import cKDTree

    from strew.synth._prepare import _spacing, exemplar_domain

    ex = apples()
    vis_ex = ex.select(~ex["void"])
    dom, _ = exemplar_domain(ex.xy, _spacing(ex.xy))
    dens_ex = len(vis_ex) / dom.area
    s = new_state(ex, Region.rectangle(480, 480), rng=3)
    fill(s)
    assert _no_close_pairs(s)  # voids included: none was left on top of an apple
    out = s.to_arrangement()
    inner = Region.rectangle(384, 384, 48, 48)
    dens = inner.contains(out.xy).sum() / inner.area
    assert 0.85 * dens_ex <= dens <= 1.15 * dens_ex
    d_ex = np.median(cKDTree(vis_ex.xy).query(vis_ex.xy, k=2)[0][:, 1])
    d_out = np.median(cKDTree(out.xy).query(out.xy, k=2)[0][:, 1])
    assert abs(d_out - d_ex) <= 0.1 * d_ex


def test_two_scales_in_one_output_with_per_element_radii():
    pal = Palette({"stones": stones(1.0), "pebbles": stones(0.25, size=60)})
    r_stone = pal["stones"]["radius"][0]
    r_pebble = pal["pebbles"]["radius"][0]
    assert r_stone > 3 * r_pebble
    region = Region.rectangle(200, 200)
    s = new_state(pal, region, selection="stones", rng=2)
    fill(s)
    n_stones = s.n
    set_selection(s, "pebbles")
    # fill the gaps between stones from the emptiest point
    grid_pts = np.mgrid[5:200:5, 5:200:5].reshape(2, -1).T.astype(float)
    gap = grid_pts[np.argmax(np.min(np.hypot(*(grid_pts[:, None] - s.pos[None]).transpose(2, 0, 1)), axis=1))]
    added = fill(s, tuple(gap))
    assert added > 10
    out = s.to_arrangement(clip=False)
    counts = out.counts()
    assert counts["stone"] == n_stones and counts["pebble"] == added
    big = out["exemplar"] == "stones"
    assert np.allclose(out["radius"][big], r_stone) and np.allclose(out["radius"][~big], r_pebble)
    assert np.allclose(out["neighborhood_radius"][big], pal["stones"]["neighborhood_radius"][0])
    assert _no_close_pairs(s)


def test_brushing_over_elements_turns_them_toward_the_selection():
    pal = Palette({"grid": grid(), "stripes": stripes()})
    s = new_state(pal, Region.rectangle(200, 200), selection="grid", rng=3)
    fill(s)
    set_selection(s, "stripes")
    pts = np.array([[60.0, 100.0], [140.0, 100.0]])
    under = shapely.distance(shapely.LineString(pts), shapely.points(s.pos)) <= 20
    idx = np.flatnonzero(under)
    brush(s, np.c_[np.linspace(60, 140, 17), np.full(17, 100.0)], 20.0)
    out = s.to_arrangement(clip=False)
    names = out.kind_names
    # every element that was under the brush now carries a stripes kind
    assert set(names[idx]) <= {"dot", "bar"}
    assert set(names[np.setdiff1d(np.arange(len(out)), np.flatnonzero(shapely.distance(shapely.LineString(pts), shapely.points(s.pos)) <= 60))]) == {"square"}

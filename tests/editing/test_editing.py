"""strew.editing, strew.region.cut_along and Arrangement.radii: the library side of the
studio's tools (issue 15 point 6)."""

from __future__ import annotations

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import Arrangement
from strew.editing import Bounds, near_stroke, overlap_drops, overlapping, wrap_stroke
from strew.region import Region, cut_along
from strew.shape import Shape

def _square() -> Shape:
    from strew.shape import Path

    return Shape([Path(np.array([(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]), closed=True)])


def _arr(xy, rot=None, scale=None) -> Arrangement:
    xy = np.asarray(xy, float).reshape(-1, 2)
    n = len(xy)
    return Arrangement({"sq": _square()}, ["sq"] * n, xy[:, 0], xy[:, 1],
                       np.zeros(n) if rot is None else rot, np.ones(n) if scale is None else scale)


coords = st.floats(0, 40, allow_nan=False)
points = st.lists(st.tuples(coords, coords), min_size=1, max_size=15)


@settings(max_examples=40, deadline=None)
@given(points, st.lists(st.floats(-3, 3), min_size=25, max_size=25), st.lists(st.floats(0.2, 3), min_size=25, max_size=25))
def test_radii_hold_every_outline(xy, rot, scale):
    arr = _arr(xy, np.array(rot[: len(xy)]), np.array(scale[: len(xy)]))
    r = arr.radii
    assert r.shape == (len(arr),) and np.all(r > 0)
    for g, x, y, ri in zip(arr.geometry, arr.x, arr.y, r):
        far = max(np.hypot(*(np.asarray(g.exterior.coords) - (x, y)).T))
        assert far <= ri * (1 + 1e-9) + 1e-12
    assert np.allclose(r, np.sqrt(2) * np.abs(arr.scale))


@settings(max_examples=40, deadline=None)
@given(points, points)
def test_overlapping_is_the_exact_test(a, b):
    new, old = _arr(a), _arr(b)
    got = overlapping(new, old)
    want = np.array([any(shapely.intersects(g, h) for h in old.geometry) for g in new.geometry])
    assert np.array_equal(got, want)


@settings(max_examples=40, deadline=None)
@given(points, st.integers(0, 25), st.integers(0, 25), st.booleans())
def test_overlap_drops_leave_no_overlap(xy, n_fixed, n_old, later):
    arr = _arr(xy)
    n_fixed = min(n_fixed, len(arr))
    m = len(arr) - n_fixed
    new = np.arange(m) >= min(n_old, m)
    g = arr.geometry
    pairs = np.array([(i, j) for i in range(len(arr)) for j in range(i + 1, len(arr)) if shapely.intersects(g[i], g[j])]).reshape(-1, 2)
    drop = overlap_drops(pairs, n_fixed, new, later=later)
    assert drop.shape == (m,)
    assert not np.any(drop & ~new & ~later)  # without `later`, only new elements go
    kept = np.r_[np.ones(n_fixed, bool), ~drop]
    for i, j in pairs:
        if j < n_fixed or not (kept[i] and kept[j]):
            continue
        if i < n_fixed:  # a kept element overlapping a fixed one is an old one
            assert j >= n_fixed and not new[j - n_fixed]
        elif later and j >= n_fixed:
            raise AssertionError(f"kept {i} and {j} overlap")
    # each dropped element has a reason: a kept earlier element (or a fixed one) it overlaps
    for j in np.flatnonzero(drop) + n_fixed:
        assert any(kept[i] for i, jj in pairs if jj == j)


def test_overlap_drops_is_synths_rule_without_fixed_elements():
    # a chain 0-1-2 of overlaps: 1 goes (overlaps 0), so 2 stays (1 went)
    pairs = np.array([[0, 1], [1, 2]])
    assert overlap_drops(pairs, 0, np.ones(3, bool)).tolist() == [False, True, False]
    assert overlap_drops(pairs, 0, np.ones(3, bool), later=False).tolist() == [False, False, False]


def test_bounds_outside_is_the_exact_test():
    region = Region.rectangle(100, 60)
    stroke = np.array([[50.0, -10], [50, 70]])
    rng = np.random.default_rng(4)
    arr = _arr(rng.uniform(-5, 105, (400, 2)) * [1, 0.6], rot=rng.uniform(0, 6, 400), scale=rng.uniform(0.5, 4, 400))
    out = Bounds(region, [stroke]).outside(arr)
    want = ~region.contains_geometry(arr.geometry, tolerance=1e-7) | shapely.intersects(arr.geometry, shapely.LineString(stroke))
    assert np.array_equal(out, want)
    assert 0 < out.sum() < len(arr)
    assert not Bounds(region).outside(_arr([(10, 10)])).any()


def test_cut_along_keeps_the_side_of_the_point():
    region = Region.rectangle(100, 60)
    wall = np.array([[40.0, -5], [60, 65]])
    left = cut_along(region, [wall], (10, 30), 2.0)
    right = cut_along(region, [wall], (90, 30), 2.0)
    assert left.contains(np.array([[10, 30]]))[0] and not left.contains(np.array([[90, 30]]))[0]
    assert right.contains(np.array([[90, 30]]))[0] and not right.contains(np.array([[10, 30]]))[0]
    assert shapely.distance(left.geometry, shapely.LineString(wall)) >= 2.0 - 1e-6
    assert abs(left.area + right.area + shapely.LineString(wall).buffer(2.0).intersection(region.geometry).area - region.area) < 1.0
    assert cut_along(region, [], (10, 30), 2.0) is region
    assert cut_along(region, [wall], (50, 30), 2.0) is region  # on the cut itself


tile_pts = st.lists(st.tuples(st.floats(-150, 250), st.floats(-150, 250)), min_size=1, max_size=30)


@settings(max_examples=30, deadline=None)
@given(tile_pts)
def test_wrap_stroke_runs_follow_the_stroke_on_the_torus(pts):
    tile = (0.0, 0.0, 100.0, 80.0)
    pts = np.asarray(pts, float)
    runs = wrap_stroke(pts, tile)
    # each run is continuous; a crossing step ends one run beyond the edge and starts the
    # next beyond the opposite edge, so it is in both; the steps are the stroke's on the torus
    steps = [np.diff(r, axis=0) for r in runs]
    for a, b in zip(steps, steps[1:]):
        assert np.allclose(a[-1], b[0])
    merged = np.concatenate([steps[0]] + [s[1:] for s in steps[1:]])
    d = np.diff(pts, axis=0)
    assert len(merged) == len(d)
    assert np.allclose(((merged - d) + [50, 40]) % [100, 80] - [50, 40], 0, atol=1e-6)
    # the stroke starts in the tile; a run's inner points lie in it (its ends may lie
    # beyond an edge, where it crosses)
    inside = [r[1:-1] for r in runs] + [runs[0][:1]]
    for r in inside:
        assert np.all((r >= -1e-9) & (r <= [100 + 1e-9, 80 + 1e-9]))


def test_wrap_stroke_copies_reach_across_the_edge():
    tile = (0.0, 0.0, 100.0, 80.0)
    runs = wrap_stroke(np.array([[98.0, 40], [99, 40]]), tile, radius=5.0)
    assert len(runs) == 2 and np.allclose(runs[1], runs[0] - [100, 0])
    assert len(wrap_stroke(np.array([[50.0, 40], [51, 40]]), tile, radius=5.0)) == 1


@settings(max_examples=40, deadline=None)
@given(points, st.lists(st.tuples(coords, coords), min_size=1, max_size=6), st.floats(0.5, 10))
def test_near_stroke_is_the_distance_to_the_polyline(xy, stroke, radius):
    xy, stroke = np.asarray(xy, float), np.asarray(stroke, float)
    got = near_stroke(xy, stroke, radius)

    def dist(p):  # brute force: distance to each segment (or the point)
        if len(stroke) == 1:
            return np.hypot(*(p - stroke[0]))
        a, b = stroke[:-1], stroke[1:]
        ab = b - a
        t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300), 0, 1)
        return np.min(np.hypot(*(a + t[:, None] * ab - p).T))

    d = np.array([dist(p) for p in xy])
    sure = np.abs(d - radius) > 1e-6  # off the bound, where rounding may go either way
    assert np.array_equal(got[sure], (d <= radius)[sure])
    assert near_stroke(np.zeros((0, 2)), stroke, radius).shape == (0,)

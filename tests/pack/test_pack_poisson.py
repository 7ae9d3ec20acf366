"""strew.pack.poisson_disk: separation, containment, coverage, determinism."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy.spatial import cKDTree

from strew import InputError, Region
from strew.pack import poisson_disk


def _min_distance(pts: np.ndarray) -> float:
    d, _ = cKDTree(pts).query(pts, k=2)
    return float(d[:, 1].min())


@settings(max_examples=25)
@given(
    w=st.floats(5, 60),
    h=st.floats(5, 60),
    r=st.floats(0.4, 4),
    seed=st.integers(0, 2**32 - 1),
)
# a strip narrower than 2r: Bridson's front died out at y = 11 of 27 (found by hypothesis)
@example(w=5.0, h=27.0, r=3.25, seed=117986734)
# the same strip on the shared xoshiro256+ stream (issue 15 point 5): seed 22's front dies
# at its first sample (y < 0.3; the only seed of 0-199 whose front dies here)
@example(w=5.0, h=27.0, r=3.25, seed=22)
def test_points_are_separated_inside_and_cover_the_rectangle(w, h, r, seed):
    pts = poisson_disk((w, h), r, rng=seed)
    assert len(pts) >= 1
    assert np.all((pts >= 0) & (pts < [w, h]))
    if len(pts) > 1:
        assert _min_distance(pts) >= r * (1 - 1e-12)
    # Bridson's maximality: no point of the domain is farther than 2r from a sample
    gx, gy = np.meshgrid(np.linspace(0, w, 60), np.linspace(0, h, 60))
    d, _ = cKDTree(pts).query(np.c_[gx.ravel(), gy.ravel()])
    assert d.max() < 2 * r


def test_region_with_hole_is_respected_and_covered():
    outer = shapely.Point(50, 50).buffer(45)
    hole = shapely.Point(50, 50).buffer(15)
    region = Region(outer.difference(hole))
    r = 2.0
    pts = poisson_disk(region, r, rng=3)
    assert region.contains(pts).all()
    assert not shapely.contains_xy(hole, pts[:, 0], pts[:, 1]).any()
    assert _min_distance(pts) >= r
    # points deeper than 2r inside the region are within 2r of a sample
    gx, gy = np.meshgrid(np.linspace(0, 100, 120), np.linspace(0, 100, 120))
    grid = np.c_[gx.ravel(), gy.ravel()]
    deep = grid[region.contains(grid) & (region.distance_to_boundary(grid) > 2 * r)]
    d, _ = cKDTree(pts).query(deep)
    assert d.max() < 2 * r


def test_several_parts_are_all_filled():
    parts = shapely.MultiPolygon([shapely.box(0, 0, 10, 10), shapely.box(30, 0, 40, 10)])
    pts = poisson_disk(parts, 1.0, rng=0)
    assert (pts[:, 0] < 10).sum() > 20 and (pts[:, 0] > 30).sum() > 20


def test_same_seed_same_points_other_seed_other_points():
    a = poisson_disk((10, 10), 0.5, rng=7)
    b = poisson_disk((10, 10), 0.5, rng=7)
    c = poisson_disk((10, 10), 0.5, rng=8)
    assert np.array_equal(a, b)
    assert not (len(a) == len(c) and np.array_equal(a, c))


def test_density_matches_a_maximal_poisson_disk_set():
    # discs of radius r/2 around the samples: random sequential adsorption jams at
    # 0.547; Bridson with k = 30 stops a little short of it; a plain grid gives 0.785
    pts = poisson_disk((1.0, 1.0), 0.01, rng=1)
    frac = len(pts) * np.pi * 0.005**2
    assert 0.44 < frac < 0.56


def test_variable_radius_keeps_the_larger_radius_between_points():
    def radius(p):
        return np.where(p[:, 0] < 0.5, 0.02, 0.05)  # steps on a cell edge of the radius map

    pts = poisson_disk((1.0, 1.0), radius, rng=4)
    r = radius(pts)
    tree = cKDTree(pts)
    for i, j in tree.query_pairs(0.05):
        assert np.hypot(*(pts[i] - pts[j])) >= max(r[i], r[j])
    left, right = (pts[:, 0] < 0.5).sum(), (pts[:, 0] >= 0.5).sum()
    assert left > 4 * right  # density follows 1 / r**2: (0.05 / 0.02)**2 = 6.25
    # maximal: no point is farther than twice the largest radius within 0.05 of it
    # (samples across the step keep the larger radius) from a sample
    gx, gy = np.meshgrid(np.linspace(0, 1, 80), np.linspace(0, 1, 80))
    grid = np.c_[gx.ravel(), gy.ravel()]
    d, _ = tree.query(grid)
    assert np.all(d < 2 * radius(grid + [0.05, 0.0]))


def test_variable_radius_must_be_positive():
    with pytest.raises(InputError, match="positive"):
        poisson_disk((1, 1), lambda p: p[:, 0] - 0.5)
    with pytest.raises(InputError, match="one radius per point"):
        poisson_disk((1, 1), lambda p: 0.1)


@pytest.mark.parametrize("radius", [0, -1, float("nan"), float("inf"), "x"])
def test_bad_radius_is_rejected(radius):
    with pytest.raises(InputError, match="radius"):
        poisson_disk((1, 1), radius)


def test_bad_region_is_rejected():
    with pytest.raises(InputError, match="region"):
        poisson_disk("square", 0.1)
    with pytest.raises(InputError, match="region"):
        poisson_disk((0, 1), 0.1)

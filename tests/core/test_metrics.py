"""strew.metrics on configurations whose answers are known by construction."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import given
from hypothesis import strategies as st

from strew import Arrangement, Region, Shape, metrics


def grid(n: int, spacing: float = 10.0, size: float = 4.0) -> Arrangement:
    g = (np.arange(n) + 0.5) * spacing
    xx, yy = np.meshgrid(g, g)
    return Arrangement(
        {"sq": Shape.rectangle(size, size)},
        np.zeros(n * n, dtype=int),
        xx.ravel(),
        yy.ravel(),
        region=Region.rectangle(n * spacing, n * spacing),
    )


def test_grid_has_no_overlaps_and_exact_coverage():
    a = grid(10)
    pairs, areas = metrics.overlaps(a)
    assert len(pairs) == 0 and len(areas) == 0
    assert metrics.coverage(a) == pytest.approx(100 * 16 / 10000)
    assert len(metrics.outside(a)) == 0
    assert metrics.density_uniformity(a, window=20) == pytest.approx(0.0)
    nn = metrics.nearest_neighbor_stats(a)
    assert nn["mean"] == pytest.approx(10) and nn["cv"] == pytest.approx(0, abs=1e-12)


def test_overlap_pairs_and_areas():
    a = Arrangement({"sq": Shape.rectangle(2, 2)}, [0, 0, 0, 0], [0, 1, 1.5, 10], [0, 0, 0, 0])
    pairs, areas = metrics.overlaps(a)
    assert pairs.tolist() == [[0, 1], [0, 2], [1, 2]]
    np.testing.assert_allclose(areas, [2.0, 1.0, 3.0])
    assert metrics.overlap_area(a) == pytest.approx(6.0)


def test_touching_squares_do_not_overlap():
    a = Arrangement({"sq": Shape.rectangle(2, 2)}, [0, 0], [0, 2], [0, 0])
    assert len(metrics.overlaps(a)[0]) == 0


def test_adjacent_strips_with_nearly_equal_corners_do_not_overlap():
    # Loi's fig05 stripes at 30 degrees: the shared corner differs by 3e-14 between the two
    # faces, and GEOS's overlay returned the whole narrow strip as their intersection.
    a_pts = [[1000.0, 715.9143339999999], [0.0, 138.56406499999997], [0.0, 230.94010799999998], [1000.0, 808.2903769999999]]
    b_pts = [[1000.0, 808.2903769999999], [0.0, 230.940108], [0.0, 277.128129], [1000.0, 854.478398]]
    shapes = {"a": Shape.polygon(a_pts), "b": Shape.polygon(b_pts)}
    arr = Arrangement(shapes, [0, 1], [0, 0], [0, 0])
    g = arr.geometry
    assert g[0].area > 0 and g[1].area > 0
    pairs, _ = metrics.overlaps(arr)
    assert len(pairs) == 0
    assert metrics.summary(arr)["filled_overlap_pairs"] == 0
    # a real overlap of the same strips is still found, with its area
    shifted = Arrangement(shapes, [0, 1], [0, 0], [0, -20.0])
    pairs, areas = metrics.overlaps(shifted)
    assert pairs.tolist() == [[0, 1]]
    assert areas[0] == pytest.approx(shifted.geometry[0].intersection(shifted.geometry[1]).area, rel=1e-6)


@given(st.floats(0.1, 5), st.floats(-3, 3), st.floats(-3, 3))
def test_overlap_area_of_two_discs_matches_union_identity(r, dx, dy):
    a = Arrangement({"c": Shape.circle(r, 64)}, [0, 0], [0, dx], [0, dy])
    pairs, areas = metrics.overlaps(a)
    g = a.geometry
    inter = g[0].intersection(g[1]).area
    if inter > 1e-9:
        assert pairs.tolist() == [[0, 1]] and areas[0] == pytest.approx(inter)
    else:
        assert len(pairs) == 0


def test_outside_finds_elements_crossing_the_region_and_in_holes():
    reg = Region.from_paths([[(0, 0), (20, 0), (20, 20), (0, 20)], [(8, 8), (12, 8), (12, 12), (8, 12)]])
    a = Arrangement({"d": Shape.circle(1)}, [0, 0, 0, 0], [5, 10, 19.5, 15], [5, 10, 5, 15], region=reg)
    assert metrics.outside(a).tolist() == [1, 2]


def test_density_uniformity_detects_clumping():
    rng = np.random.default_rng(0)
    even = grid(20, spacing=5, size=1)
    pts = rng.normal(50, 8, size=(400, 2)).clip(0, 99)
    clumped = Arrangement({"sq": Shape.rectangle(1, 1)}, np.zeros(400, int), pts[:, 0], pts[:, 1], region=Region.rectangle(100, 100))
    assert metrics.density_uniformity(even, window=10) == pytest.approx(0.0)
    # the default window (about 10 elements each) aliases with the lattice a little
    assert metrics.density_uniformity(even) < 0.25
    assert metrics.density_uniformity(clumped) > 1.0
    assert metrics.density_uniformity(clumped, window=10) > 1.0


def test_kind_fractions_and_summary(two_kind_arrangement):
    f = metrics.kind_fractions(two_kind_arrangement)
    assert f == {"dot": 0.5, "bar": 0.5}
    s = metrics.summary(two_kind_arrangement)
    assert s["count"] == 4 and s["counts"] == {"dot": 2, "bar": 2}
    assert "outside" in s and s["overlap_pairs"] >= 0


def test_metrics_on_empty_and_single():
    e = grid(1).select([])
    assert metrics.coverage(e) == 0.0
    assert np.isnan(metrics.nearest_neighbor_stats(grid(1))["mean"])
    assert len(metrics.overlaps(grid(1))[0]) == 0


def test_summary_splits_filled_overlaps_from_stroke_crossings_and_counts_visible():
    # two overlapping squares (area 2), a stroke crossing one of them, a stroke touching
    # another stroke, and a void square lying on the first: the void counts nowhere
    shapes = {
        "sq": Shape.rectangle(2, 2),
        "ln": Shape.from_geometry(shapely.LineString([(-3, 0), (3, 0)])),
    }
    a = Arrangement(shapes, [0, 0, 1, 1, 0], [0, 1, 0, 6, 0.5], [0, 0, 10, 10, 0]).with_columns(
        void=[False, False, False, False, True]
    )
    a = a.replace(rotation=np.array([0, 0, 0, np.pi / 2, 0.0]))
    s = metrics.summary(a)
    assert s["elements"] == 5 and s["count"] == 4 == metrics.visible_count(a)
    assert s["filled_overlap_pairs"] == 1 and s["filled_overlap_area"] == pytest.approx(2.0)
    # the lines at y=10: one horizontal from x=-3..3, one vertical at x=6 from y=7..13: apart
    pairs, _ = metrics.overlaps(a)
    assert s["overlap_pairs"] == len(pairs)
    assert s["stroke_crossings"] == 0
    b = a.replace(x=np.array([0, 1, 0, 3, 0.5]))  # the vertical line now touches the horizontal one's end
    sb = metrics.summary(b)
    assert sb["stroke_crossings"] == 1 and sb["filled_overlap_pairs"] == 1
    # overlaps() keeps counting every pair, voids included (documented behaviour unchanged)
    assert sb["overlap_pairs"] == len(metrics.overlaps(b)[0]) >= 1 + 1 + 2

"""strew.pack.pack: no overlaps, inside the domain, determinism, parameters, bad input."""

from __future__ import annotations

import time

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import Cancelled, InputError, Region, Shape
from strew.metrics import outside, overlaps
from strew.pack import PackWarning, pack
from strew.pack._exclusive import build_exclusive_regions
from strew.pack._field import DistanceField

HOOK = Shape.polygon([(-15, -15), (15, -15), (15, -7), (-5, -7), (-5, 7), (15, 7), (15, 15), (-15, 15)])
LEAF = Shape.polygon(np.c_[12 * np.cos(np.linspace(0, 2 * np.pi, 24, endpoint=False)), 2.5 * np.sin(np.linspace(0, 2 * np.pi, 24, endpoint=False))])
RING = Shape.from_geometry(shapely.Point(0, 0).buffer(9, 8).difference(shapely.Point(0, 0).buffer(5, 8)))


def _blob_with_hole() -> Region:
    outer = shapely.Point(100, 90).buffer(85, 16)
    hole = shapely.box(80, 70, 130, 110)
    return Region(outer.difference(hole))


def _assert_valid(arr, region):
    assert len(arr) > 0
    pairs, _ = overlaps(arr)
    assert len(pairs) == 0, f"{len(pairs)} overlapping pairs"
    # elements must not even touch: their exclusive regions are disjoint
    g = arr.geometry
    left, right = arr.sindex.query(g, predicate="intersects")
    assert np.all(left == right)
    assert len(outside(arr, region, tolerance=1e-9)) == 0


@pytest.mark.parametrize("method", ["fill-gap", "naive"])
def test_concave_elongated_and_holed_kinds_in_a_region_with_a_hole(method):
    region = _blob_with_hole()
    kw = {"max_failures": 600} if method == "naive" else {}
    arr = pack({"hook": HOOK, "leaf": LEAF, "ring": RING}, region, method=method, scale=(0.4, 0.7), rng=1, **kw)
    _assert_valid(arr, region)
    hole = shapely.box(80, 70, 130, 110)
    assert not shapely.intersects(arr.geometry, shapely.buffer(hole, -1e-6)).any()
    assert arr.region == region
    assert arr.meta["pack"]["algorithm"] == method


@settings(max_examples=12)
@given(
    radii=st.lists(st.floats(0.3, 1.0), min_size=5, max_size=9),
    size=st.floats(3, 8),
    seed=st.integers(0, 1000),
    method=st.sampled_from(["fill-gap", "naive"]),
)
def test_random_star_shapes_never_overlap_or_leave_the_domain(radii, size, seed, method):
    n = len(radii) * 2
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    r = np.repeat(radii, 2) * np.tile([1.0, 0.35], len(radii)) * size
    shape = Shape.polygon(np.c_[r * np.cos(t) + 40, r * np.sin(t) - 7])  # off-centre on purpose
    region = Region(shapely.Polygon([(0, 0), (60, 0), (60, 45), (30, 60), (0, 45)]))
    arr = pack(shape, region, method=method, max_failures=150, rng=seed)
    _assert_valid(arr, region)


def test_fill_gap_adds_to_the_sparse_poisson_step_and_stops_after_200_cancellations():
    region = Region.rectangle(200, 160)
    arr = pack(HOOK, region, scale=(0.5, 0.5), rng=2)
    info = arr.meta["pack"]
    assert 0 < info["sparse"] < len(arr)
    assert info["stopped"] == "200 consecutive cancellations"
    assert info["trials"] >= len(arr) - info["sparse"] + 200


def test_fill_gap_is_about_as_dense_as_naive_dart_throwing():
    region = Region.rectangle(150, 130)
    fg = pack(HOOK, region, scale=(0.5, 0.5), rng=3)
    nv = pack(HOOK, region, scale=(0.5, 0.5), method="naive", max_failures=3000, rng=3)
    assert len(fg) >= 0.85 * len(nv)
    assert fg.meta["pack"]["trials"] < nv.meta["pack"]["trials"] / 5


def test_same_seed_same_result_other_seed_other_result():
    region = _blob_with_hole()
    kinds = {"hook": HOOK, "leaf": LEAF}
    a = pack(kinds, region, scale=(0.4, 0.6), rng=5)
    b = pack(kinds, region, scale=(0.4, 0.6), rng=5)
    c = pack(kinds, region, scale=(0.4, 0.6), rng=6)
    assert a.equals(b)
    assert not (len(a) == len(c) and np.array_equal(a.x, c.x))


def test_kinds_are_placed_cyclically_or_by_weight():
    region = Region.rectangle(120, 120)
    kinds = {"hook": HOOK, "leaf": LEAF, "ring": RING}
    arr = pack(kinds, region, scale=(0.5, 0.5), kind_choice="cycle", rng=1)
    assert np.array_equal(arr.kind, np.arange(len(arr)) % 3)  # §3.2: cyclic
    for choice in ("cycle", "fit"):
        only = pack(kinds, region, scale=(0.5, 0.5), weights={"leaf": 1.0}, kind_choice=choice, rng=1)
        assert set(only.kind_names) == {"leaf"}
        mixed = pack(kinds, region, scale=(0.5, 0.5), weights=[1, 1, 0], kind_choice=choice, rng=1)
        assert set(mixed.kind_names) == {"hook", "leaf"}


def test_rotation_and_scale_ranges_per_kind():
    region = Region.rectangle(150, 150)
    arr = pack(
        {"hook": HOOK, "leaf": LEAF},
        region,
        rotation={"*": (0.2, 0.3), "leaf": (1.0, 1.5)},
        scale={"hook": (0.3, 0.4), "leaf": (0.8, 0.9)},
        rng=4,
    )
    hook = arr.kind_names == "hook"
    assert hook.any() and (~hook).any()
    assert np.all((arr.rotation[hook] >= 0.2) & (arr.rotation[hook] <= 0.3))
    assert np.all((arr.rotation[~hook] >= 1.0) & (arr.rotation[~hook] <= 1.5))
    assert np.all((arr.scale[hook] >= 0.3) & (arr.scale[hook] <= 0.4))
    assert np.all((arr.scale[~hook] >= 0.8) & (arr.scale[~hook] <= 0.9))
    _assert_valid(arr, region)


def test_margin_keeps_elements_apart_and_lowers_density():
    region = Region.rectangle(120, 100)
    tight = pack(LEAF, region, rng=1)
    loose = pack(LEAF, region, margin=2.0, rng=1)
    g = loose.geometry
    left, right = loose.sindex.query(g, predicate="dwithin", distance=4.0 - 1e-6)
    assert np.all(left == right)  # gaps of at least twice the margin
    assert shapely.distance(region.geometry.exterior, g).min() >= 2.0 - 1e-6
    assert len(loose) < 0.8 * len(tight)


def test_exclusive_shape_controls_spacing():
    # a small square whose exclusive region is a disc of radius 6 about it (§3.1)
    square = Shape.rectangle(2, 2)
    disc = Shape.circle(6.0, segments=32)
    arr = pack(square, Region.rectangle(80, 80), exclusive={"shape": disc}, rng=0)
    from scipy.spatial.distance import pdist

    assert pdist(arr.xy).min() >= 12 * np.cos(np.pi / 32) - 1e-9
    assert len(overlaps(arr)[0]) == 0


def test_transform_is_about_the_bounding_box_centre():
    far = Shape.rectangle(4, 2).translated(500, -300)  # local coordinates far from the origin
    region = Region.rectangle(40, 40)
    arr = pack(far, region, rng=0)
    _assert_valid(arr, region)
    centres = shapely.get_coordinates(shapely.centroid(arr.geometry))
    assert np.all((centres > 0) & (centres < 40))


def test_density_grows_with_smaller_exclusive_regions():
    region = Region.rectangle(100, 100)
    small = pack(HOOK, region, scale=(0.3, 0.3), rng=1)
    large = pack(HOOK, region, scale=(0.6, 0.6), rng=1)
    assert len(small) > 2.5 * len(large)


def test_distance_field_local_update_matches_a_global_update():
    region = _blob_with_hole()
    kinds = build_exclusive_regions({"hook": HOOK})
    from strew.pack._exclusive import transform_many

    rng = np.random.default_rng(0)
    xy = rng.uniform(30, 170, size=(12, 2))
    geoms = transform_many(kinds[0].body, xy, rng.uniform(0, 6, 12), np.full(12, 0.4))
    local = DistanceField(region, 2.0)
    for g in geoms:  # one at a time: each update limited to a window
        local.occupy([g])
    glob = DistanceField(region, 2.0)
    glob.dmax = 1e6  # a window larger than the raster: every pixel recomputed
    glob.occupy(list(geoms))
    assert np.array_equal(local.d, glob.d)
    # and the field is the distance to the placed regions where they are nearest
    free = np.argwhere(glob.d > 0)
    pts = np.c_[glob.x0 + (free[:, 1] + 0.5) * 2.0, glob.y0 + (free[:, 0] + 0.5) * 2.0]
    exact = shapely.distance(shapely.union_all(geoms), shapely.points(pts))
    assert np.all(glob.d[free[:, 0], free[:, 1]] <= exact + 1e-9)


def test_progress_and_cancellation():
    calls = []
    arr = pack(HOOK, Region.rectangle(100, 100), scale=(0.4, 0.4), rng=0, progress=lambda d, t, m: calls.append(d))
    assert calls and calls[-1] == len(arr)
    with pytest.raises(Cancelled):
        pack(HOOK, Region.rectangle(100, 100), scale=(0.4, 0.4), rng=0, should_cancel=lambda: True)


# -- bad input -------------------------------------------------------------------------
def test_zero_area_shape_is_rejected():
    flat = Shape.polygon([(0, 0), (10, 0), (20, 0)])
    with pytest.raises(InputError, match="'flat'.*zero area"):
        pack({"flat": flat}, Region.rectangle(50, 50))
    stroke = Shape(({"points": [(0, 0), (10, 0)], "closed": False},))
    with pytest.raises(InputError, match="zero area.*margin"):
        pack({"stroke": stroke}, Region.rectangle(50, 50))
    # a stroke with a margin has an exclusive region
    arr = pack({"stroke": stroke}, Region.rectangle(50, 50), margin=1.0, rng=0)
    assert len(arr) > 5


def test_self_intersecting_polygon_is_repaired_with_a_warning():
    bowtie = Shape.polygon([(0, 0), (10, 10), (10, 0), (0, 10)])
    region = Region.rectangle(60, 60)
    with pytest.warns(PackWarning, match="'bowtie'.*intersects itself"):
        arr = pack({"bowtie": bowtie}, region, rng=0)
    _assert_valid(arr, region)


@pytest.mark.parametrize("method", ["fill-gap", "naive"])
def test_region_smaller_than_every_shape_gives_an_empty_result_quickly(method):
    t0 = time.perf_counter()
    tiny = pack(HOOK, Region.rectangle(5, 5), method=method, rng=0)
    assert len(tiny) == 0 and "no shape fits" in tiny.meta["pack"]["stopped"]
    # a thin leaf (area below the region's) that fits in no orientation
    thin = pack(LEAF, Region.rectangle(15, 15), method=method, rng=0)
    assert len(thin) == 0 and "no shape fits" in thin.meta["pack"]["stopped"]
    assert time.perf_counter() - t0 < 20


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"rotation": (1.0, 0.5)}, "rotation.*inverted"),
        ({"scale": (2.0, 1.0)}, "scale.*inverted"),
        ({"scale": (0.0, 1.0)}, "scale.*positive"),
        ({"scale": {"nope": (1, 2)}}, "scale: unknown kind 'nope'"),
        ({"rotation": (0, float("nan"))}, "rotation.*finite"),
        ({"method": "magic"}, "method"),
        ({"max_failures": 0}, "max_failures"),
        ({"candidates": 0}, "candidates"),
        ({"power": -1}, "power"),
        ({"resolution": 0}, "resolution"),
        ({"resolution": 1e-3}, "resolution.*too fine"),
        ({"weights": [1, 2]}, "weights"),
        ({"weights": [0]}, "weights"),
        ({"exclusive": {"other": HOOK}}, "exclusive: unknown kind"),
        ({"margin": "wide"}, "margin"),
        ({"kind_choice": "best"}, "kind_choice: unknown choice 'best'"),
        ({"scale_choice": "big"}, "scale_choice: unknown choice 'big'"),
        ({"tolerance": 0}, "tolerance: must be in"),
        ({"tolerance": "loose"}, "tolerance: must be a number"),
    ],
)
def test_bad_parameters_name_the_problem(kwargs, match):
    with pytest.raises(InputError, match=match):
        pack(HOOK, Region.rectangle(50, 50), **kwargs)

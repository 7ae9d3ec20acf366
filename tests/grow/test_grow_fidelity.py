"""Grow keeps the exemplar's structure (issue 14), measured by strew.metrics.fidelity.

The suite's grow rows (``benchmarks/fidelity.py``) on smaller regions, plus flow mode on
a curved field, relaxation on noisy rows, a closed boundary stroke and the automatic
repairs of the connectivity (§4, Fig. 3) and of several sizes (§5.1).
"""

from __future__ import annotations


import numpy as np
import pytest
import shapely
from scipy.spatial import cKDTree

from strew import Region
from strew.fields import flow_field
from strew.grow import analyze, grow, size_priority
from strew.metrics import fidelity

from strew_testing import fidelity_suite


make_exemplar = fidelity_suite().make_exemplar


def _region(ex, scale=2.2):
    x0, y0, x1, y1 = ex.region.bounds
    return Region.rectangle(scale * (x1 - x0), scale * (y1 - y0))


@pytest.mark.slow
@pytest.mark.parametrize(
    "name, mode",
    [
        ("rows_noisy", "fixed"),
        ("stones", "fixed"),
        ("two_sizes", "fixed"),
        ("clusters", "fixed"),
        ("stripes", "fixed"),
        ("sparse_voids", "fixed"),
        ("rows_noisy", "rotate"),
        ("bricks", "rotate"),
        ("scales", "rotate"),
    ],
)
def test_suite_rows_are_faithful(name, mode):
    ex = make_exemplar(name)
    region = _region(ex)
    out = grow(ex, region=region, mode=mode, rng=1)
    assert len(out) >= 4 * len(ex)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, rep.failures


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_rings_row_is_faithful_at_the_issues_count(seed):
    # rings are judged at the issue's count (at least 10x the exemplar's elements, the
    # scale of benchmarks/fidelity.py), not at 2.2x: there the hub lattice's phase against
    # the judge's border filter decides density[hub] (9877c79 failed it at seeds 3-5, and
    # 8 start offsets gave 6/8 before and after helper fr's hub targets;
    # benchmarks/fr_rings_phase.py)
    ex = make_exemplar("rings")
    region = _region(ex, 3.5)
    out = grow(ex, region=region, rng=seed)
    assert len(out) >= 10 * len(ex)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, rep.failures


def test_a_variant_nobody_tuned_on_keeps_its_rows():
    # denser, noisier rows at an angle: the diagonals of the jittered squares are
    # ambiguous and must all be flipped one way (Fig. 3) for the rows to grow
    ex = make_exemplar("rows_noisy", rng=11, spacing=9.0, noise=0.06, row_angle=0.3, nx=10, ny=9)
    out = grow(ex, region=_region(ex, 2.0), rng=3)
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, rep.failures


def test_pebbles_keep_their_distance_from_stones_in_a_variant_nobody_tuned_on():
    # the reference never has a pebble as close to a stone as half their smallest
    # distance allowed: stones grew with a pebble too close (nn[stone>pebble] failed)
    ex = make_exemplar("two_sizes", rng=7)
    out = grow(ex, region=_region(ex), rng=3)
    assert len(out) >= 4 * len(ex)
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, rep.failures


def _four_neighbour_share(xy, spacing, inner):
    tree = cKDTree(xy)
    hi = np.array([len(tree.query_ball_point(p, 1.25 * spacing)) - 1 for p in xy[inner]])
    lo = np.array([len(tree.query_ball_point(p, 0.8 * spacing)) - 1 for p in xy[inner]])
    return float(((hi == 4) & (lo == 0)).mean())


def test_relaxation_straightens_noisy_rows():
    ex = make_exemplar("rows_noisy", rng=4, nx=10, ny=9)
    spacing = 11.0
    region = _region(ex, 2.2)
    shares = {}
    for relax in (False, True):
        out = grow(ex, region=region, rng=2, relax=relax)
        inner = region.distance_to_boundary(out.xy) > 2 * spacing
        shares[relax] = _four_neighbour_share(out.xy, spacing, inner)
    assert shares[True] >= 0.9
    assert shares[True] > shares[False]


def test_flow_mode_keeps_the_lattice_on_a_curved_field_and_stays_inside():
    ex = make_exemplar("hex_lattice", nx=8, ny=8)
    spacing = 12.0
    w, h = 24 * spacing, 16 * spacing
    region = Region.rectangle(w, h)
    t = np.linspace(0, w, 30)
    strokes = [np.c_[t, h * (0.3 + 0.05 * np.sin(2 * np.pi * t / w))], np.c_[t, h * (0.7 + 0.05 * np.sin(2 * np.pi * t / w + 0.5))]]
    field = flow_field(strokes)
    out = grow(ex, region=region, mode="flow", flow=field, rng=1)
    assert len(out) > 200
    # no element crosses the region's edge
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    # at least 90% of interior elements keep six neighbours at the lattice spacing
    xy = out.xy
    inner = region.distance_to_boundary(xy) > 2 * spacing
    tree = cKDTree(xy)
    hi = np.array([len(tree.query_ball_point(p, 1.15 * spacing)) - 1 for p in xy[inner]])
    lo = np.array([len(tree.query_ball_point(p, 0.85 * spacing)) - 1 for p in xy[inner]])
    assert ((hi == 6) & (lo == 0)).mean() >= 0.9
    # and the elements follow the field (hexagons: modulo 60°), within the 10° turn
    # allowed at their seeds (relaxation has moved them a little since)
    v = field(xy)
    d = np.mod(out.rotation - np.arctan2(v[:, 1], v[:, 0]), np.pi / 3)
    d = np.minimum(d, np.pi / 3 - d)
    assert np.degrees(d).max() <= 12.0


def _centre_fill(xy, pts, spacing):
    """Share of points ``pts`` with an element centre of ``xy`` within ``spacing``."""
    return float((cKDTree(xy).query(pts)[0] < spacing).mean())


@pytest.mark.parametrize("name", ["stones", "hex_lattice", "two_sizes"])
def test_a_closed_boundary_fills_its_inside(name):
    ex = make_exemplar(name)
    spacing = float(np.median(cKDTree(ex.xy).query(ex.xy, 2)[0][:, 1]))
    # the same measure on the exemplar's own inside: stones of radius 12 at a median
    # spacing of 10.5 (two sizes) leave points more than a spacing from any centre
    # in the exemplar itself (0.88 of them within one); lattices and stones: 1.0
    x0, y0, x1, y1 = ex.region.bounds
    ex_pts = np.mgrid[x0 + spacing : x1 - spacing : 80j, y0 + spacing : y1 - spacing : 80j].reshape(2, -1).T
    ex_fill = _centre_fill(ex.xy, ex_pts, spacing)
    a, b = 10 * spacing, 7 * spacing
    cx, cy = 15 * spacing, 10 * spacing
    t = np.linspace(0, 2 * np.pi, 60)
    oval = np.c_[cx + a * np.cos(t), cy + b * np.sin(t)]
    out = grow(ex, region=Region.rectangle(30 * spacing, 20 * spacing), boundary=[oval], start=(cx, cy), rng=1)
    poly = shapely.Polygon(oval)
    # nothing outside or across the stroke
    assert shapely.contains_xy(poly, out.x, out.y).all()
    assert not shapely.intersects(out.geometry, shapely.LineString(oval)).any()
    # at least 95% of the inside (less a band of half a spacing) has an element
    # centre within one spacing, or 95% of the exemplar's own share where that is less
    g = np.mgrid[cx - a : cx + a : 80j, cy - b : cy + b : 60j].reshape(2, -1).T
    g = g[shapely.contains_xy(poly.buffer(-0.5 * spacing), g[:, 0], g[:, 1])]
    assert _centre_fill(out.xy, g, spacing) >= 0.95 * min(1.0, ex_fill)


def test_ambiguous_diagonals_of_a_jittered_square_grid_are_flipped_one_way():
    ex = make_exemplar("rows_noisy", rng=5, nx=9, ny=8)
    plain = analyze(ex, regularize=False)
    ref = analyze(ex)
    n_plain = plain.ring_arrays()["n"]
    n = ref.ring_arrays()["n"]
    assert len(set(n_plain.tolist())) > 2  # Delaunay: rings of 4 to 8 at random
    assert (n == 6).mean() >= 0.9  # one consistent triangulation: six-rings
    # all diagonals run one way
    xy = ex.xy
    e = ref.edges
    d = xy[e[:, 1]] - xy[e[:, 0]]
    ang = np.mod(np.degrees(np.arctan2(d[:, 1], d[:, 0])), 180.0)
    diag = (np.abs(ang - 45) < 25) | (np.abs(ang - 135) < 25)
    assert diag.any()
    ones = (np.abs(ang[diag] - 45) < 25).mean()
    assert ones in (0.0, 1.0) or min(ones, 1 - ones) < 0.05


def test_irregular_exemplars_keep_their_delaunay_connectivity():
    ex = make_exemplar("stones")
    assert np.array_equal(analyze(ex).edges, analyze(ex, regularize=False).edges)


def test_size_priority_ranks_larger_kinds_first():
    assert size_priority(make_exemplar("stones")) == {}
    assert size_priority(make_exemplar("bricks")) == {}
    p = size_priority(make_exemplar("three_sizes"))
    assert p["large"] > p["medium"] > p["small"]


def test_spray_never_places_an_element_across_the_region_edge():
    from strew.grow import SprayGrowth

    ex = make_exemplar("bricks")
    region = Region.rectangle(160.0, 120.0)
    g = SprayGrowth(ex, radius=40.0, region=region, rng=1)
    # a stroke from inside along the region's edge, with a radius reaching beyond it
    g.add_points([[40.0, 60.0], [80.0, 8.0], [150.0, 8.0], [152.0, 110.0]])
    out = g.grow()
    assert len(out) > 10
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))


def test_only_clustered_exemplars_grow_hubs_first():
    from strew.grow._clusters import satellite_structure

    for name in ("hex_lattice", "bricks", "stones", "two_sizes", "three_sizes", "stripes", "sparse_voids"):
        assert satellite_structure(make_exemplar(name)) is None, name
    for name, hub in (("clusters", "disc"), ("rings", "hub")):
        for v in (None, 5):
            ex = make_exemplar(name, rng=v)
            sat = satellite_structure(ex)
            assert sat is not None and ex.kinds[sat.hub] == hub
            # every satellite belongs to one hub
            m = np.concatenate(sat.members)
            assert len(np.unique(m)) == len(m) and np.all(ex.kind[m] != sat.hub)


@pytest.mark.parametrize("name, variant, mode", [("clusters", 3, "fixed"), ("rings", 9, "fixed"), ("rings", 5, "rotate")])
def test_clustered_variants_nobody_tuned_on_stay_clustered(name, variant, mode):
    # hubs grown through the whole exemplar's connectivity came closer than the exemplar
    # ever has them and left satellites in scatter (clusters: g[disc,disc], g[disc,dot],
    # nn[dot>disc]; rings: five to eight metrics failed)
    ex = make_exemplar(name, rng=variant)
    region = _region(ex, 2.5)
    out = grow(ex, region=region, mode=mode, rng=2)
    assert len(out) >= 4 * len(ex)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    from strew.metrics import summary

    assert summary(out)["overlap_pairs"] == 0
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, rep.failures


def test_clustered_growth_stops_at_count_with_its_connectivity():
    ex = make_exemplar("clusters")
    a = grow(ex, region=_region(ex), count=100, rng=4, connectivity=True)
    b = grow(ex, region=_region(ex), count=100, rng=4, connectivity=True)
    assert len(a) == 100
    assert np.array_equal(a.xy, b.xy) and np.array_equal(a.kind, b.kind)
    e = np.asarray(a.extra["connectivity"]["edges"])
    assert e.min() >= 0 and e.max() < 100
    # each dot is joined to a disc, at the exemplar's disc-to-dot distance
    dot = np.asarray(a.kind_names) == "dot"
    assert dot.any() and (~dot).any()
    linked = e[dot[e[:, 0]] != dot[e[:, 1]]]
    assert set(linked.ravel().tolist()) >= set(np.flatnonzero(dot).tolist())
    d = np.hypot(*(a.xy[linked[:, 0]] - a.xy[linked[:, 1]]).T)
    ring = ex.shapes["disc"].radius + ex.shapes["dot"].radius + 1.5  # the suite's ring_gap
    assert np.all(np.abs(d / ring - 1) < 0.1)


def test_eq5_in_the_local_frame_forgives_a_turn_but_not_a_disorder():
    # issue 14 point 1: rotation mode is judged in the local frame. A lattice turned as a
    # whole keeps every neighbourhood in its elements' frame; shuffled positions do not.
    from strew import Arrangement
    from strew._errors import InputError

    ex = make_exemplar("rows_noisy", nx=8, ny=8)
    j, i = np.mgrid[0:30, 0:30]
    p = np.c_[i.ravel(), j.ravel()] * 11.0 + 5.0
    t = np.radians(8.0)
    c = np.array([165.0, 165.0])
    q = (p - c) @ np.array([[np.cos(t), np.sin(t)], [-np.sin(t), np.cos(t)]]) + c
    region = Region.rectangle(330.0, 330.0)

    def arr(xy, rot, mode):
        keep = region.contains(xy) & (region.distance_to_boundary(xy) > 6)
        n = int(keep.sum())
        return Arrangement(ex.shapes, np.zeros(n, int), xy[keep, 0], xy[keep, 1], np.full(n, rot), region=region, meta={"params": {"mode": mode}})

    straight = fidelity(ex, arr(p, 0.0, "fixed"), local=False).metrics["eq5"]
    turned = arr(q, t, "rotate")
    local = fidelity(ex, turned, local=False).metrics["eq5"]  # auto: the meta says rotate
    glob = fidelity(ex, turned, local=False, eq5_frame="global").metrics["eq5"]
    assert local.value == pytest.approx(fidelity(ex, turned, local=False, eq5_frame="local").metrics["eq5"].value)
    assert local.passed and local.value < 1.5 * straight.value + 1e-9
    assert glob.value > 3 * local.value
    rng = np.random.default_rng(0)
    shaken = arr(q + rng.normal(0, 2.5, q.shape), t, "rotate")
    assert fidelity(ex, shaken, local=False).metrics["eq5"].value > 3 * local.value
    with pytest.raises(InputError, match="eq5_frame"):
        fidelity(ex, turned, eq5_frame="sideways")


def test_flow_mode_bends_a_lattice_sixty_degrees_without_holes():
    # issue 14 point 2: the field turns 60 degrees across the region; the lattice bends
    # with it, keeps its six neighbours on at least 90% of the interior, and the
    # dislocations the bend needs leave no hole (no interior point 0.9 spacing from a centre)
    ex = make_exemplar("hex_lattice", nx=8, ny=8)
    sp = 12.0
    w, h = 30 * sp, 20 * sp
    region = Region.rectangle(w, h)

    def field(p):
        a = np.radians(60.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]

    out = grow(ex, region=region, mode="flow", flow=field, rng=1)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    xy = out.xy
    inner = region.distance_to_boundary(xy) > 2 * sp
    tree = cKDTree(xy)
    hi = np.array([len(tree.query_ball_point(p, 1.15 * sp)) - 1 for p in xy[inner]])
    lo = np.array([len(tree.query_ball_point(p, 0.85 * sp)) - 1 for p in xy[inner]])
    assert ((hi == 6) & (lo == 0)).mean() >= 0.9
    g = np.mgrid[2 * sp : w - 2 * sp : 3.0, 2 * sp : h - 2 * sp : 3.0].reshape(2, -1).T
    assert tree.query(g)[0].max() < 0.9 * sp
    # and the elements follow the field (hexagons: modulo 60 degrees): the turn at each
    # seed is held within 10 degrees of the field, which goes on turning past it
    v = field(xy)
    d = np.degrees(np.mod(out.rotation - np.arctan2(v[:, 1], v[:, 0]), np.pi / 3))
    d = np.minimum(d, 60 - d)
    assert np.median(d) <= 10.0 and d.max() <= 20.0


def test_priority_changes_which_kind_grows_first_and_fills():
    # issue 14 point 4: §5.1 priorities decide which kind grows first; either way the
    # region fills (its largest gap within 1.3x the exemplar's)
    ex = make_exemplar("two_sizes")
    x0, y0, x1, y1 = ex.region.bounds
    w, h = 2.0 * (x1 - x0), 2.0 * (y1 - y0)
    s = float(np.median(cKDTree(ex.xy).query(ex.xy, 2)[0][:, 1]))
    ex_gap = cKDTree(ex.xy).query(np.mgrid[s : x1 - x0 - s : 2.0, s : y1 - y0 - s : 2.0].reshape(2, -1).T)[0].max()
    g = np.mgrid[2 * s : w - 2 * s : 2.0, 2 * s : h - 2 * s : 2.0].reshape(2, -1).T
    lead = {}
    for first, then in (("stone", "pebble"), ("pebble", "stone")):
        out = grow(ex, region=Region.rectangle(w, h), rng=1, priority={first: 1, then: 0})
        names = np.asarray(out.kind_names)
        lead[first] = (names[:40] == "stone").mean()  # §5.1 ranks seeds within 5 l only
        assert (names == then).sum() >= 0.1 * len(out)
        assert cKDTree(out.xy).query(g)[0].max() <= 1.3 * ex_gap
    assert lead["stone"] >= lead["pebble"] + 0.3


@pytest.mark.slow
def test_sparse_apples_keep_their_distance_in_a_variant_nobody_tuned_on():
    # saturated sparse discs: the reference never has two apples closer than about 30;
    # Fig. 6 (b)'s l_short let them come to 13-19 (nn[apple>apple] failed)
    ex = make_exemplar("sparse_voids", rng=1)
    out = grow(ex, region=_region(ex), rng=1)
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, rep.failures
    a = out.xy[np.asarray(out.kind_names) == "apple"]
    e = ex.xy[np.asarray(ex.kind_names) == "apple"]
    d_out = cKDTree(a).query(a, 2)[0][:, 1].min()
    d_ex = cKDTree(e).query(e, 2)[0][:, 1].min()
    assert d_out >= 0.8 * d_ex  # (relaxation moves elements a little after placement)


@pytest.mark.slow
def test_small_stones_stay_as_near_a_large_one_as_the_reference_has_them():
    # three sizes 1:2:4: where the seeds of the large kind die, small stones filled
    # gaps in it that the reference never has (nn[small>large] failed 0/5 at 3.5x);
    # a seed that misses a larger kind first tries to become one (§5.1 departure)
    ex = make_exemplar("three_sizes")
    region = _region(ex)
    out = grow(ex, region=region, rng=2)
    assert len(out) >= 4 * len(ex)

    def far(arr, a, b):  # nearest b from each a, where the region's edge hides none (Hanisch)
        xy, k = arr.xy, arr.kind
        d = cKDTree(xy[k == b]).query(xy[k == a])[0]
        return d[arr.region.distance_to_boundary(xy[k == a]) > d]

    small, large = ex.kinds.index("small"), ex.kinds.index("large")
    # the 90th percentile: 23.1 in the reference, 31.0 before, 26.3 now
    assert np.quantile(far(out, small, large), 0.9) <= 1.2 * np.quantile(far(ex, small, large), 0.9)
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.metrics["nn[small>large]"].passed, rep.metrics["nn[small>large]"]


def _six_neighbour_share(xy, sp, inner):
    tree = cKDTree(xy)
    hi = np.array([len(tree.query_ball_point(p, 1.15 * sp)) - 1 for p in xy[inner]])
    lo = np.array([len(tree.query_ball_point(p, 0.85 * sp)) - 1 for p in xy[inner]])
    return float(((hi == 6) & (lo == 0)).mean())


@pytest.mark.parametrize("degrees, share", [(60.0, 0.97), (90.0, 0.82)])
def test_flow_mode_bends_a_lattice_with_few_defects_and_no_holes(degrees, share):
    # issue 14 point 2: the field turns 60 or 90 degrees across 30 spacings. The fitted
    # frame is carried on by the field's turn from the neighbours (was: 92.3% / 78.5%,
    # the lattice lagging the field on one side and leading it on the other, seams
    # where they met); where it bends too sharply the defects leave no hole
    ex = make_exemplar("hex_lattice", nx=8, ny=8)
    sp = 12.0
    w, h = 30 * sp, 20 * sp
    region = Region.rectangle(w, h)

    def field(p):
        a = np.radians(degrees) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]

    out = grow(ex, region=region, mode="flow", flow=field, rng=1)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    xy = out.xy
    assert _six_neighbour_share(xy, sp, region.distance_to_boundary(xy) > 2 * sp) >= share
    g = np.mgrid[2 * sp : w - 2 * sp : 3.0, 2 * sp : h - 2 * sp : 3.0].reshape(2, -1).T
    assert cKDTree(xy).query(g)[0].max() < 0.8 * sp


@pytest.mark.parametrize("first, then", [("brick_red", "brick_ochre"), ("brick_ochre", "brick_red")])
def test_priority_on_bricks_leaves_no_gap(first, then):
    # issue 14 point 4: with a priority, a brick's slot closed in a little while it
    # waited (§5.1) or it had more placed neighbours than a ring; the seed died and a
    # brick was missing (largest gap 1.39-1.51x the exemplar's). Now within 1.1x and
    # no two bricks overlap.
    ex = make_exemplar("bricks")
    x0, y0, x1, y1 = ex.region.bounds
    w, h = 2.0 * (x1 - x0), 2.0 * (y1 - y0)
    s = float(np.median(cKDTree(ex.xy).query(ex.xy, 2)[0][:, 1]))
    ex_gap = cKDTree(ex.xy).query(np.mgrid[s : x1 - x0 - s : 2.0, s : y1 - y0 - s : 2.0].reshape(2, -1).T)[0].max()
    g = np.mgrid[2 * s : w - 2 * s : 2.0, 2 * s : h - 2 * s : 2.0].reshape(2, -1).T
    for seed in (1, 2):
        out = grow(ex, region=Region.rectangle(w, h), rng=seed, priority={first: 1, then: 0})
        assert cKDTree(out.xy).query(g)[0].max() <= 1.1 * ex_gap
        geoms = out.geometry
        tree = shapely.STRtree(geoms)
        a, b = tree.query(geoms, predicate="intersects")
        pairs = a < b
        areas = shapely.area(shapely.intersection(geoms[a[pairs]], geoms[b[pairs]]))
        assert np.all(areas <= 1e-6 * shapely.area(geoms).min())


@pytest.mark.slow
def test_fixed_mode_bricks_stay_on_one_lattice():
    # issue 14 point 1: an element nudged off its slot in the open front (fixed mode)
    # was followed by the seeds fitted to it, and two fronts met half a course out of
    # step (seed 5: 5.9% of the bricks more than a quarter course off the first
    # brick's lattice, regularity failed). Only enclosed slots nudge now.
    ex = make_exemplar("bricks")
    q, hh = 22.0 + 1.6, 9.0 + 1.6  # make.py's bricks: length + mortar, height + mortar
    basis = np.array([[q, 0.0], [0.5 * q, hh]]).T  # running bond
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    for seed in (4, 5):
        out = grow(ex, region=region, rng=seed)
        c = np.linalg.solve(basis, (out.xy - out.xy[0]).T).T
        off = np.abs((c - np.round(c)) @ basis.T)
        assert (off[:, 1] > 0.25 * hh).mean() <= 0.02

"""Issue 13: synth reproduces the fidelity suite's exemplars, palettes share a region,
the per-element radius is the collision bound (§4.1), the brush leaves no holes."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Arrangement, InputError, Region, Shape, save
from strew.cli import main
from strew.metrics import fidelity
from strew.synth import Palette, brush, erase, new_state, synthesize
from strew.synth._exemplars import grid, stones, stripes

suite = fidelity_suite()

# The suite's classes that synth reproduces (issue 13, point 1): all twelve.
FAITHFUL = ["hex_lattice", "rows_noisy", "bricks", "scales", "stones", "two_sizes", "clusters", "three_sizes", "rings", "stripes", "sparse_voids", "sticks"]


@pytest.mark.slow
@pytest.mark.parametrize("name", FAITHFUL)
def test_suite_exemplar_is_reproduced_faithfully(name):
    """The suite's exemplar, synthesized at default settings over 4x its frame's area
    (the issue's runs use 10x; see benchmarks/results/synth_fidelity*)."""
    ex = suite.make_exemplar(name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0))
    out = synthesize(ex, region, rng=1, measure=False)
    rep = fidelity(ex, out, region)
    assert rep.faithful, rep.failures


@pytest.mark.parametrize("name", ["rows_noisy", "three_sizes"])
def test_jittered_rows_and_three_sizes_are_faithful(name):
    """The two classes that failed for synth: noisy rows (the optimisation averaged the
    rows' jitter away: neighbour bearings too regular) and three sizes 1:2:4 (large
    stones displaced smaller ones until they were 1.5x their density). Another seed
    than the slow test's, 4x the frame's area."""
    ex = suite.make_exemplar(name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0))
    out = synthesize(ex, region, rng=2, measure=False)
    rep = fidelity(ex, out, region, eq5=False)
    assert rep.faithful, rep.failures


@pytest.mark.parametrize("variant", [1, 3])
def test_untuned_cluster_variants_are_faithful(variant):
    """Clusters drawn at other seeds (nobody tuned on them): before the fixes, variant 1
    grew dots without discs (dots 1.7x too dense: dot seeds copied a disc's
    neighbourhood, and a disc's ring was copied where an output dot had been paired
    with the disc) and variant 3 stopped growing (the discs' r-bar did not reach the
    next cluster). 4x the frame's area."""
    ex = suite.make_exemplar("clusters", rng=variant)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0))
    out = synthesize(ex, region, rng=2, measure=False)
    rep = fidelity(ex, out, region, eq5=False, local=False)
    assert rep.faithful, rep.failures
    dots, discs = out.select(out.kind == out.kinds.index("dot")), out.select(out.kind == out.kinds.index("disc"))
    near = cKDTree(discs.xy).query(dots.xy)[0] < 1.3 * 12.5  # within 1.3 ring radii of a disc
    assert near.mean() > 0.9


def test_optimisation_keeps_the_exemplars_jitter(monkeypatch):
    """§5.2-5.3 extension: the least-squares blend of many predictions put every tile
    of noisy rows on its ideal lattice point. With predictions that carry each tile's own
    jitter (``_optimize._own_jitter``; jittered lattices no longer take the soft
    threshold, so ``noise_floor`` does not matter there) the spread of nearest-neighbour
    distances stays near the exemplar's; with the blend alone it halves."""
    import strew.synth._optimize as opt

    ex = suite.make_exemplar("rows_noisy")
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0))

    def nn_spread(arr: Arrangement) -> float:
        inner = (arr.x > arr.x.min() + 15) & (arr.x < arr.x.max() - 15) & (arr.y > arr.y.min() + 15) & (arr.y < arr.y.max() - 15)
        d = cKDTree(arr.xy).query(arr.xy[inner], k=5)[0][:, 1:]
        return float(d.std())

    own = nn_spread(ex)
    kept = nn_spread(synthesize(ex, region, rng=3, measure=False))
    kept_no_floor = nn_spread(synthesize(ex, region, rng=3, measure=False, noise_floor=0.0))
    monkeypatch.setattr(opt, "_own_jitter", lambda state, h, center, hp, off: off)
    flat = nn_spread(synthesize(ex, region, rng=3, measure=False, noise_floor=0.0))
    assert kept >= 0.75 * own
    assert kept_no_floor >= 0.75 * own
    assert flat < 0.75 * own  # the blend alone does flatten the jitter
    with pytest.raises(InputError, match="noise_floor"):
        synthesize(ex, region, rng=3, noise_floor=-1.0)


SEAMLESS = ["bricks", "scales", pytest.param("hex_lattice", marks=pytest.mark.slow), pytest.param("stripes", marks=pytest.mark.slow),
            pytest.param("sparse_voids", marks=pytest.mark.slow)]


@pytest.mark.parametrize("name", SEAMLESS)
def test_local_fidelity_map_has_no_failing_window(name):
    """Issue 13 point 2 at a moderate size (about 12x the exemplar's area, the
    fidelity suite's default): every window of the local fidelity map passes, so
    growth fronts meet without seams. (At 50x this holds for these classes; stones,
    clusters, three_sizes and rings still have failing windows there.)"""
    ex = suite.make_exemplar(name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = synthesize(ex, region, rng=1, measure=False)
    rep = fidelity(ex, out, region, eq5=False)
    assert rep.faithful, rep.failures
    score = np.asarray(rep.local["score"], float)
    assert np.isfinite(score).sum() >= 10  # the map has windows to judge
    assert rep.local["worst"]["score"] <= 1.0, rep.local["worst"]


def _shares(out: Arrangement, region: Region, names) -> dict[str, float]:
    """Share of the region nearest to each exemplar's elements."""
    x0, y0, x1, y1 = region.bounds
    g = np.mgrid[x0 + 2 : x1 : 4.0, y0 + 2 : y1 : 4.0].reshape(2, -1).T
    _, j = cKDTree(out.xy).query(g)
    owner = np.asarray(out["exemplar"])[j]
    return {n: float(np.mean(owner == n)) for n in names}


@pytest.mark.parametrize("weights", [{"grid": 1.0, "stripes": 1.0}, {"grid": 2.0, "stripes": 1.0, "stones": 1.0}])
def test_palette_weights_are_shares_of_the_region(weights):
    pal = Palette({"grid": grid(), "stripes": stripes(), "stones": stones()})
    region = Region.rectangle(360, 300)
    out = synthesize(pal, region, selection=weights, rng=3, measure=False)
    shares = _shares(out, region, list(weights))
    total = sum(weights.values())
    for name, w in weights.items():
        assert abs(shares[name] - w / total) <= 0.1, shares
    # each texture keeps its own kinds
    kinds = {"grid": {"square"}, "stripes": {"dot", "bar"}, "stones": {"stone"}}
    names = out.kind_names
    ex = np.asarray(out["exemplar"])
    for name in weights:
        assert set(names[ex == name]) <= kinds[name]


def test_selection_with_regions_puts_each_texture_in_its_region():
    pal = Palette({"grid": grid(), "stripes": stripes()})
    left, right = Region.rectangle(120, 160), Region.rectangle(120, 160, 120, 0)
    out = synthesize(pal, Region.rectangle(240, 160), selection={"grid": left, "stripes": right}, rng=1, measure=False)
    ex = np.asarray(out["exemplar"])
    assert (ex == "grid").sum() > 50 and (ex == "stripes").sum() > 50
    assert np.all(out.x[ex == "grid"] <= 120) and np.all(out.x[ex == "stripes"] >= 120)
    with pytest.raises(InputError, match="region for every selected exemplar"):
        synthesize(pal, Region.rectangle(240, 160), selection={"grid": left, "stripes": 1.0})


def test_cli_select_name_equals_region_file(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    save(grid(), "g.json")
    save(stripes(), "st.json")
    for name, x in (("left", 0), ("right", 150)):
        Path(f"{name}.svg").write_text(f'<svg xmlns="http://www.w3.org/2000/svg" width="300" height="200"><path d="M{x} 0 H{x + 150} V200 H{x} Z"/></svg>')
    rc = main(["synth", "g.json", "st.json", "--select", "g=left.svg", "--select", "st=right.svg", "--seed", "1", "--out", "o.json", "--quiet"])
    assert rc == 0
    from strew import load

    out = load("o.json")
    ex = np.asarray(out["exemplar"])
    assert set(ex) == {"g", "st"}
    assert np.all(out.x[ex == "g"] <= 150) and np.all(out.x[ex == "st"] >= 150)
    assert out.region.area == pytest.approx(300 * 200)
    assert main(["synth", "g.json", "st.json", "--select", "g=left.svg", "--select", "st:1", "--out", "x.json", "--quiet"]) == 2
    assert main(["synth", "g.json", "--select", "g=", "--size", "50x50", "--out", "x.json", "--quiet"]) == 2


def test_given_radius_is_the_collision_bound():
    """§4.1: with radii given, no two output elements come closer than r_p + r_q, even
    when another kind of the exemplar (sticks, default radius) has bounding discs that
    overlap the given ones, which used to shrink every kind's bound by one factor."""
    rng = np.random.default_rng(0)
    g = np.mgrid[0:8, 0:8].reshape(2, -1).T * 16.0 + rng.normal(0, 0.3, (64, 2))
    sticks = g[:-1] + np.array([8.0, 8.0])
    xy = np.r_[g, sticks]
    kind = np.r_[np.zeros(len(g), int), np.ones(len(sticks), int)]
    rot = np.zeros(len(xy))
    shapes = {"disc": Shape.circle(3.0), "stick": Shape.rectangle(14.0, 1.0)}
    radius = np.r_[np.full(len(g), 8.0), np.full(len(sticks), np.nan)]
    ex = Arrangement(shapes, kind, xy[:, 0], xy[:, 1], rot, columns={"radius": radius})
    out = synthesize(ex, Region.rectangle(200, 200), rng=2, measure=False)
    discs = out.xy[out.kind_names == "disc"]
    assert len(discs) > 60
    d, _ = cKDTree(discs).query(discs, k=2)
    assert d[:, 1].min() >= 16.0 - 1e-9  # given r = 8; the exemplar's own discs come 15.2 apart


@pytest.mark.parametrize("name", ["hex_lattice", "stones"])
def test_brush_fills_its_band_without_holes(name):
    """§5.4: a stroke brushed segment by segment leaves no gap wider than the
    exemplar's own widest; erasing part of it and brushing again restores it."""
    ex = suite.make_exemplar(name)
    a = float(np.median(cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]))
    radius = 5.0 * a
    state = new_state(ex, Region.rectangle(40 * a, 24 * a), rng=1)
    xs = np.linspace(7 * a, 33 * a, 27)
    line = np.c_[xs, 12 * a + 4 * a * np.sin(xs / (6 * a))]
    for i in range(0, len(line), 4):
        brush(state, line[i : i + 5], radius)
    probe = np.random.default_rng(0).uniform(ex.xy.min(0) + 3 * a, ex.xy.max(0) - 3 * a, (3000, 2))
    own = float(cKDTree(ex.xy).query(probe)[0].max())
    band = shapely.LineString(line).buffer(radius - 2 * a)
    b = band.bounds
    grid_pts = np.mgrid[b[0] : b[2] : a / 3, b[1] : b[3] : a / 3].reshape(2, -1).T
    grid_pts = grid_pts[shapely.contains_xy(band, grid_pts[:, 0], grid_pts[:, 1])]

    def widest_gap() -> float:
        return float(cKDTree(state.to_arrangement(clip=False).xy).query(grid_pts)[0].max())

    assert widest_gap() <= 1.2 * own
    n = state.n
    assert erase(state, line[10:16], 2.5 * a) > 0
    brush(state, line[9:17], radius)
    assert widest_gap() <= 1.2 * own
    assert state.n >= 0.97 * n


def test_elongated_shapes_are_tested_as_shapes_while_growing():
    """Sticks' collision discs are shrunk to their spacing (§4.1 extension), so growing
    tests the shapes themselves: the output needs no overlap clean-up, keeps the
    exemplar's density, and is faithful. (Shrunk discs alone packed about 8x more sticks
    than survived the clean-up.)"""
    from strew.metrics import overlaps
    from strew.synth import fill

    ex = suite.make_exemplar("sticks", np.random.default_rng(7))
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(1.6 * (x1 - x0), 1.6 * (y1 - y0))
    state = new_state(ex, region, rng=2)
    fill(state)
    # every element the state holds, those across the region's edge included
    assert len(overlaps(state.to_arrangement(drop_overlaps=False, clip=False))[0]) == 0
    raw = state.to_arrangement(drop_overlaps=False)
    assert len(state.to_arrangement()) == len(raw)
    rep = fidelity(ex, raw, region)
    assert rep.faithful, rep.failures


def test_elongated_copies_are_limited_by_their_shape_neighbourhood():
    """Sticks are limited by shape, not by centre circles (issue 13, helper s30t): a
    copy is refused when more output shapes come within its kind's bounding radius of
    its shape than its exemplar element has there (``_grow.shape_limits``). A copy laid
    exactly on an output stick has that stick's shape neighbours plus the stick itself."""
    from strew.synth import _grow, fill
    from strew.synth._shapes import element_geometries

    ex = suite.make_exemplar("sticks", np.random.default_rng(7))
    x0, y0, x1, y1 = ex.region.bounds
    state = new_state(ex, Region.rectangle(1.4 * (x1 - x0), 1.4 * (y1 - y0)), rng=2)
    fill(state)
    prep = state.prep
    lim, reach = _grow.shape_limits(prep)
    sel = prep.selected_elements
    assert (lim[sel] >= 0).mean() > 0.5  # one-kind exemplar of shrunk discs: limited
    idx = np.flatnonzero(lim[state.src] >= 0)
    g = element_geometries(prep, state.src, state.pos)
    d = shapely.distance(g[idx][:, None], g[None, :])
    own = np.count_nonzero(d <= reach[state.src[idx]][:, None], axis=1) - 1
    got = _grow._shape_crowded(state, state.pos[idx], state.src[idx], lim, reach)
    want = own + 1 > lim[state.src[idx]]
    assert want.any() and (~want).any()
    np.testing.assert_array_equal(got, want)

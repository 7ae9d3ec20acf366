"""strew.metrics.fidelity: each metric on cases with known answers, and the verdicts.

A faithful copy (translated, or tiled from a periodic exemplar) passes; a uniform scatter
with the same kind counts fails on a clustered exemplar; flipped kind fractions fail; a
jittered lattice loses regularity; g(r) is about 1 for Poisson points, also inside an
L-shaped region (edge correction), and peaks at a hexagonal lattice's distances.
"""

from __future__ import annotations

import functools
import json

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import Arrangement, Region, Shape
from strew._errors import InputError
from strew.arrangement import concat
from strew.metrics import FidelityReport, fidelity, nearest_neighbor_distances, pair_correlation

from strew_testing import fidelity_suite


suite = fidelity_suite()


@functools.lru_cache(maxsize=None)
def exemplar(name: str) -> Arrangement:
    """The suite's default exemplar (arrangements are immutable: safe to share)."""
    return suite.make_exemplar(name)


def tile(ex: Arrangement, nx: int, ny: int) -> Arrangement:
    """Copies of ``ex`` side by side, one frame apart."""
    x0, y0, x1, y1 = ex.region.bounds
    w, h = x1 - x0, y1 - y0
    parts = [Arrangement(ex.shapes, ex.kind, ex.x + i * w, ex.y + j * h, ex.rotation, ex.scale, columns=ex.columns) for i in range(nx) for j in range(ny)]
    return concat(parts).replace(region=Region.rectangle(nx * w, ny * h, x0, y0))


def moved(a: Arrangement, dx: float, dy: float) -> Arrangement:
    reg = Region(shapely.affinity.translate(a.region.geometry, dx, dy))
    return Arrangement(a.shapes, a.kind, a.x + dx, a.y + dy, a.rotation, a.scale, columns=a.columns, region=reg)


def poisson(n: int, region: Region, rng: int = 0) -> Arrangement:
    g = np.random.default_rng(rng)
    x0, y0, x1, y1 = region.bounds
    pts = g.uniform((x0, y0), (x1, y1), (int(n * 1.5 * (x1 - x0) * (y1 - y0) / region.area), 2))
    pts = pts[region.contains(pts)][:n]
    return Arrangement({"dot": Shape.circle(0.1)}, np.zeros(len(pts), int), pts[:, 0], pts[:, 1], region=region)


@pytest.fixture(scope="module")
def clusters():
    return exemplar("clusters")


@pytest.fixture(scope="module")
def rows():
    return exemplar("rows_noisy")


# -- g(r) -------------------------------------------------------------------------------


def test_g_of_poisson_points_is_about_one():
    out = pair_correlation(poisson(4000, Region.rectangle(200, 200)))
    g = out["g"]["dot,dot"]
    assert np.all(np.abs(g[3:] - 1.0) < 0.15), g
    assert abs(np.mean(g[3:]) - 1.0) < 0.05


def test_g_edge_correction_in_an_l_shaped_region():
    L = Region(shapely.Polygon([(0, 0), (200, 0), (200, 80), (80, 80), (80, 200), (0, 200)]))
    arr = poisson(3000, L, rng=1)
    out = pair_correlation(arr, r_max=25.0, bins=10)
    g = out["g"]["dot,dot"]
    assert np.all(np.abs(g - 1.0) < 0.12), g
    # without a correction (the bounding box as window), g would sag: the correction matters
    naive = pair_correlation(arr.replace(region=None), r_max=25.0, bins=10)["g"]["dot,dot"]
    assert np.mean(np.abs(naive - 1.0)) > np.mean(np.abs(g - 1.0))


def test_g_of_a_hexagonal_lattice_peaks_at_the_lattice_distances():
    ex = suite.make_exemplar("hex_lattice", nx=20, ny=20)
    a = 12.0
    out = pair_correlation(ex, r_max=2.5 * a, bins=50)
    r, g = out["r"], out["g"]["hex,hex"]
    assert np.all(g[r < 0.8 * a] == 0)
    for d in (a, np.sqrt(3) * a, 2 * a):
        assert g[np.abs(r - d) <= 0.6].max() > 3.0, d
    assert g[np.argmin(np.abs(r - 1.35 * a))] == 0


def test_swapping_kinds_changes_the_cross_kind_g():
    ex = exemplar("stripes")
    g = pair_correlation(ex)["g"]
    rng = np.random.default_rng(0)
    shuffled = Arrangement(ex.shapes, rng.permutation(ex.kind), ex.x, ex.y, ex.rotation, region=ex.region)
    gs = pair_correlation(shuffled)["g"]
    # stripes put unlike kinds far apart at short range: shuffling raises the cross g there
    assert gs["dot,bar"][3:10].mean() > g["dot,bar"][3:10].mean() + 0.2


def test_nearest_neighbor_distances_of_a_square_grid():
    g = np.mgrid[0:10, 0:10].reshape(2, -1).T * 5.0
    kind = (np.arange(100) // 10) % 2  # alternate columns
    a = Arrangement({"a": Shape.circle(1), "b": Shape.circle(1)}, kind, g[:, 0], g[:, 1])
    nn = nearest_neighbor_distances(a)
    assert nn["a>a"]["median"] == pytest.approx(5.0)
    assert nn["a>b"]["median"] == pytest.approx(5.0)


# -- verdicts --------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["clusters", "rows_noisy", "hex_lattice", "stones", "two_sizes", "sparse_voids"])
def test_a_translated_copy_is_faithful(name):
    ex = exemplar(name)
    rep = fidelity(ex, moved(ex, 1234.5, -321.0), eq5=False)
    assert rep.faithful, rep.failures


@pytest.mark.parametrize("name", ["clusters", "rows_noisy", "hex_lattice", "bricks", "scales", "rings"])
def test_a_tiled_copy_is_faithful(name):
    ex = exemplar(name)  # these frames are one period: copies tile seamlessly
    rep = fidelity(ex, tile(ex, 3, 3), eq5=name == "clusters")
    assert rep.faithful, rep.failures
    assert rep.info["area_ratio"] > 4


def test_a_uniform_scatter_fails_on_clusters(clusters):
    big = tile(clusters, 3, 3)
    rng = np.random.default_rng(1)
    x0, y0, x1, y1 = big.region.bounds
    scatter = Arrangement(big.shapes, big.kind, rng.uniform(x0, x1, len(big)), rng.uniform(y0, y1, len(big)), region=big.region)
    rep = fidelity(clusters, scatter, eq5=False)
    assert not rep.faithful
    assert {"g[disc,dot]", "nn[dot>disc]"} <= set(rep.failures)
    assert rep.metrics["fraction[dot]"].passed  # same counts: fractions cannot tell


def test_flipped_kind_fractions_fail(clusters):
    big = tile(clusters, 3, 3)
    flipped = Arrangement(big.shapes, 1 - big.kind, big.x, big.y, region=big.region)
    rep = fidelity(clusters, flipped, eq5=False)
    assert {"fraction[disc]", "fraction[dot]", "density[disc]", "density[dot]"} <= set(rep.failures)
    m = rep.metrics["fraction[dot]"]
    assert m.exemplar == pytest.approx(1 - m.result, abs=0.02)  # the interior is most of the tiling


def test_a_jittered_lattice_fails_regularity_and_a_turned_one_keeps_it(rows):
    big = tile(rows, 3, 3)
    rng = np.random.default_rng(2)
    jit = Arrangement(big.shapes, big.kind, big.x + rng.normal(0, 2.0, len(big)), big.y + rng.normal(0, 2.0, len(big)), rng.normal(0, 0.3, len(big)), region=big.region)
    rep = fidelity(rows, jit, eq5=False)
    assert rep.info["lattice"]
    assert "regularity" in rep.failures
    assert rep.metrics["regularity"].result < 0.5
    # the whole lattice turned, each tile with it: the local frame keeps it regular
    t = 0.6
    c, s = np.cos(t), np.sin(t)
    reg = Region(shapely.affinity.rotate(big.region.geometry, t, origin=(0, 0), use_radians=True))
    turned = Arrangement(big.shapes, big.kind, c * big.x - s * big.y, s * big.x + c * big.y, big.rotation + t, region=reg)
    rep = fidelity(rows, turned, eq5=False)
    assert rep.metrics["regularity"].passed, rep.metrics["regularity"]
    assert rep.metrics["orientation.bearing"].passed


def test_non_lattice_exemplars_report_regularity_not_applicable(clusters):
    rep = fidelity(clusters, moved(clusters, 5, 5), eq5=False)
    assert not rep.info["lattice"]
    assert not rep.metrics["regularity"].applicable


def test_tolerances_follow_the_stated_rule(clusters):
    from strew._fidelity import FLOORS, MULTIPLE

    rep = fidelity(clusters, tile(clusters, 3, 3), eq5=False)
    for name, m in rep.metrics.items():
        if not m.applicable:
            continue
        fam = name.split("[")[0].split(".")[0]
        factor = np.sqrt(1 + rep.info["exemplar_window_area"] / rep.info["result_window_area"])
        assert m.tolerance == pytest.approx(max(FLOORS[fam], MULTIPLE * m.spread / 2 * factor)), name
        assert m.passed == (m.value <= m.tolerance)
    assert rep.metrics["fraction[dot]"].tolerance >= 0.05
    assert rep.metrics["density[dot]"].tolerance >= 0.10


def test_eq5_is_zero_for_a_copy_and_large_for_a_scatter(clusters):
    rep = fidelity(clusters, moved(clusters, 10, 10))
    assert rep.metrics["eq5"].value == pytest.approx(0.0, abs=1e-6)
    # across the seams of a tiling, neighbourhoods join that the crop never shows whole
    rep = fidelity(clusters, tile(clusters, 2, 2))
    assert rep.metrics["eq5"].value < 0.25 * rep.metrics["eq5"].tolerance
    big = tile(clusters, 2, 2)
    rng = np.random.default_rng(3)
    x0, y0, x1, y1 = big.region.bounds
    scatter = Arrangement(big.shapes, big.kind, rng.uniform(x0, x1, len(big)), rng.uniform(y0, y1, len(big)), region=big.region)
    rep = fidelity(clusters, scatter)
    assert "eq5" in rep.failures


def test_voids_are_invisible_and_reported():
    ex = exemplar("sparse_voids")
    vis = ex.select(~ex["void"])
    rep = fidelity(ex, moved(vis, 0, 0).without_columns("void"), eq5=False)
    assert rep.faithful, rep.failures
    assert set(rep.kinds) == {"apple"}
    assert rep.info["exemplar_void_share"] == pytest.approx(float(ex["void"].mean()))
    assert rep.info["result_void_share"] == 0.0
    with_voids = fidelity(ex, ex, eq5=False)
    assert with_voids.metrics["fraction[apple]"].value == 0


# -- the local map --------------------------------------------------------------------------


def test_the_worst_window_finds_a_seam(clusters):
    big = tile(clusters, 5, 5)
    # empty a vertical band in the middle: a seam where two growth fronts failed to meet
    x0, _, x1, _ = big.region.bounds
    mid = 0.5 * (x0 + x1)
    seam = big.select(np.abs(big.x - mid) > 40)
    rep = fidelity(clusters, seam, eq5=False)
    w = rep.local["worst"]
    assert w["score"] > 1
    assert w["bounds"][0] - 1 < mid < w["bounds"][2] + 1
    score = np.asarray(rep.local["score"])
    assert score.ndim == 2 and np.isfinite(score).sum() >= 9
    # windows far from the seam score lower than the seam's
    cols = np.nanmax(score, axis=0)
    assert cols[0] < w["score"] and cols[-1] < w["score"]


# -- the report, determinism, bad input -----------------------------------------------------------


def test_report_serialises_and_shows_itself(clusters):
    rep = fidelity(clusters, tile(clusters, 2, 2))
    assert isinstance(rep, FidelityReport)
    d = rep.to_dict()
    text = json.dumps(d, allow_nan=False)
    assert json.loads(text)["faithful"] == rep.faithful
    assert set(d["metrics"]) == set(rep.metrics)
    for m in d["metrics"].values():
        assert {"value", "tolerance", "passed", "exemplar", "result"} <= set(m)
    html = rep._repr_html_()
    assert "<table>" in html and "g[disc,dot]" in html
    assert "faithful" in repr(rep)


def test_fidelity_is_deterministic(clusters):
    big = tile(clusters, 2, 2)
    a = json.dumps(fidelity(clusters, big).to_dict(), sort_keys=True)
    b = json.dumps(fidelity(clusters, big).to_dict(), sort_keys=True)
    assert a == b


def test_bad_input_names_the_problem(clusters):
    other = Arrangement({"leaf": Shape.circle(1)}, [0, 0, 0], [0, 5, 9], [0, 1, 2])
    with pytest.raises(InputError, match="no kind in common"):
        fidelity(clusters, other)
    with pytest.raises(InputError, match="no visible elements"):
        fidelity(clusters, clusters.select(np.zeros(len(clusters), bool)))
    with pytest.raises(InputError, match="at least 3 visible"):
        fidelity(clusters.select([0, 1]), clusters)
    with pytest.raises(InputError, match="must be an Arrangement"):
        fidelity(clusters, "result.json")
    with pytest.raises(InputError, match="region"):
        fidelity(clusters, clusters, region="R")


@settings(max_examples=8)
@given(dx=st.floats(-1e4, 1e4), dy=st.floats(-1e4, 1e4))
def test_any_translation_is_faithful(dx, dy):
    ex = exemplar("stones")
    assert fidelity(ex, moved(ex, dx, dy), eq5=False, local=False).faithful


def test_pebbles_taking_over_fail():
    # the first symptom: small elements take over (0.9 of the output) and large
    # ones thin out
    ex = exemplar("two_sizes")
    big = tile(ex, 3, 3)
    drop = (big.kind == 0) & (np.random.default_rng(0).random(len(big)) < 0.6)
    rep = fidelity(ex, big.select(~drop), eq5=False)
    assert rep.metrics["fraction[pebble]"].result > 0.88
    assert {"fraction[pebble]", "density[stone]"} <= set(rep.failures)
    assert rep.metrics["density[pebble]"].passed

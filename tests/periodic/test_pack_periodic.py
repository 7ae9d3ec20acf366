"""Seamless repeat tiles from pack (issue 18 point 1): Poisson disk, fill-gap and naive
wrap around the torus of a rectangular tile."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.spatial import cKDTree

from strew import InputError, Region, Shape, metrics
from strew import _periodic as P
from strew.pack import pack, poisson_disk

HOOK = Shape.polygon([(0, 0), (30, 0), (30, 8), (10, 8), (10, 22), (30, 22), (30, 30), (0, 30)])
MIX = {"bar": Shape.rectangle(6, 3), "sq": Shape.rectangle(3, 3)}


def _strips(arr, width):
    """Edge strips of ``width`` along the tile's four edges vs the interior: the ratio of
    element densities (by canonical centroid), of area coverage (wrapped images), and
    each kind's share in the strips and inside."""
    x0, y0, w, h = P.frame(arr)
    c = shapely.centroid(arr.geometry)
    cx, cy = P.canonical(shapely.get_x(c), shapely.get_y(c), (x0, y0, w, h))
    u, v = cx - x0, cy - y0
    edge = (u < width) | (u >= w - width) | (v < width) | (v >= h - width)
    inner = shapely.box(x0 + width, y0 + width, x0 + w - width, y0 + h - width)
    ring = shapely.box(x0, y0, x0 + w, y0 + h).difference(inner)
    density = (edge.sum() / ring.area) / ((~edge).sum() / inner.area)
    cover = shapely.union_all(P.images(arr).geometry)
    coverage = (shapely.area(shapely.intersection(cover, ring)) / ring.area) / (shapely.area(shapely.intersection(cover, inner)) / inner.area)
    shares = {k: ((arr.kind[edge] == i).mean(), (arr.kind[~edge] == i).mean()) for i, k in enumerate(arr.kinds)}
    return density, coverage, shares


def _no_overlap_across_the_wrap(arr):
    tiled = P.tiled_copies(arr, 3, 3)
    pairs, areas = metrics.overlaps(tiled)
    assert len(pairs) == 0, (len(pairs), areas[:5])


@settings(max_examples=12, deadline=None)
@given(
    w=st.floats(26, 70),
    h=st.floats(26, 70),
    seed=st.integers(0, 2**32 - 1),
    method=st.sampled_from(["fill-gap", "naive"]),
    hooks=st.booleans(),
)
def test_tiled_three_by_three_no_element_overlaps_another(w, h, seed, method, hooks):
    shapes = {"hook": HOOK} if hooks else MIX
    extra = {"scale": (0.15, 0.2)} if hooks else {}
    if method == "naive":
        extra["max_failures"] = 300
    arr = pack(shapes, Region.rectangle(w, h, 3.0, -2.0), rng=seed, method=method, periodic=True, **extra)
    assert len(arr) > 0
    x0, y0, tw, th = arr.meta["periodic"]
    np.testing.assert_allclose([x0, y0, tw, th], [3.0, -2.0, w, h], rtol=1e-12)  # the region's bounds, rounded
    # each element once, at its canonical position
    assert np.all((arr.x >= x0) & (arr.x < x0 + tw) & (arr.y >= y0) & (arr.y < y0 + th))
    _no_overlap_across_the_wrap(arr)


def test_elements_cross_the_tile_edge_and_the_tile_is_filled_up_to_it():
    """Where the plain pack keeps off the boundary, the tile's edges are crossed."""
    for method in ("fill-gap", "naive"):
        arr = pack(MIX, "80x50", rng=4, method=method, periodic=True, max_failures=2000 if method == "naive" else 200)
        crossing = int((~shapely.within(arr.geometry, shapely.box(0, 0, 80, 50))).sum())
        assert crossing > 10, (method, crossing)
        _no_overlap_across_the_wrap(arr)
        assert len(metrics.overlaps(P.images(arr))[0]) == 0


@pytest.mark.parametrize("method", ["fill-gap", "naive"])
def test_edge_strips_match_the_interior(method):
    # strips two element diameters wide (bars 6 x 3: about 7) along each edge
    dens, cov, shares = [], [], []
    for seed in range(2):
        arr = pack(MIX, "120x90", rng=seed, method=method, periodic=True, max_failures=1500 if method == "naive" else 200)
        d, c, s = _strips(arr, 14.0)
        dens.append(d)
        cov.append(c)
        shares.append(s)
    assert abs(np.mean(dens) - 1) < 0.1, dens
    assert abs(np.mean(cov) - 1) < 0.1, cov
    for k in MIX:
        edge, inside = np.mean([s[k] for s in shares], axis=0)
        assert abs(edge - inside) < 0.08, (k, edge, inside)


def test_same_seed_same_tile():
    for method in ("fill-gap", "naive"):
        a = pack({"hook": HOOK}, "60x45", rng=7, method=method, periodic=True, scale=(0.15, 0.2), max_failures=300)
        b = pack({"hook": HOOK}, "60x45", rng=7, method=method, periodic=True, scale=(0.15, 0.2), max_failures=300)
        for col in ("x", "y", "rotation", "scale", "kind"):
            assert getattr(a, col).tobytes() == getattr(b, col).tobytes()
        assert a.meta == b.meta and a.meta["params"]["periodic"] is True


def test_bad_input_is_refused_naming_the_problem():
    with pytest.raises(InputError, match="rectangular region"):
        pack(MIX, Region.circle(0, 0, 40), rng=1, periodic=True)
    with pytest.raises(InputError, match="smaller than two elements"):
        pack({"hook": HOOK}, "40x200", rng=1, periodic=True, scale=(0.5, 0.5))
    ctx = pack(MIX, "60x60", rng=1, max_failures=20)
    with pytest.raises(InputError, match="context"):
        pack(MIX, "60x60", rng=1, periodic=True, context=ctx)
    with pytest.raises(InputError, match="constant radius"):
        poisson_disk((10, 10), lambda p: np.ones(len(p)), periodic=True)


def test_cli_periodic_writes_a_tile_and_exits_2_on_bad_input(tmp_path, capsys):
    from strew import load, save
    from strew.arrangement import Arrangement
    from strew.cli import main

    shapes = tmp_path / "mix.json"
    save(Arrangement(MIX, np.zeros(0, int), [], []), shapes)
    out = tmp_path / "tile.json"
    assert main(["pack", str(shapes), "--size", "60x40", "--periodic", "--seed", "2", "-q", "-o", str(out)]) == 0
    arr = load(out)
    assert arr.meta["periodic"] == [0.0, 0.0, 60.0, 40.0]
    _no_overlap_across_the_wrap(arr)
    assert main(["pack", str(shapes), "--size", "10x40", "--periodic", "-q", "-o", str(out)]) == 2
    assert "smaller than two elements" in capsys.readouterr().err
    region = Path(__file__).resolve().parents[2] / "examples" / "pack" / "blob_with_hole.json"
    assert main(["pack", str(shapes), "--region", str(region), "--periodic", "-q", "-o", str(out)]) == 2
    assert "rectangular region" in capsys.readouterr().err


@settings(max_examples=25, deadline=None)
@given(w=st.floats(3, 60), h=st.floats(3, 60), r=st.floats(0.4, 4), seed=st.integers(0, 2**32 - 1))
def test_periodic_poisson_disk_keeps_apart_across_the_wrap_and_covers_the_torus(w, h, r, seed):
    assume(min(w, h) >= 2 * r)  # as pack's tile: two circles across (else a point nears its own image)
    pts = poisson_disk(Region.rectangle(w, h, -1.0, 2.0), r, rng=seed, periodic=True)
    assert len(pts) >= 1
    assert np.all((pts >= [-1.0, 2.0]) & (pts < [-1.0 + w, 2.0 + h]))
    copies = np.concatenate([pts + [i * w, j * h] for i in (-1, 0, 1) for j in (-1, 0, 1)])
    tree = cKDTree(copies)
    d, _ = tree.query(pts, k=2)
    assert d[:, 1].min() >= r * (1 - 1e-12)
    # maximal on the torus: no point farther than 2r from a sample, edges included
    gx, gy = np.meshgrid(np.linspace(-1.0, -1.0 + w, 50), np.linspace(2.0, 2.0 + h, 50))
    d, _ = tree.query(np.c_[gx.ravel(), gy.ravel()])
    assert d.max() < 2 * r
    assert np.array_equal(pts, poisson_disk(Region.rectangle(w, h, -1.0, 2.0), r, rng=seed, periodic=True))


@settings(max_examples=40, deadline=None)
@given(
    rows=st.integers(2, 40),
    cols=st.integers(2, 40),
    p=st.sampled_from([0.005, 0.05, 0.4]),
    sx=st.floats(0.5, 1.5),
    sy=st.floats(0.5, 1.5),
    seed=st.integers(0, 2**32 - 1),
)
def test_torus_distance_transform_equals_brute_force(rows, cols, p, sx, sy, seed):
    """The fill-gap field on a tile: wrapped distances to the nearest obstacle pixel
    centre, with pixels sx by sy (sparse obstacles make the padding grow)."""
    from strew.pack._field import _edt_torus

    rng = np.random.default_rng(seed)
    free = rng.random((rows, cols)) > p
    free[rng.integers(rows), rng.integers(cols)] = False
    rr, cc = np.mgrid[0:rows, 0:cols]
    best = np.full((rows, cols), np.inf)
    for r0, c0 in np.argwhere(~free):
        dy = np.minimum((rr - r0) % rows, (r0 - rr) % rows)
        dx = np.minimum((cc - c0) % cols, (c0 - cc) % cols)
        best = np.minimum(best, np.hypot(dx * sx, dy * sy))
    np.testing.assert_allclose(_edt_torus(free, sx, sy), best, rtol=0, atol=1e-9)

"""ornament on a periodic tile (issue 18 point 1): growth wraps around the torus."""

import subprocess
import sys

import numpy as np
import pytest
import shapely

from strew import _periodic as P
from strew import metrics
from strew._errors import InputError
from strew.ornament import grow_ornament
from strew.region import Region

W, H = 60.0, 45.0


@pytest.fixture(scope="module")
def dots():
    return grow_ornament("dots", Region.rectangle(W, H), rng=2, periodic=True)


@pytest.mark.parametrize("pattern, style", [("dots", "outline"), pytest.param("flowers", "ink", marks=pytest.mark.slow)])
def test_tiled_copies_do_not_overlap_across_the_wrap(pattern, style):
    arr = grow_ornament(pattern, Region.rectangle(W, H), rng=2, periodic=True, style=style)
    assert P.frame(arr) == (0.0, 0.0, W, H)
    assert np.all((arr.x >= 0) & (arr.x < W) & (arr.y >= 0) & (arr.y < H))  # canonical positions
    n = len(arr)
    assert n > 20
    pairs, _ = metrics.overlaps(P.tiled_copies(arr, 3, 3))
    assert len(pairs) == 0  # all filled shapes: none overlaps another, in the tile or across its edges
    # and growth did cross the edges: some elements reach over them
    b = shapely.bounds(arr.geometry)
    assert np.any((b[:, 0] < 0) | (b[:, 2] > W) | (b[:, 1] < 0) | (b[:, 3] > H))


def test_coverage_in_edge_strips_matches_the_interior(dots):
    tile = shapely.box(0, 0, W, H)
    ink = shapely.intersection(shapely.union_all(P.images(dots).geometry), tile)
    band = 8.0
    inner = shapely.box(band, band, W - band, H - band)
    strip = tile.difference(inner)
    ratio = (ink.intersection(strip).area / strip.area) / (ink.intersection(inner).area / inner.area)
    assert 0.85 < ratio < 1.15
    # the empty circles were closed across the wrap too: no gap wider than a dot's diameter
    g = np.mgrid[0.25:W:0.5, 0.25:H:0.5].reshape(2, -1).T
    clear = shapely.distance(shapely.union_all(P.images(dots).geometry), shapely.points(g))
    assert clear.max() < 2 * 3.0


def test_periodic_ornament_is_deterministic(dots):
    again = grow_ornament("dots", Region.rectangle(W, H), rng=2, periodic=True)
    assert np.array_equal(dots.x, again.x) and np.array_equal(dots.y, again.y)


def test_bad_input():
    with pytest.raises(InputError, match="rectangular region"):
        grow_ornament("dots", Region.circle(20, 20, 20), periodic=True)
    with pytest.raises(InputError, match="smaller than two elements"):
        grow_ornament("dots", Region.rectangle(3, 30), periodic=True)


@pytest.mark.slow
def test_cli_periodic_flag(tmp_path):
    out = tmp_path / "t.json"
    ok = subprocess.run([sys.executable, "-m", "strew", "ornament", "dots", "--size", "30x20", "--periodic", "--out", str(out)],
                        capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    from strew import load

    assert P.frame(load(out)) == (0.0, 0.0, 30.0, 20.0)
    bad = subprocess.run([sys.executable, "-m", "strew", "ornament", "dots", "--size", "3x20", "--periodic", "--out", str(out)],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "smaller than two elements" in bad.stderr

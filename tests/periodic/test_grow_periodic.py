"""grow on a periodic tile (issue 18 point 1): growth wraps around the torus (Ijiri §5 on a torus)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from scipy.spatial import cKDTree

from strew import _periodic as P
from strew import load, metrics
from strew._errors import InputError
from strew._resources import example_path
from strew.cli import main
from strew._feedback import ResultWarning
from strew.grow import analyze, grow, lattice_periods
from strew.region import Region

STONES = str(example_path("grow", "stones_irregular.json"))
HEX = str(example_path("grow", "scales_hex.json"))
W, H = 200.0, 160.0


@pytest.fixture(scope="module")
def stones():
    return load(STONES)


@pytest.fixture(scope="module")
def tile(stones):
    return grow(stones, Region.rectangle(W, H, 5.0, -3.0), periodic=True, rng=2)


def test_tile_repeats_without_overlaps_and_keeps_elements_canonical(tile):
    assert P.frame(tile) == (5.0, -3.0, W, H)
    assert len(metrics.outside(tile)) == 0
    assert np.all((tile.x >= 5) & (tile.x < 5 + W) & (tile.y >= -3) & (tile.y < -3 + H))
    assert len(tile) > 150
    wo = metrics.wrap_overlaps(tile)
    assert wo["across"] == 0 and wo["inside"] == 0
    pairs, _ = metrics.overlaps(P.tiled_copies(tile, 3, 3))
    assert len(pairs) == 0
    # growth did go across the edges: some elements reach over them
    b = shapely.bounds(tile.geometry)
    assert np.any((b[:, 0] < 5) | (b[:, 2] > 5 + W) | (b[:, 1] < -3) | (b[:, 3] > -3 + H))


def test_edge_strips_are_as_dense_as_the_interior(stones, tile):
    # growth starts at the tile's centre, so its fronts meet at the tile's edges: the
    # edge strips straddle that seam. Mean over three seeds (one tile's strips hold
    # about 100 elements, so a single ratio scatters by about 10%)
    ratios = [metrics.repeat_report(tile)["density"]["ratio"]]
    for seed in (3, 4):
        ratios.append(metrics.repeat_report(grow(stones, Region.rectangle(W, H), periodic=True, rng=seed))["density"]["ratio"])
    assert 0.9 <= float(np.mean(ratios)) <= 1.1, ratios
    # the same growth in the plane thins out along the region's edge
    flat = grow(stones, Region.rectangle(W, H), rng=3)
    assert metrics.repeat_report(flat, tile=[0, 0, W, H])["density"]["ratio"] < min(ratios[1], 0.9)


def test_lattice_in_a_multiple_of_its_periods_repeats_exactly(recwarn):
    # scales_hex: 10-unit rows, periods 10 x 17.32; 20 x 10 rows fill 200 x 173.2 exactly
    h = 10 * 10 * np.sqrt(3)
    arr = grow(load(HEX), Region.rectangle(200, h), periodic=True, rng=1)
    assert len(arr) == 400
    xy = np.c_[arr.x, arr.y]
    d = cKDTree(xy, boxsize=[200, h]).query(xy, k=7)[0][:, 1:]  # six neighbours on the torus
    assert np.allclose(d, 10.0, atol=1e-6)
    assert not [w for w in recwarn if issubclass(w.category, ResultWarning)]


def test_lattice_in_another_tile_is_grown_in_a_multiple_and_moved_to_fit():
    with pytest.warns(ResultWarning, match=r"lattice with periods 10 x 17.32.*grew it in 200 x 155.885"):
        arr = grow(load(HEX), Region.rectangle(200, 150), periodic=True, rng=1)
    assert len(arr) == 360  # 20 x 18 rows
    assert metrics.wrap_overlaps(arr)["across"] == 0 and metrics.wrap_overlaps(arr)["inside"] == 0
    assert len(metrics.outside(arr)) == 0
    xy = np.c_[arr.x, arr.y]
    d = cKDTree(xy, boxsize=[200, 150]).query(xy, k=7)[0][:, 1:]
    assert d.max() - d.min() < 0.05 * 10  # one lattice throughout, no seam
    assert lattice_periods(analyze(load(STONES))) is None  # an irregular exemplar is not a lattice


def test_lattice_that_cannot_be_moved_to_fit_meets_at_the_seam_without_overlaps_and_says_so():
    # scales.svg's scales touch: with the reference analyze() builds by default (no
    # lattice repairs), squeezing its rows 1.3% into 300 would overlap them, and
    # spreading them to fill from 266 would move them by 13%
    ex = load(str(example_path("exemplars", "scales.svg")))
    with pytest.warns(ResultWarning, match=r"lattice with periods 22 x 38.*gap or dislocations; a tile of 308 x 304"):
        arr = grow(analyze(ex), Region.rectangle(300, 300), periodic=True, rng=1)
    assert metrics.wrap_overlaps(arr)["across"] == 0
    assert len(metrics.outside(arr)) == 0
    # grow(exemplar) repairs the lattice (issue 14: the shorter of two tied diagonals):
    # the rows grown in 308 x 304 then squeeze into 300 x 300 without an overlap, and
    # it says so
    with pytest.warns(ResultWarning, match=r"lattice with periods 22 x 38.*grew it in 308 x 304 and moved its centres"):
        arr = grow(ex, Region.rectangle(300, 300), periodic=True, rng=1)
    wo = metrics.wrap_overlaps(arr)
    assert wo["across"] == 0 and wo["inside"] == 0
    assert len(metrics.outside(arr)) == 0


def test_same_seed_same_tile(stones, tile):
    again = grow(stones, Region.rectangle(W, H, 5.0, -3.0), periodic=True, rng=2)
    assert np.array_equal(tile.x, again.x) and np.array_equal(tile.y, again.y)
    assert np.array_equal(tile.rotation, again.rotation) and np.array_equal(tile.kind, again.kind)
    assert tile.meta == again.meta and tile.meta["params"]["periodic"] is True


def test_bad_input_is_refused_naming_the_problem(stones):
    with pytest.raises(InputError, match="rectangular region"):
        grow(stones, Region.circle(0, 0, 80), periodic=True, rng=1)
    with pytest.raises(InputError, match="too small"):
        grow(stones, Region.rectangle(20, 200), periodic=True, rng=1)
    with pytest.raises(InputError, match="rectangular region"):
        grow(stones, count=20, periodic=True, rng=1)


def test_cli_periodic_writes_a_tile_and_exits_2_on_bad_input(tmp_path, capsys):
    out = tmp_path / "t.json"
    assert main(["grow", STONES, "--size", "150x120", "--periodic", "--seed", "2", "-q", "-o", str(out)]) == 0
    arr = load(out)
    assert arr.meta["periodic"] == [0.0, 0.0, 150.0, 120.0]
    assert metrics.wrap_overlaps(arr)["across"] == 0
    assert main(["grow", STONES, "--size", "15x120", "--periodic", "-q", "-o", str(tmp_path / "u.json")]) == 2
    assert "too small" in capsys.readouterr().err

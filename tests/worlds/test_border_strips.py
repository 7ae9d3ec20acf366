"""Border strips of a tiled world against its interior (issue 19 point 4).

A pack world of 20 tiles (300 x 240 in tiles of 60, about 10,000 elements). The strips
are the centres within ``k s`` of an inner tile border (``s = 1 / sqrt(density)``, the
mean spacing), the interior the rest, both away from the world's own edge band; the
definitions and the large-world figures with intervals are in
``benchmarks/worlds_strips.py``.

The bounds. The issue asks for 3 %; on top of it each assertion allows 3 standard errors
of the statistic at this world's size, the counts taken as Poisson (and the kinds as
binomial). That is an upper bound of the noise of a saturated packing, whose counts vary
less: in ``python benchmarks/worlds_strips.py --methods pack`` (800 x 800, 2 seeds) the
tile-bootstrap interval of the strip density ratio is 0.4 of the Poisson one untiled,
0.6 tiled. At this size the bounds come to about 10 % (strips of 2 s) and 12 % (1 s):
a test of this size sees a seam of that order (an empty seam, a kind missing along the
borders), not the 3 % itself, which the benchmark's worlds of 1.8e5 elements measure.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import strew
from strew.tiles import tiled

sys.path.insert(0, str(Path(__file__).parent))
from world_stats import (  # noqa: E402
    folded_profile,
    overlapping_pairs,
    overlapping_pairs_across,
    profile_test,
    signed_profile,
    strip_units,
)

SIZE = (300.0, 240.0)
TILE = 60.0
SHAPES = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
TOL = 0.03  # issue 19 point 4
Z = 3.0

pytestmark = pytest.mark.slow  # one 10,000-element pack world: about 4 s CPU with numba's kernels loaded


@pytest.fixture(scope="module")
def world():
    a = tiled("pack", SHAPES, SIZE, tile_size=TILE, seed=7)
    s = 1.0 / np.sqrt(len(a) / (SIZE[0] * SIZE[1]))
    return a, s, float(a.meta["world"]["halo"])


def test_the_world_has_20_tiles_and_no_overlaps_across_them(world):
    a, _, _ = world
    assert a.meta["world"]["tiles"] == 20 and len(np.unique(a["tile"])) == 20
    assert len(a) > 8000
    assert overlapping_pairs_across(a, a["tile"]) == 0  # exact polygons: no area shared across a border
    assert overlapping_pairs(a) == 0
    assert ((a.x >= 0) & (a.x <= SIZE[0]) & (a.y >= 0) & (a.y <= SIZE[1])).all()


@pytest.mark.parametrize("mult", [2.0, 1.0])
def test_strip_density_and_kind_fractions_match_the_interior(world, mult):
    a, s, halo = world
    u = strip_units(a, SIZE, TILE, mult * s, max(halo, 3 * s))
    ns, ni = u["strip"].sum(), u["inner"].sum()
    assert ns > 1000 and ni > 3000
    ratio = (ns / u["strip_area"].sum()) / (ni / u["inner_area"].sum())
    se = np.sqrt(1 / ns + 1 / ni)  # of log(ratio), Poisson counts
    assert abs(np.log(ratio)) < TOL + Z * se, (ratio, se)
    for k in range(len(a.kinds)):
        ps, pi = u["strip_kind"][:, k].sum() / ns, u["inner_kind"][:, k].sum() / ni
        se_k = np.sqrt((1 - ps) / (ns * ps) + (1 - pi) / (ni * pi))  # of log(ps / pi), binomial shares
        assert abs(np.log(ps / pi)) < TOL + Z * se_k, (a.kinds[k], ps / pi, se_k)


def test_no_grid_in_the_density_folded_modulo_the_tile(world):
    # the overview's grid would be a density step at the borders: the centres' density
    # folded modulo the tile size (inner tiles only) is flat within its noise
    a, s, _ = world
    p = folded_profile(a, SIZE, TILE, s)
    t = profile_test(p["counts"], p["exposure"], p["near_bins"])
    assert sum(t["counts"]) > 5000
    assert t["p"] > 1e-3, t["chi2_dof"]  # chi-square against flat, Poisson counts
    r = t["near_ratio"]["value"]
    cn = np.asarray(t["counts"])[p["near_bins"]].sum()
    cf = np.asarray(t["counts"])[~p["near_bins"]].sum()
    assert abs(np.log(r)) < TOL + Z * np.sqrt(1 / cn + 1 / cf), r


def test_every_phase_has_the_density_of_the_others(world):
    # a tile of phase 0 runs alone, those of phases 1-3 around finished neighbours: a
    # stationary world has one density in all (a checkerboard in the overview otherwise)
    a, s, halo = world
    u = strip_units(a, SIZE, TILE, 2 * s, max(halo, 3 * s))
    c, area = u["strip"] + u["inner"], u["strip_area"] + u["inner_area"]
    for p in range(4):
        m = u["phase"] == p
        assert m.sum() in (4, 6)  # 5 x 4 tiles: 6, 4, 6, 4
        r = (c[m].sum() / area[m].sum()) / (c[~m].sum() / area[~m].sum())
        se = np.sqrt(1 / c[m].sum() + 1 / c[~m].sum())
        assert abs(np.log(r)) < TOL + Z * se, (p, r, se)


# A world of many short borders for the profile across them: 600 x 500 in tiles of 50
# (120 tiles, about 42,000 elements; 7,600 centres within a spacing s of a border,
# about 1,700 in each half-spacing bin of the profile, whose bounds come to about 11 %).
# pack's old hand-over (d66b77e: the centres in the finished tile kept, the rest dropped)
# put 1.18 of the interior's density within s/2 on the finished side of a border here
# (1.19 in benchmarks/worlds_strips.py, and 0.83 on the later side, bars' share 0.73
# there), a seam that the strips of +-1 s average out (1.045 at 800 x 800; their bounds
# here come to about 7 %). A uniform 3 % seam needs some 40,000 strip elements
# (worlds_strips.py, 800 x 800, two seeds: the +-1 s ratio within 0.8 %).
PROFILE_SIZE = (600.0, 500.0)
PROFILE_TILE = 50.0


@pytest.fixture(scope="module")
def profile_world():
    a = tiled("pack", SHAPES, PROFILE_SIZE, tile_size=PROFILE_TILE, seed=11)
    s = 1.0 / np.sqrt(len(a) / (PROFILE_SIZE[0] * PROFILE_SIZE[1]))
    return a, s


def test_the_density_and_kinds_across_a_border_match_the_interior(profile_world):
    # centres by signed distance to the nearest inner border (positive into the later
    # tile), in half spacings: each of the 4 bins within one spacing of the border against
    # the 4 bins 2 to 3 spacings out, all kinds and each kind's share
    a, s = profile_world
    assert overlapping_pairs_across(a, a["tile"]) == 0
    c = signed_profile(a, PROFILE_SIZE, PROFILE_TILE, s)["counts"].astype(float)  # (kinds + 1, 12 bins)
    ref, near = [0, 1, 10, 11], [4, 5, 6, 7]
    nr = c[0, ref].sum()
    assert nr > 5000
    for b in near:
        r = c[0, b] / (nr / len(ref))
        se = np.sqrt(1 / c[0, b] + 1 / nr)  # of log(r), Poisson counts
        assert abs(np.log(r)) < TOL + Z * se, (b, r, se)
        for k in range(len(a.kinds)):
            ps, pr = c[k + 1, b] / c[0, b], c[k + 1, ref].sum() / nr
            se_k = np.sqrt((1 - ps) / (c[0, b] * ps) + (1 - pr) / (nr * pr))
            assert abs(np.log(ps / pr)) < TOL + Z * se_k, (b, a.kinds[k], ps / pr, se_k)


def test_strips_of_many_borders_match_the_interior(profile_world):
    a, s = profile_world
    u = strip_units(a, PROFILE_SIZE, PROFILE_TILE, s, 3 * s)
    ns, ni = u["strip"].sum(), u["inner"].sum()
    assert ns > 6000 and ni > 20000
    ratio = (ns / u["strip_area"].sum()) / (ni / u["inner_area"].sum())
    se = np.sqrt(1 / ns + 1 / ni)
    assert abs(np.log(ratio)) < TOL + Z * se, (ratio, se)

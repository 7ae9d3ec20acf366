"""Tiled synth's border strips keep the exemplar's kinds (issue 19 point 4): the stones of
two_sizes are as common along the tile borders as inside the tiles.

The seam this guards against: a finished tile kept the elements centred within one
element diameter of its rectangle, the later tile grew on from that cut and filled the
stone-shaped hollows at its edge with pebbles (880 x 880, tiles 220, seeds 1,2 on
d66b77e: stones' share in the +-2s strips 0.91x the interior's, just past the kept band
0.67x, density 1.05x). Now the finished tile keeps every element whose disc reaches into
that band and the later tile grows from the band's outer edge (strew.tiles,
_GROWS_FROM_CONTEXT): 1.00x, 0.90x and 1.00x.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from strew.tiles import tiled

sys.path.insert(0, str(Path(__file__).parent))
from world_stats import overlapping_pairs, signed_profile, strip_units  # noqa: E402

from strew_testing import fidelity_suite  # noqa: E402

pytestmark = pytest.mark.slow  # two 16-tile synth worlds, ~3-4 CPU s each

SIDE, TILE = 880.0, 220.0  # 4 x 4 frames of two_sizes, 4 x 4 tiles
SEEDS = (1, 2)


@pytest.fixture(scope="module")
def worlds():
    ex = fidelity_suite().make_exemplar("two_sizes")
    return [tiled("synth", ex, (SIDE, SIDE), tile_size=TILE, seed=s, measure=False) for s in SEEDS]


def _spacing(a) -> float:
    return 1.0 / np.sqrt(len(a) / SIDE**2)


def test_stones_share_and_density_in_border_strips_match_the_interior(worlds):
    # pooled over both seeds' tiles; strips: centres within 2 mean spacings of an inner
    # border, the world's edge band (a quarter tile) left out. On d66b77e: stones 0.911x,
    # density 1.050x; now 0.999x and 0.999x (noise of these ~600 strip elements: ~4 %)
    units = [strip_units(a, (SIDE, SIDE), TILE, 2.0 * _spacing(a), TILE / 4) for a in worlds]
    u = {f: np.concatenate([x[f] for x in units]) for f in ("strip", "inner", "strip_area", "inner_area", "strip_kind", "inner_kind")}
    stone = list(worlds[0].kinds).index("stone")
    assert u["strip"].sum() > 800
    share = (u["strip_kind"][:, stone].sum() / u["strip"].sum()) / (u["inner_kind"][:, stone].sum() / u["inner"].sum())
    density = (u["strip"].sum() / u["strip_area"].sum()) / (u["inner"].sum() / u["inner_area"].sum())
    assert 0.95 < share < 1.05, share
    assert 0.96 < density < 1.035, density


def test_stones_just_past_the_kept_band_are_not_replaced_by_pebbles(worlds):
    # centres 1 to 2.5 spacings into the later tile (past a band of one stone diameter,
    # 1.6 s): where the later tile met the cut. On d66b77e the stones' share there was
    # 0.67x the interior's; now 0.90x
    stone = list(worlds[0].kinds).index("stone") + 1  # row 0 of the profile: all kinds
    band = np.zeros(2)
    inner = np.zeros(2)
    for a in worlds:
        s = _spacing(a)
        c = signed_profile(a, (SIDE, SIDE), TILE, s, reach=3.0)["counts"]  # bins of s/2 from -3s
        band += [c[stone, 8:11].sum(), c[0, 8:11].sum()]
        u = strip_units(a, (SIDE, SIDE), TILE, 3.0 * s, TILE / 4)
        inner += [u["inner_kind"][:, stone - 1].sum(), u["inner"].sum()]
    assert band[1] > 400
    assert (band[0] / band[1]) / (inner[0] / inner[1]) > 0.8


def test_no_overlaps_across_the_borders(worlds):
    for a in worlds:
        assert overlapping_pairs(a) == 0

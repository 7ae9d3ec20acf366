"""pack's hand-over keeps a finished tile's large elements just past the border (issue 19 point 4).

A later pack tile packs around its finished neighbours' elements (its ``context``), and
pack's Step 1 (Sakurai & Miyata §4.1: sparse Poisson-disk placements at random scales,
where nearly all of strew demo's large trees come from) samples the free region shrunk
by the largest element's radius: within about that radius of the finished packing it
places none, and Step 2 fills that band with small trees. Trees tiled at 550ea99 had,
within half a spacing past a border, 0.25 (scale 0.8-1.0) and 0.48 (0.6-0.8) of the
interior's large trees, and 1.03 of its density within 1 s of a border
(``python benchmarks/pack_seam_profile.py``). The finished tile's ramp
(``strew.tiles._ramp``) now keeps its own elements just past the border with the
probability it keeps them at the border (1 - w: the large ones), falling to 0 at
``_RAMP_PAST`` halos; the smallest (w = 1) are never kept there.
"""

from __future__ import annotations

import numpy as np
import pytest

import strew
import strew.tiles
from strew._resources import example_path
from strew.io import load_shapes
from strew.metrics import overlaps
from strew.tiles import Tile, _Job, _ramp, plan, world

_RAMP_PAST = getattr(strew.tiles, "_RAMP_PAST", 0.0)  # 0 at 550ea99: nothing kept past a border

T = 100.0
HALO = 10.0
N = 4000


def _job() -> _Job:
    # two tiles side by side: tile 0 (phase 0) runs first, tile 1 (phase 1) is its later neighbour
    return _Job("pack", None, {}, (2 * T, T), HALO, 7, (T, T), (2, 1))


def _tile0() -> Tile:
    tiles, _, _ = plan((2 * T, T), T)
    assert tiles[0].phase == 0 and tiles[1].phase == 1
    return tiles[0]


def _kept(x: float) -> tuple[float, float]:
    # squares at scales 0.2 (the kind's smallest: w = 1) and 1.0 (w = 0.2), centres at x
    shapes = {"sq": strew.Shape.rectangle(1.0, 1.0)}
    sc = np.tile([0.2, 1.0], N)
    a = strew.Arrangement(shapes, np.zeros(2 * N, np.int64), np.full(2 * N, x), np.linspace(1.0, T - 1.0, 2 * N),
                          np.zeros(2 * N), sc)
    k = _ramp(a, _tile0(), _job())
    return float(k[sc == 0.2].mean()), float(k[sc == 1.0].mean())


def test_the_ramp_keeps_large_elements_just_past_the_border_and_none_further():
    band = _RAMP_PAST * HALO
    assert band > 0
    # just before the border: drop probability w (0.2 for the large), as before
    small, large = _kept(T - 1e-9)
    assert small < 0.02 and abs(large - 0.8) < 0.03, (small, large)
    # just past it: the same (1 - w), the smallest never
    small, large = _kept(T + 1e-9)
    assert small == 0.0 and abs(large - 0.8) < 0.03, (small, large)
    # half the band past: half as many
    small, large = _kept(T + 0.5 * band)
    assert small == 0.0 and abs(large - 0.4) < 0.03, (small, large)
    # past the band: none (550ea99's ramp kept 1 - w of them here; run_tile dropped them)
    assert _kept(T + 1.01 * band) == (0.0, 0.0)


@pytest.fixture(scope="module")
def two_tiles():
    lib = load_shapes(example_path("pack", "trees.json"))
    out: dict[int, object] = {}
    info = world("pack", lib, (480.0, 240.0), tile_size=240.0, seed=5, sink=lambda k, a: out.__setitem__(k, a),
                 scale=(0.2, 1.0), rotation=(-0.15, 0.15))
    return out, float(info.meta["world"]["halo"])


@pytest.mark.slow  # two tiles of trees, about 1,200 elements
def test_a_finished_tile_hands_over_its_large_trees_just_past_the_border(two_tiles):
    from strew.arrangement import concat

    out, halo = two_tiles
    a0 = out[0]
    sc = np.abs(np.asarray(a0.scale, float).reshape(len(a0), -1)[:, 0])
    past = np.asarray(a0.x, float) > 240.0
    assert past.any(), "the finished tile kept nothing past the border"
    assert np.all(np.asarray(a0.x, float)[past] <= 240.0 + _RAMP_PAST * halo + 1e-9)
    # the holes handed on are the dropped elements only, none of the kept
    holes = np.asarray(a0.meta["holes"], float).reshape(-1, 3)
    # the rest of the band and everything further went to the later tile as holes
    assert np.any((holes[:, 0] > 240.0) & (holes[:, 0] <= 240.0 + _RAMP_PAST * halo))
    assert np.any(holes[:, 0] > 240.0 + _RAMP_PAST * halo)
    # and no kept element is the tile's smallest (w = 1 there: never kept past the border)
    assert sc[past].min() > sc.min()
    kept = {(float(x), float(y)) for x, y in zip(a0.x, a0.y)}
    assert len(holes) and not any((float(x), float(y)) in kept for x, y, _ in holes)
    # the later tile packed around them
    w = concat([out[0], out[1]])
    assert len(overlaps(w)[0]) == 0

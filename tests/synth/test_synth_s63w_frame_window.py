"""Issue 13 point 1 (helper s63w): synth's own reading of an exemplar's frame as a wall
or a window (``_prepare.frame_is_window``, ``Prepared.frame_window``), which
``_swap.fill_swapped`` takes its target by."""

from __future__ import annotations

import numpy as np
import shapely
from strew_testing import fidelity_suite

from strew import Arrangement
from strew.synth._palette import Palette
from strew.synth._prepare import frame_is_window, prepare


def _grid(lo: float, hi: float, step: float) -> np.ndarray:
    g = np.arange(lo, hi + 1e-9, step)
    return np.array([(x, y) for x in g for y in g], float)


def _frame_band(depth: float, count: int, size: float = 200.0) -> np.ndarray:
    """``count`` centres along each side of a ``size`` square, ``depth`` inside it."""
    t = np.linspace(0.2 * size, 0.8 * size, count)
    return np.concatenate([np.c_[t, np.full(count, depth)], np.c_[t, np.full(count, size - depth)],
                           np.c_[np.full(count, depth), t], np.c_[np.full(count, size - depth), t]])


def _built(stone_r: float, pebble_r: float, pebble_depth: float):
    """Stones of radius ``stone_r`` on a grid whose outer row stands ``stone_r`` off the
    frame (a 200 square), pebbles of radius ``pebble_r`` along the frame,
    ``pebble_depth`` inside it."""
    stones = _grid(stone_r, 200.0 - stone_r, 45.0)
    pebbles = _frame_band(pebble_depth, 3)
    pos = np.r_[stones, pebbles]
    kind = np.r_[np.zeros(len(stones), int), np.ones(len(pebbles), int)]
    r = np.where(kind == 0, stone_r, pebble_r)
    return pos, kind, r


BOX = shapely.box(0.0, 0.0, 200.0, 200.0)


def test_wall_small_kind_nearer_the_frame():
    # stones (radius 13) and pebbles (radius 9) each kept off by their own radius:
    # 13 >= 1.25 x 9, the band between holds only pebbles -> a wall
    pos, kind, r = _built(13.0, 9.0, 9.0)
    assert not frame_is_window(pos, kind, r, BOX)


def test_window_kinds_of_near_sizes():
    # pebbles of radius 11.5 kept off by 11.5 (stones 13): the kinds keep off by
    # similar distances (13 < 1.25 x 11.5) -> a window (two sizes ratio 0.85, h9)
    pos, kind, r = _built(13.0, 11.5, 11.5)
    assert frame_is_window(pos, kind, r, BOX)


def test_window_when_a_kind_crosses_the_frame():
    # pebbles cut by the frame (a crop: centres 2 inside, radius 9; one outside)
    pos, kind, r = _built(13.0, 9.0, 2.0)
    assert frame_is_window(pos, kind, r, BOX)
    pos[-1] = (-3.0, 100.0)
    assert frame_is_window(pos, kind, r, BOX)


def test_one_kind_is_a_window():
    pos, kind, r = _built(13.0, 9.0, 9.0)
    keep = kind == 0
    assert frame_is_window(pos[keep], kind[keep], r[keep], BOX)


def _exemplar(v: int, ratio: float, n_large: int, n_small: int):
    return fidelity_suite().make_exemplar("two_sizes", rng=v, ratio=ratio, n_large=n_large, n_small=n_small)


def test_prepare_reads_the_suite_frames():
    # two sizes ratio 0.85 (grow_variants.HARDER["two_sizes"][9], variant seed 36): a
    # window; ratio 0.7 (HARDER[3], variant seed 8, the rows fill_swapped was made
    # for): a wall; an exemplar without a region: False (the inner frame as before)
    win = _exemplar(36, 0.85, 40, 120)
    wall = _exemplar(8, 0.7, 40, 100)
    assert prepare(Palette({"ex": win}).select("ex")).frame_window.tolist() == [True]
    assert prepare(Palette({"ex": wall}).select("ex")).frame_window.tolist() == [False]
    bare = Arrangement(win.shapes, win.kind, win.xy[:, 0], win.xy[:, 1], win.rotation, win.scale)
    assert bare.region is None
    assert prepare(Palette({"ex": bare}).select("ex")).frame_window.tolist() == [False]

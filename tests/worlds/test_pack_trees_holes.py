"""pack's hand-over at tile borders on a wide range of scales (issue 19 point 4).

strew demo's trees (scale 0.2-1.0, halo 60), 480 x 480 in tiles of 240 (2 x 2 tiles, one
per phase; the regions reach 1.25 halo). A finished tile thins its elements near a later
tile (``strew.tiles._ramp``) and hands the discs about the ones it dropped on in
``meta["holes"]``; the later tile keeps what it placed on a finished tile's side only in
those holes (``strew.tiles._in_holes``: nearer, by distance less the bounding radii, to a
dropped element than to every kept one). Before, it kept everything it placed there, and
one pack run leaves room for the smallest trees in any packing: the later tile added
them to the gaps of the finished tile's packing as deep as its region reached (past
the ramp, where nothing was dropped), 5-10 % of the density
(``python benchmarks/pack_seam_split.py``).
"""

from __future__ import annotations

import numpy as np
import pytest

from strew._resources import example_path
from strew.io import load_shapes
from strew.metrics import overlaps
from strew.tiles import world

W, T = 480.0, 240.0

pytestmark = pytest.mark.slow  # four tiles of trees, about 2,300 elements: a few seconds


@pytest.fixture(scope="module")
def tiles():
    lib = load_shapes(example_path("pack", "trees.json"))
    out: dict[int, object] = {}
    info = world("pack", lib, (W, W), tile_size=T, seed=3, sink=lambda k, a: out.__setitem__(k, a),
                 scale=(0.2, 1.0), rotation=(-0.15, 0.15))
    return out, float(info.meta["world"]["halo"])


def _owner(a) -> np.ndarray:
    return (np.clip(np.floor(a.y / T), 0, 1) * 2 + np.clip(np.floor(a.x / T), 0, 1)).astype(int)


def _radii(a) -> np.ndarray:
    # bounding radius: the shape's about its origin times the scale
    r = np.array([float(a.shapes[k].radius) for k in a.kinds])
    return r[np.asarray(a.kind, int)] * np.abs(np.asarray(a.scale, float).reshape(len(a), -1)[:, 0])


def test_later_tiles_keep_on_a_finished_side_only_what_fills_its_holes(tiles):
    # an element a later tile placed on a finished tile's side is kept only where the
    # finished packing had a dropped element nearest (distance less the bounding radii)
    out, _ = tiles
    # tile k has phase k here (2 x 2 tiles)
    for k in (1, 2, 3):
        a = out[k]
        theirs = np.flatnonzero(_owner(a) < k)
        assert len(theirs), "a later tile kept nothing on a finished side"
        holes = np.concatenate([np.asarray(out[j].meta["holes"], float).reshape(-1, 3) for j in range(k)])
        assert len(holes), "the finished tiles dropped nothing near a later one"
        kept = [out[j] for j in range(k)]
        kx = np.concatenate([b.x for b in kept])
        ky = np.concatenate([b.y for b in kept])
        kr = np.concatenate([_radii(b) for b in kept])
        for e in theirs:
            dh = np.min(np.hypot(a.x[e] - holes[:, 0], a.y[e] - holes[:, 1]) - holes[:, 2])
            dk = np.min(np.hypot(a.x[e] - kx, a.y[e] - ky) - kr)
            assert dh < dk + 1e-9, "a later tile kept an element in a gap of a finished packing"


def test_the_world_has_no_overlaps(tiles):
    from strew.arrangement import concat

    out, _ = tiles
    a = concat([out[k] for k in sorted(out)])
    assert len(overlaps(a)[0]) == 0

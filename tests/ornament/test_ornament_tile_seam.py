"""Ornament in tiled worlds: every tile grows, whatever its place (issue 19 point 4).

A seed (a point proxy) on a raster cell's corner covered no cell: its four cell centres
lie at exactly half a cell diagonal, which rounding put a hair beyond the point's pad.
No circle was then stopped by an element, growth never began, and the tile stayed empty
(flowers 480 x 480 in tiles of 120: 3 of the 4 phase-0 tiles and one phase-1 tile, the
reason phase-0 tiles measured 0.77x the mean density in benchmarks/worlds_strips.py).
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import Region
from strew.ornament import grow_elements
from strew.tiles import tiled


def _middle_density(arr, rect, inset):
    x0, y0, x1, y1 = rect
    x, y = np.asarray(arr.x), np.asarray(arr.y)
    k = (x > x0 + inset) & (x < x1 - inset) & (y > y0 + inset) & (y < y1 - inset)
    return k.sum() / ((x1 - x0 - 2 * inset) * (y1 - y0 - 2 * inset))


@pytest.mark.parametrize("pattern, box, cells", [
    ("dots", (70.0, 70.0, 130.0, 130.0), 200),  # seed (100, 100) on a corner of cells of 0.3
    ("flowers", (210.0, 210.0, 390.0, 390.0), None),  # seed (300, 300), cells of 0.6 (the 480 world's tile)
])
def test_seed_on_a_cell_corner_grows(pattern, box, cells):
    orn = grow_elements(pattern, Region(shapely.box(*box)), resolution=cells, max_elements=20)
    c = (box[0] + box[2]) / 2, (box[1] + box[3]) / 2
    assert np.allclose(orn.seeds, [c])  # the corner case itself
    assert len(orn.elements) == 20  # was 1: the seed alone, no circle was eligible
    assert orn.stats["successes"] >= 5  # a flower's rule places up to 3 elements


@pytest.mark.slow  # about 3.5 s CPU
def test_tiled_ornament_every_tile_grows():
    # dots 140 x 140 in tiles of 40 (halo 10), cells 200: the phase-0 tile (2, 2) runs on
    # [70, 130]^2 and its seed (100, 100) lies on a cell corner; on d66b77e its middle
    # was empty (density 0 against 0.043-0.058 in the other tiles)
    side, t = 140.0, 40.0
    arr = tiled("ornament", "dots", (side, side), tile_size=t, seed=1, cells=200)
    n = int(side // t)
    dens = np.array([[_middle_density(arr, (i * t, j * t, (i + 1) * t, (j + 1) * t), t / 4) for i in range(n)] for j in range(n)])
    med = float(np.median(dens))
    assert med > 0.03
    assert dens.min() > 0.6 * med, dens.round(3)
    # the tiles of each phase (2 x 2 colouring) against all: no phase sparse or dense
    phase = (np.arange(n)[:, None] % 2) * 2 + np.arange(n)[None, :] % 2
    for p in range(4):
        assert 0.8 < dens[phase == p].mean() / dens.mean() < 1.2, (p, dens.round(3))

"""Every tile of a tiled ornament world grows on the untiled world's raster cell
(issue 19 point 4, helper w26b).

strew.ornament's default raster has cells of half the minimum radius, at least 256 along
the region's longer side (§4.1's raster buffer). A tile's region (tile plus halo) fell
under that floor: the vase at tile 48 grew on cells of 0.23-0.28 units where one run over
the 192-unit world grows on 0.75, and the vase grows fewer elements on a finer raster
(72 x 72 panel: 968 elements on the default cells, 1,062 on the world's cell; benchmarks/
w26b_cells.py), so the tiled vase worlds were ~3.5 % short of the untiled control in every
tile phase. strew.tiles._ornament_cells hands each tile the world's cell.
"""

from __future__ import annotations

import pytest

import strew
import strew.ornament._engine as E
import strew.tiles as T
from strew.ornament import grow_ornament


def _cells_seen(monkeypatch, run):
    """The raster cell size (``_Grower.h``) and longer region side of every run ``run`` makes."""
    seen: list[tuple[float, float]] = []
    orig = E._Grower.__init__

    def init(self, *a, **k):
        orig(self, *a, **k)
        bx0, by0, bx1, by1 = self.region.bounds
        seen.append((float(self.h), max(bx1 - bx0, by1 - by0)))

    monkeypatch.setattr(E._Grower, "__init__", init)
    run()
    monkeypatch.setattr(E._Grower, "__init__", orig)
    return seen


# hierarchy too (helper w27h): its tiles at 48 grew on cells of 0.23 against the world's
# 0.75 as well
@pytest.mark.parametrize("pattern", ["vase", "hierarchy"])
@pytest.mark.parametrize("params", [{}, {"cells": 160}])
def test_tiles_grow_on_the_world_cell(monkeypatch, params, pattern):
    # a 120 x 120 world in tiles of 40 (halo 10): each tile's region is 50-60 units,
    # under the 256-cell floor; max_elements keeps every run short
    side = 120.0
    (world_h, _), = _cells_seen(monkeypatch, lambda: grow_ornament(pattern, strew.Region.rectangle(side, side), rng=3, max_elements=5, **params))
    seen = _cells_seen(monkeypatch, lambda: T.tiled("ornament", pattern, (side, side), tile_size=40.0, seed=3, max_elements=5, **params))
    assert len(seen) == 9
    for h, region_side in seen:
        assert region_side < side
        # whole cells along the region's side, no coarser than the world's and less
        # than one cell per side finer
        assert h <= world_h + 1e-12
        assert region_side / h - region_side / world_h < 1.0 + 1e-9


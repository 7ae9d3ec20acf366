"""A finished hierarchy tile keeps its flowers up to the border (issue 19 point 4, helper w31h).

Wong et al. grow every flower before any leaf (§5, Fig. 10). A tile of a world
(strew.tiles) left its later phases within half a halo of a later tile to that tile
(_LATE_BAND), and the later tile refilled that band from its side: its flowers landed on
the border and the band's inner half got leaves (finished side 0.5-1 s, tiles 40, 52, 56:
flowers 16 against the untiled control's 32, leaves 85 against 72;
benchmarks/results/w31h_summary.txt). The tile now keeps its second phase (hierarchy's
flowers) there as it grew it (strew.tiles._held_phase_rows); leaves and fillers are still
left to the later tile.
"""

from __future__ import annotations

import numpy as np

from strew.tiles import _Job, plan, run_tile

SIZE, TILE, HALO = (192.0, 192.0), 48.0, 12.0


def test_finished_tile_keeps_its_flowers_near_a_later_tile():
    tiles, nx, ny = plan(SIZE, TILE)
    job = _Job("ornament", "hierarchy", {}, SIZE, HALO, 1, (TILE, TILE), (nx, ny), False)
    t = tiles[2 * nx + 2]  # phase 0 with a later tile on every side
    assert t.phase == 0
    arr = run_tile(job, t)
    names = np.asarray(arr.kinds, dtype=object)[np.asarray(arr.kind, np.int64)]
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    x0, y0, x1, y1 = t.rect
    inset = np.minimum.reduce([x - x0, x1 - x, y - y0, y1 - y])  # > 0: inside t
    band = (inset > 0) & (inset < 0.5 * HALO)
    inner = inset >= 0.5 * HALO
    a_band = TILE**2 - (TILE - HALO) ** 2
    a_inner = (TILE - HALO) ** 2
    flower = names == "flower"
    # the band's flowers per unit area against the tile's inner part: 0.43 now, 0.14 before
    # (one flower, kept only as the ancestor of a leaf deeper in the tile)
    assert (flower & band).sum() / a_band >= 0.3 * (flower & inner).sum() / a_inner
    # the leaves and fillers near the later tiles are still theirs
    assert not (np.isin(names, ["leaf", "quote"]) & band).any()

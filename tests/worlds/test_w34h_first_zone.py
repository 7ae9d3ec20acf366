"""A finished hierarchy tile grows its vines only where it keeps them (issue 19 point 4,
helper w34h).

A tile of a world (strew.tiles) keeps its first phase (hierarchy's vines) up to half a
halo past its border with a later tile (_first_phase_rows) and leaves deeper vines to that
tile. It grew them up to a halo past the border, more of them there than on its own side
near the border, and earlier (the open edge's circles are large, and §4.1 fills the
largest first): those vines shrank its own circles near the border, then were cut
(benchmarks/results/w32h_interior_vines.txt). Its first phase now grows within the kept
reach only (strew.tiles._first_zone).
"""

from __future__ import annotations

import numpy as np

import strew.tiles as tiles
from strew.tiles import _Job, plan, run_tile

SIZE, TILE, HALO = (192.0, 192.0), 48.0, 12.0


def test_finished_tile_grows_no_vine_past_its_kept_reach(monkeypatch):
    tl, nx, ny = plan(SIZE, TILE)
    job = _Job("ornament", "hierarchy", {}, SIZE, HALO, 1, (TILE, TILE), (nx, ny), False)
    t = tl[2 * nx + 2]  # phase 0 with a later tile on every side
    assert t.phase == 0
    grown = []
    keep_groups = tiles._keep_groups

    def spy(arr, keep, *a, **k):
        grown.append(arr)
        return keep_groups(arr, keep, *a, **k)

    monkeypatch.setattr(tiles, "_keep_groups", spy)
    kept = run_tile(job, t)
    arr = grown[0]
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    x0, y0, x1, y1 = t.rect
    depth = np.hypot(np.maximum(np.maximum(x0 - x, x - x1), 0.0), np.maximum(np.maximum(y0 - y, y - y1), 0.0))
    vine = np.asarray(arr["phase"], dtype=object) == "vines"
    # every vine the tile grew lies where it keeps its vines (half a halo past the border);
    # before, it grew dozens up to a halo past it and cut them
    assert vine.sum() > 20
    assert depth[vine].max() <= tiles._KEEP_FIRST_REACH * HALO + 1e-9
    # and it still grows vines up to that reach past its border, and keeps them
    assert (vine & (depth > 0)).sum() >= 4
    names = np.asarray(kept.kinds, dtype=object)[np.asarray(kept.kind, np.int64)]
    kx, ky = np.asarray(kept.x, float), np.asarray(kept.y, float)
    out = (kx < x0) | (kx > x1) | (ky < y0) | (ky > y1)
    assert ((names == "vine") & out).sum() >= 4

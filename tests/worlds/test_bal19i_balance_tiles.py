"""synth's balance rule inside tiles (issue 19 point 4, helper bal19i).

A tile's region reaches a halo past its rectangle into the tiles that run after it;
the tile drops what it grows there (beyond a band about its rectangle), and the later
tiles grow it again. ``strew.tiles.run_tile`` hands synth that part of the region
(``_synth_drop``, the private ``_balance_drop`` of ``synthesize``), and the balance
rule (``strew.synth._grow._prefer_balanced``, ``BALANCE_TILE``) leaves alone the seeds
whose disc reaches the region's edge there (``"edge"``, the default) or reaches into
it (``"cut"``). Untiled synthesis never has one.
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew.tiles import _Job, _grow, _synth_drop, plan
from strew_testing import fidelity_suite

T, HALO, BAND = 440.0, 110.0, 25.0


def _tile(tiles, i, j):
    return next(t for t in tiles if t.i == i and t.j == j)


def test_the_dropped_part_is_the_later_tiles_side_beyond_the_band():
    from strew.region import Region

    tiles, nx, ny = plan((4 * T, 4 * T), T)
    job = _Job("synth", None, {}, (4 * T, 4 * T), HALO, 1, (T, T), (nx, ny))
    t = _tile(tiles, 2, 2)  # phase 0: all 8 neighbours run later
    region = Region(shapely.box(*_grow(t.rect, HALO, job.size)))
    drop = _synth_drop(region, t, job, BAND)
    x0, y0, x1, y1 = t.rect
    assert drop is not None
    assert drop.area == pytest.approx((T + 2 * HALO) ** 2 - (T + 2 * BAND) ** 2)
    inside = [(x0 + 1, y0 + 1), ((x0 + x1) / 2, (y0 + y1) / 2), (x1 + BAND - 1, y1 - 1), (x0 - BAND + 1, y0 - BAND + 1)]
    beyond = [(x1 + BAND + 1, (y0 + y1) / 2), (x0 - HALO + 1, y0 - HALO + 1), ((x0 + x1) / 2, y1 + HALO - 1)]
    assert not shapely.contains_xy(drop, *np.array(inside).T).any()
    assert shapely.contains_xy(drop, *np.array(beyond).T).all()
    # the last phase drops nothing; a phase-1 tile only its later neighbours' side
    assert _synth_drop(region, _tile(tiles, 1, 1), job, BAND) is None
    t1 = _tile(tiles, 1, 2)  # phase 1: its left and right neighbours (phase 0) are finished
    r1 = Region(shapely.box(*_grow(t1.rect, HALO, job.size)))
    d1 = _synth_drop(r1, t1, job, BAND)
    a0, b0, a1, b1 = t1.rect
    assert shapely.contains_xy(d1, (a0 + a1) / 2, b1 + HALO - 1) and shapely.contains_xy(d1, (a0 + a1) / 2, b0 - HALO + 1)
    assert not shapely.contains_xy(d1, a0 - HALO + 1, (b0 + b1) / 2) and not shapely.contains_xy(d1, a1 + HALO - 1, (b0 + b1) / 2)


@pytest.mark.slow  # one 550 x 550 three_sizes tile and a 300 x 300 synthesis, twice: about 6 s
@pytest.mark.parametrize("mode", ["edge", "cut"])
def test_the_rule_leaves_alone_the_seeds_whose_disc_reaches_the_dropped_part(monkeypatch, mode):
    import strew
    import strew.synth._grow as G
    from strew.synth import synthesize
    from strew.tiles import run_tile

    if mode == "edge":
        assert G.BALANCE_TILE == "edge"  # the default
    ex = fidelity_suite().make_exemplar("three_sizes")
    orig = G._prefer_balanced
    seen = []

    def wrapped(state, seeds, cands, costs, slack, c):
        before = costs.copy()
        orig(state, seeds, cands, costs, slack, c)
        prep = state.prep
        side = np.sqrt(np.bincount(prep.source, minlength=len(prep.names)) / np.maximum(prep.density, 1e-12))
        reach = G.BALANCE_RADIUS * side[prep.source[state.src[seeds]]]
        drop = state._balance_drop
        if drop is None:
            near = np.zeros(len(seeds), bool)
        else:
            far = drop if mode == "cut" else shapely.intersection(drop.boundary, state.region.geometry.boundary)
            near = shapely.distance(far, shapely.points(state.pos[seeds])) <= reach
        changed = (before != costs).any(axis=1)
        seen.append((drop is not None, int(near.sum()), int((changed & near).sum()), int((changed & ~near).sum())))

    monkeypatch.setattr(G, "_prefer_balanced", wrapped)
    monkeypatch.setattr(G, "BALANCE_TILE", mode)
    tiles, nx, ny = plan((2 * T, 2 * T), T)
    job = _Job("synth", ex, {"measure": False}, (2 * T, 2 * T), HALO, 3, (T, T), (nx, ny))
    arr = run_tile(job, tiles[0])  # phase 0, in the world's corner: tiles 1-3 run later
    assert len(arr) > 500 and seen
    tiled = np.array(seen)
    assert tiled[:, 0].all()  # every call inside the tile knows the dropped part
    assert tiled[:, 1].sum() > 30  # many seeds reach it ...
    assert tiled[:, 2].sum() == 0  # ... and the rule reorders none of their candidates
    assert tiled[:, 3].sum() > 0  # it still acts on the others
    seen.clear()
    synthesize(ex, strew.Region.rectangle(300, 300), rng=3, measure=False)
    untiled = np.array(seen)
    assert len(untiled) and not untiled[:, 0].any() and untiled[:, 3].sum() > 0  # untiled: the rule as before

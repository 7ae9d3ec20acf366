"""Repeat tiles made by tiling a torus (issue 18 through strew.tiles, issue 19's runner)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import strew
from strew import _periodic as P
from strew._errors import InputError
from strew.tiles import _links, periodic, plan_periodic

sys.path.insert(0, str(Path(__file__).parents[1] / "worlds"))
from world_stats import overlapping_pairs  # noqa: E402

SHAPES = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}


def _edge_ratio(arr, width: float) -> float:
    """Density of centres within ``width`` of the tile's edges over the rest's."""
    x0, y0, w, h = P.frame(arr)
    x, y = arr.x - x0, arr.y - y0
    edge = (x < width) | (x > w - width) | (y < width) | (y > h - width)
    edge_area = w * h - (w - 2 * width) * (h - 2 * width)
    return (edge.sum() / edge_area) / ((~edge).sum() / (w * h - edge_area))


@pytest.fixture(scope="module")
def packed():
    return periodic("pack", SHAPES, (120, 90), rng=3, tile_size=30)


def test_pack_repeat_has_no_overlaps_across_the_wrap(packed):
    a = packed
    assert P.frame(a) == (0.0, 0.0, 120.0, 90.0)
    assert a.meta["world"]["grid"] == [4, 4]  # 120 / 30 and 90 / 30 = 3 rounded to an even 4
    assert len(a) > 800
    assert ((a.x >= 0) & (a.x < 120) & (a.y >= 0) & (a.y < 90)).all()  # canonical
    assert overlapping_pairs(P.tiled_copies(a, 3, 3)) == 0
    # elements do cross the edges (the wrap is really exercised)
    import shapely

    b = shapely.bounds(a.geometry)
    assert (b[:, 0] < 0).any() and (b[:, 2] > 120).any() and (b[:, 1] < 0).any() and (b[:, 3] > 90).any()
    assert a.meta["method"] == "pack" and a.meta["seed"] == 3 and "params" in a.meta


def test_pack_repeat_is_deterministic_and_seeded(packed):
    again = periodic("pack", SHAPES, (120, 90), rng=3, tile_size=30)
    assert again.equals(packed)
    other = periodic("pack", SHAPES, (120, 90), rng=4, tile_size=30)
    assert not np.array_equal(other.x[:20], packed.x[:20])
    gen = np.random.default_rng(3)
    from_gen = periodic("pack", SHAPES, "60x40", rng=gen)
    assert "rng_state" in from_gen.meta  # a Generator is recorded as methods record it
    assert periodic("pack", SHAPES, "60x40", rng=np.random.default_rng(3)).equals(from_gen)


def test_pack_edge_strips_match_the_interior():
    # measured: strips of width halo (3.35) along the tile's edges hold 1.03-1.06x the
    # interior's density at 200 x 200 (seeds 1-3), 0.97-1.06x at 120 x 120 (seeds 1-4);
    # density by distance to a seam oscillates (0-1: 1.00, 1-2: 1.13, 3-4: 0.92x)
    ratios, fracs = [], []
    for seed in (1, 2):
        a = periodic("pack", SHAPES, (160, 160), rng=seed)
        width = a.meta["world"]["halo"]
        ratios.append(_edge_ratio(a, width))
        x, y = a.x, a.y
        edge = (x < width) | (x > 160 - width) | (y < width) | (y > 160 - width)
        fracs.append((a.kind[edge] == 0).mean() - (a.kind[~edge] == 0).mean())
    assert 0.94 <= np.mean(ratios) <= 1.08, ratios
    assert abs(np.mean(fracs)) < 0.04, fracs


def test_a_corner_away_from_the_origin_is_kept():
    a = periodic("pack", SHAPES, strew.Region.rectangle(40, 40, 10, -5), rng=1)
    assert P.frame(a) == (10.0, -5.0, 40.0, 40.0)
    assert ((a.x >= 10) & (a.x < 50) & (a.y >= -5) & (a.y < 35)).all()
    assert overlapping_pairs(P.tiled_copies(a)) == 0


def test_synth_repeat_has_no_overlaps_across_the_wrap():
    from strew.io import load

    ex = load(Path(__file__).parents[2] / "examples" / "exemplars" / "stones.svg")
    a = periodic("synth", ex, (200, 200), rng=1)
    assert len(a) > 40
    assert a.meta["method"] == "synth" and P.frame(a) == (0.0, 0.0, 200.0, 200.0)
    assert overlapping_pairs(P.tiled_copies(a, 3, 3)) == 0


def test_refusals_name_the_problem():
    with pytest.raises(InputError, match="rectangular region"):
        periodic("pack", SHAPES, strew.Region.circle(0, 0, 50), rng=1)
    with pytest.raises(InputError, match=r"^size: a periodic 10 x 10 tile is cut into 2 x 2 tiles.*at least 13.4"):
        periodic("pack", SHAPES, (10, 10), rng=1)
    with pytest.raises(InputError, match="^method: unknown method 'nope'"):
        periodic("nope", SHAPES, (50, 50), rng=1)


@settings(max_examples=40, deadline=None)
@given(st.floats(1, 1000), st.floats(1, 1000), st.one_of(st.none(), st.floats(0.05, 2)))
def test_torus_plan_has_even_counts_and_phases_differ_across_the_wrap(w, h, frac):
    t = None if frac is None else frac * max(w, h)  # at most 40 x 40 tiles
    tiles, nx, ny = plan_periodic((w, h), t)
    assert nx % 2 == 0 and ny % 2 == 0 and nx >= 2 and ny >= 2
    area = sum((r[2] - r[0]) * (r[3] - r[1]) for r in (x.rect for x in tiles))
    assert area == pytest.approx(w * h, rel=1e-9)
    for x in tiles:
        for dj in (-1, 0, 1):
            for di in (-1, 0, 1):
                if di or dj:  # the 8 neighbours on the torus never share a phase
                    assert tiles[((x.j + dj) % ny) * nx + (x.i + di) % nx].phase != x.phase
        links = _links(x, nx, ny, (w, h))
        assert all(tiles[k].phase < x.phase for k in links)
        # every lower-phase neighbour position appears once, moved next to x
        assert sum(len(v) for v in links.values()) == sum(
            1 for dj in (-1, 0, 1) for di in (-1, 0, 1)
            if (di or dj) and tiles[((x.j + dj) % ny) * nx + (x.i + di) % nx].phase < x.phase)
        for k, shifts in links.items():
            r = tiles[k].rect
            for dx, dy in shifts:  # the moved neighbour touches x's rectangle
                assert r[0] + dx <= x.rect[2] + 1e-9 * w and r[2] + dx >= x.rect[0] - 1e-9 * w
                assert r[1] + dy <= x.rect[3] + 1e-9 * h and r[3] + dy >= x.rect[1] - 1e-9 * h


@pytest.mark.parametrize("seed", [1, 2])
def test_tiles_at_the_halo_limit_never_overlap(seed):
    # elements as large as the tiles allow (halo = twice the bar's reach = 6.7, tiles of
    # 15 >= 2 halo), where a tile's kept elements reach deepest into its neighbours
    big = {"bar": strew.Shape.rectangle(6, 3), "disc": strew.Shape.circle(2.0, 16)}
    a = periodic("pack", big, (60, 60), rng=seed, tile_size=15)
    assert a.meta["world"]["grid"] == [4, 4] and a.meta["world"]["halo"] == pytest.approx(2 * np.hypot(3, 1.5))
    assert len(a) > 60 and overlapping_pairs(P.tiled_copies(a)) == 0
    from strew.tiles import tiled

    b = tiled("pack", big, (75, 45), tile_size=15, seed=seed)  # 5 x 3 tiles, not a torus
    assert len(b) > 60 and overlapping_pairs(b) == 0

"""Painting a repeat tile (issue 18 point 4): the synthesis state's brush, filler and
eraser on the torus of a tile (``SynthState.set_tile``) and the spray on it
(``SprayGrowth(tile=...)``), as the studio's repeat view uses them. Copies of the painted
tile laid 3 x 3 do not overlap, and the strips along the tile's edges are as dense as its
interior (no seam)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import InputError, Region, load, metrics, synth
from strew import _periodic as P
from strew.grow import SprayGrowth

EXEMPLAR = Path(__file__).resolve().parents[2] / "examples" / "synth" / "pebbles.json"
TILE = (0.0, 0.0, 140.0, 140.0)
RADIUS = 20.0


@pytest.fixture(scope="module")
def pebbles():
    return load(EXEMPLAR)


def _rows(w: float, h: float, radius: float) -> list[np.ndarray]:
    """Strokes across the whole tile and 20 past both side edges, rows 1.2 radii apart."""
    xs = np.arange(-20.0, w + 20.0, 8.0)
    return [np.c_[xs, np.full(len(xs), y)] for y in np.arange(0.5 * radius, h, 1.2 * radius)]


def _state(ex, seed: int):
    st_ = synth.new_state(ex, Region.rectangle(TILE[2], TILE[3]), rng=seed)
    st_.set_tile(TILE)
    return st_


def _brushed(ex, seed: int):
    state = _state(ex, seed)
    for row in _rows(TILE[2], TILE[3], RADIUS):
        synth.brush(state, row, RADIUS)
    return state, state.to_arrangement()


def _sprayed(ex, seed: int):
    g = SprayGrowth(ex, radius=RADIUS, tile=TILE, rng=seed)
    for row in _rows(TILE[2], TILE[3], RADIUS):
        g.add_points(row)
        g.grow()
    return g.arrangement()


def _check_tile(arr, *, min_ratio: float = 0.85) -> dict:
    """A periodic tile whose 3 x 3 copies do not overlap and whose edges are not thinner
    than its interior."""
    assert P.frame(arr) == TILE
    x0, y0, w, h = TILE
    assert np.all((arr.x >= x0) & (arr.x < x0 + w) & (arr.y >= y0) & (arr.y < y0 + h))  # canonical
    pairs, _ = metrics.overlaps(P.tiled_copies(arr, 3, 3))
    assert len(pairs) == 0
    rep = metrics.repeat_report(arr)
    assert rep["overlaps"]["across"] == 0 and rep["overlaps"]["inside"] == 0
    assert rep["density"]["ratio"] >= min_ratio, rep["density"]
    # elements reach the strips on every side, so the repeat has no empty band
    s = rep["strip"]
    for side in (arr.x < x0 + s, arr.x >= x0 + w - s, arr.y < y0 + s, arr.y >= y0 + h - s):
        assert side.sum() >= 5
    return rep


def test_a_brush_stroke_across_the_edge_continues_at_the_opposite_one(pebbles):
    state = _state(pebbles, 2)
    x = np.arange(80.0, 200.0, 8.0)  # from inside the tile to 60 past its right edge
    synth.brush(state, np.c_[x, np.full(len(x), 70.0)], RADIUS)
    assert not state.ghost.any()  # ghost images live only during growth
    arr = state.to_arrangement()
    assert np.sum(arr.x < 50) >= 10 and np.sum(arr.x > 90) >= 10  # both sides of the seam at x = 0
    assert np.all(np.abs(arr.y - 70.0) <= RADIUS + 1e-9)  # within the brush discs
    assert len(metrics.overlaps(P.tiled_copies(arr))[0]) == 0
    # the eraser wraps too: a path just right of the edge at x = 140 erases its left side
    before = state.to_arrangement()
    gone = synth.erase(state, np.array([[150.0, 50.0], [150.0, 90.0]]), 15.0)
    after = state.to_arrangement()

    def dist(a):  # to the path on the torus
        return np.hypot(P.wrap_delta(a.x - 150.0, TILE[2]), np.clip(a.y, 50.0, 90.0) - a.y)

    assert gone == int(np.sum(dist(before) <= 15.0)) > 0
    assert np.all(dist(after) > 15.0)


def test_a_brushed_tile_repeats_without_a_seam(pebbles):
    _, arr = _brushed(pebbles, 1)
    _check_tile(arr)


def test_a_filled_tile_repeats_without_a_seam(pebbles):
    state = _state(pebbles, 3)
    synth.fill(state, (10.0, 130.0))  # from near a corner: growth meets itself across the edges
    _check_tile(state.to_arrangement())


def test_a_sprayed_tile_repeats_without_a_seam(pebbles):
    arr = _sprayed(pebbles, 1)
    assert arr.meta["tool"] == "spray"
    _check_tile(arr)


def test_painting_a_tile_is_deterministic(pebbles):
    row = np.c_[np.arange(100.0, 190.0, 8.0), np.full(12, 30.0)]  # across the right edge

    def brushed():
        state = _state(pebbles, 4)
        synth.brush(state, row, RADIUS)
        return state.to_arrangement()

    def sprayed():
        g = SprayGrowth(pebbles, radius=RADIUS, tile=TILE, rng=4)
        g.add_points(row)
        return g.grow()

    a, b = brushed(), brushed()
    assert len(a) > 10 and a.xy.tobytes() == b.xy.tobytes() and a.kind.tobytes() == b.kind.tobytes()
    c, d = sprayed(), sprayed()
    assert len(c) > 10 and c.xy.tobytes() == d.xy.tobytes() and c.rotation.tobytes() == d.rotation.tobytes()


def test_without_a_tile_nothing_changes(pebbles):
    """The plane is untouched: set_tile(None) after a tile gives the plain brush."""
    row = np.c_[np.arange(10.0, 130.0, 8.0), np.full(15, 70.0)]
    plain = synth.new_state(pebbles, Region.rectangle(140, 140), rng=5)
    synth.brush(plain, row, RADIUS)
    back = _state(pebbles, 5)
    back.set_tile(None)
    synth.brush(back, row, RADIUS)
    assert plain.pos.tobytes() == back.pos.tobytes()
    assert "periodic" not in back.to_arrangement().meta


def test_a_tile_too_small_is_refused(pebbles):
    state = synth.new_state(pebbles, None, rng=1)
    with pytest.raises(InputError, match="too small"):
        state.set_tile((0, 0, 20, 300))
    with pytest.raises(InputError, match="width and height must be positive"):
        state.set_tile((0, 0, -5, 300))
    with pytest.raises(InputError, match="too small"):
        SprayGrowth(pebbles, radius=10.0, tile=(0, 0, 15, 15))


_STATE: dict = {}


@settings(max_examples=60, deadline=None)
@given(
    x=st.floats(-300, 300), y=st.floats(-300, 300), r=st.floats(1, 60),
    qx=st.floats(0, 139.99), qy=st.floats(0, 139.99),
)
def test_wrapped_brush_discs_cover_the_torus_disc(pebbles, x, y, r, qx, qy):
    """A point of the tile is within a wrapped disc exactly when it is within ``r`` of
    the brush point on the torus."""
    state = _STATE.get("s") or _STATE.setdefault("s", _state(pebbles, 1))  # one state for all examples
    pts, rad = state.wrap_discs(np.array([[x, y]]), np.array([r]))
    assert np.all((pts[0] >= 0) & (pts[0] < 140))  # the centre first, wrapped
    d_torus = np.hypot(P.wrap_delta(qx - x, 140.0), P.wrap_delta(qy - y, 140.0))
    d_discs = np.min(np.hypot(pts[:, 0] - qx, pts[:, 1] - qy) - rad)
    if abs(d_torus - r) > 1e-6:
        assert (d_discs <= 0) == (d_torus <= r)


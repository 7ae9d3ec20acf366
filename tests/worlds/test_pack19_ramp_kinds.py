"""pack's ramp hand-over: which kinds a finished tile drops near a later one (issue 19 point 4).

A finished tile thins its elements near a later tile (``strew.tiles._ramp``); within a
kind, a larger element is dropped less (by the square root of the area ratio, so that a
large element's hole is not refilled by two small ones). Across kinds the area ratio
used to weigh too: strew demo's stones (ring 460, hook 620, crescent 382 units of area)
had their crescents, the smallest, dropped most, and the later tile refilled their
holes with rings, the most compact kind, about as often as with crescents: crescents'
share within 1 spacing of a border 0.970 [0.956, 0.986] of the interior's (``python
benchmarks/pack_seam_kinds.py --seeds 1,2,3,4``). Across kinds the weight is now the
kinds' compactness (area over the circumscribed disc's) to the power 1/4: a compact
kind fits any kind's hole, so it is dropped more.
"""

from __future__ import annotations

import math

import numpy as np

import strew
from strew.tiles import _RAMP_COMPACT_EXPONENT, Tile, _Job, _ramp, plan

T = 100.0
N = 4000  # elements of each kind; binomial sd of a drop rate near 0.5: 0.008


def _job() -> _Job:
    # two tiles side by side: tile 0 (phase 0) runs first, tile 1 (phase 1) is its later neighbour
    return _Job("pack", None, {}, (2 * T, T), 10.0, 7, (T, T), (2, 1))


def _tile0() -> Tile:
    tiles, _, _ = plan((2 * T, T), T)
    assert tiles[0].phase == 0 and tiles[1].phase == 1
    return tiles[0]


def _arr(shapes: dict, scales: np.ndarray, x: float) -> strew.Arrangement:
    kind = np.repeat(np.arange(len(shapes)), N)
    y = np.tile(np.linspace(1.0, T - 1.0, N), len(shapes))
    return strew.Arrangement(shapes, kind, np.full(len(kind), x), y, np.zeros(len(kind)), np.tile(scales, len(shapes)))


def _dropped(shapes: dict, scales: np.ndarray) -> np.ndarray:
    # half a halo before the border: drop probability 0.5 times the weights
    return ~_ramp(_arr(shapes, scales, T - 5.0), _tile0(), _job())


def test_kinds_of_one_form_are_dropped_alike_whatever_their_areas():
    # squares of side 1 and 2, each at scale 1: the larger (4x the area) is dropped as
    # often as the smaller (7c83aee: half as often, the area ratio taken across kinds)
    d = _dropped({"small": strew.Shape.rectangle(1.0, 1.0), "large": strew.Shape.rectangle(2.0, 2.0)}, np.ones(N))
    small, large = d[:N].mean(), d[N:].mean()
    assert abs(small - 0.5) < 0.04, small
    assert abs(large - small) < 0.04, (small, large)


def test_a_compact_kind_is_dropped_more_than_an_elongated_one_of_its_area():
    # a disc and a 4 x 1 bar of the same area: the bar is dropped (c_bar / c_disc) ** 1/4
    # as often (7c83aee: alike)
    disc = strew.Shape.circle(1.0, 64)
    side = math.sqrt(disc.area / 4.0)
    bar = strew.Shape.rectangle(4.0 * side, side)
    d = _dropped({"disc": disc, "bar": bar}, np.ones(N))
    c = [s.area / (math.pi * s.radius**2) for s in (disc, bar)]
    expect = 0.5 * (c[1] / c[0]) ** _RAMP_COMPACT_EXPONENT
    assert expect < 0.42  # the test can tell the two apart
    assert abs(d[:N].mean() - 0.5) < 0.04, d[:N].mean()
    assert abs(d[N:].mean() - expect) < 0.04, (d[N:].mean(), expect)


def test_larger_elements_of_a_kind_are_dropped_less():
    # within a kind the area weight stays: scale 2 (4x the area) dropped half as often
    sc = np.where(np.arange(N) % 2 == 0, 1.0, 2.0)
    d = _dropped({"small": strew.Shape.rectangle(1.0, 1.0), "large": strew.Shape.rectangle(2.0, 2.0)}, sc)
    for part in (slice(0, N), slice(N, 2 * N)):
        lo, hi = d[part][sc == 1.0].mean(), d[part][sc == 2.0].mean()
        assert abs(lo - 0.5) < 0.04, lo
        assert abs(hi - 0.25) < 0.04, hi


def test_what_is_a_halo_away_is_kept():
    shapes = {"small": strew.Shape.rectangle(1.0, 1.0), "large": strew.Shape.rectangle(2.0, 2.0)}
    assert _ramp(_arr(shapes, np.ones(N), T - 10.5), _tile0(), _job()).all()

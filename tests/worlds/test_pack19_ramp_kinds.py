"""pack's ramp hand-over drops every kind alike (issue 19 point 4).

A finished tile thins its elements near a later tile (``strew.tiles._ramp``); within a
kind, a larger element is dropped less (by the square root of the area ratio, so that a
large element's hole is not refilled by two small ones). Across kinds the area ratio
used to weigh too: strew demo's stones (ring 460, hook 620, crescent 382 units of area)
had their crescents, the smallest, dropped most, and the later tile refilled their
holes with rings as often as with crescents: crescents' share within 1 spacing of a
border 0.970 [0.956, 0.986] of the interior's (``python benchmarks/pack_seam_kinds.py
--seeds 1,2,3,4``); with the weight taken within each kind, 1.001.
"""

from __future__ import annotations

import numpy as np

import strew
from strew.tiles import Tile, _Job, _ramp, plan

T = 100.0


def _job() -> _Job:
    # two tiles side by side: tile 0 (phase 0) runs first, tile 1 (phase 1) is its later neighbour
    return _Job("pack", None, {}, (2 * T, T), 10.0, 7, (T, T), (2, 1))


def _arr(n: int, scales: np.ndarray, x: float) -> strew.Arrangement:
    shapes = {"small": strew.Shape.circle(1.0, 16), "large": strew.Shape.rectangle(4.0, 3.0)}
    kind = np.repeat([0, 1], n)
    y = np.tile(np.linspace(1.0, T - 1.0, n), 2)
    sc = np.tile(scales, 2)
    return strew.Arrangement(shapes, kind, np.full(2 * n, x), y, np.zeros(2 * n), sc)


def test_ramp_drops_every_kind_at_the_same_rate():
    # at the same distance from the later tile and each kind at its own smallest scale,
    # a kind four times larger in area is dropped as often as the small one
    n = 4000
    a = _arr(n, np.ones(n), T - 5.0)  # half a halo before the border: drop probability 0.5
    keep = _ramp(a, _tile0(), _job())
    dropped = ~keep
    small, large = dropped[:n].mean(), dropped[n:].mean()
    # binomial sd at p = 0.5, n = 4000: 0.008
    assert abs(small - 0.5) < 0.04, small
    assert abs(large - small) < 0.04, (small, large)


def test_ramp_drops_larger_elements_of_a_kind_less():
    # within a kind the area weight stays: scale 2 (4x the area) dropped half as often
    n = 4000
    sc = np.where(np.arange(n) % 2 == 0, 1.0, 2.0)
    a = _arr(n, sc, T - 5.0)
    dropped = ~_ramp(a, _tile0(), _job())
    for part in (slice(0, n), slice(n, 2 * n)):
        d, s = dropped[part], sc
        lo, hi = d[s == 1.0].mean(), d[s == 2.0].mean()
        assert abs(lo - 0.5) < 0.04, lo
        assert abs(hi - 0.25) < 0.04, hi


def test_ramp_keeps_what_is_a_halo_away():
    n = 500
    a = _arr(n, np.ones(n), T - 10.5)
    assert _ramp(a, _tile0(), _job()).all()


def _tile0() -> Tile:
    tiles, _, _ = plan((2 * T, T), T)
    return tiles[0]

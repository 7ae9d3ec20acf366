"""Border strips against the untiled control on the same lines (issue 19.4, helper w60d).

A world that is not stationary at the tile's scale shows a strip-to-interior ratio off 1
without any seam: ornament's hierarchy grown from the first-phase tiles' seed points, at
tiles of 32-48, where the interior (>= 3 s from every border) is only each tile's centre
(benchmarks/results/w60d_notes.md). world_stats.strip_ratios_against_control divides the
tiled world's ratios by its untiled control's on the same lines: a structure tied to the
lines' positions (here a denser band along them) cancels; what the tiles add does not.
"""

from __future__ import annotations

import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from world_stats import strip_ratios_against_control, strip_units  # noqa: E402

SIZE = (400.0, 400.0)
TILE = 100.0
SPACING = 2.0  # about 0.25 points per unit area: s = 2
WIDTH, MARGIN = 2 * SPACING, 3 * SPACING


def _world(rng: np.random.Generator, band: float = 2.0, seam: float = 0.0) -> SimpleNamespace:
    """Poisson points of two kinds (b: 30 %) at 0.25 per unit area; ``band`` x that
    density (kind b's share unchanged) within 10 units of the lines x, y = 50 + 100 k, which
    fall in the tiles' centres as hierarchy's seed points do; ``seam``: extra points of kind
    b per unit area within WIDTH of the tile borders x, y = 100 k (what a seam would put
    there)."""
    n = rng.poisson(0.25 * SIZE[0] * SIZE[1])
    p = rng.uniform(0, SIZE[0], (n, 2))
    near_centre = (np.abs((p + 50.0) % TILE - TILE / 2) > TILE / 2 - 10).any(1)
    extra = p[near_centre][rng.random(near_centre.sum()) < band - 1.0]
    pts = [p, extra]
    kinds = [rng.random(len(p)) < 0.3, rng.random(len(extra)) < 0.3]
    if seam > 0:
        m = rng.poisson(seam * SIZE[0] * SIZE[1])
        q = rng.uniform(0, SIZE[0], (m, 2))
        d = np.abs((q + TILE / 2) % TILE - TILE / 2)
        q = q[(d < WIDTH).any(1)]
        pts.append(q)
        kinds.append(np.ones(len(q), bool))
    xy = np.concatenate(pts)
    return SimpleNamespace(x=xy[:, 0], y=xy[:, 1], kind=np.concatenate(kinds).astype(np.int64), kinds=["a", "b"])


def _units(arr) -> dict:
    return strip_units(arr, SIZE, TILE, WIDTH, MARGIN)


def _cat(us: list[dict]) -> dict:
    return {k: np.concatenate([u[k] for u in us]) for k in ("strip", "inner", "strip_area", "inner_area", "strip_kind", "inner_kind")}


def test_lines_bias_cancels_against_the_control() -> None:
    """The band along the tiles' centres lowers the strip-to-interior density ratio of both
    worlds alike (no seam anywhere): the own ratio's interval excludes 1 by far, the double
    ratio's holds it, and kind b's share (unchanged by the band) stays 1 in both."""
    rng = np.random.default_rng(60)
    t = _cat([_units(_world(rng)) for _ in range(4)])
    c = _cat([_units(_world(rng)) for _ in range(4)])
    r = strip_ratios_against_control(t, c, 400, np.random.default_rng(0))
    d = r["density"]
    assert d["tiled"]["ci"][1] < 0.9 and d["control"]["ci"][1] < 0.9  # the lines' bias: strips look sparse
    lo, hi = d["tiled_over_control"]["ci"]
    assert lo < 1.0 < hi and hi - lo < 0.1
    assert abs(d["tiled_over_control"]["value"] - 1.0) < 0.03
    b = r["kind_share"][1]["tiled_over_control"]
    assert b["ci"][0] < 1.0 < b["ci"][1]


def test_a_seam_shows_against_the_control() -> None:
    """Extra kind-b points in the tiled world's strips only: the double ratio sees them in
    the density and in kind b's share (and kind a's share falls), though the own ratio,
    lowered by the band, can lie near 1."""
    rng = np.random.default_rng(61)
    t = _cat([_units(_world(rng, seam=0.04)) for _ in range(4)])
    c = _cat([_units(_world(rng)) for _ in range(4)])
    r = strip_ratios_against_control(t, c, 400, np.random.default_rng(0))
    assert r["density"]["tiled"]["ci"][1] > 0.97  # the own measure: the band hides the seam
    assert r["density"]["tiled_over_control"]["ci"][0] > 1.05
    assert r["kind_share"][1]["tiled_over_control"]["ci"][0] > 1.1
    assert r["kind_share"][0]["tiled_over_control"]["ci"][1] < 0.97


def test_same_world_gives_exactly_one_and_units_must_pair() -> None:
    u = _units(_world(np.random.default_rng(62)))
    r = strip_ratios_against_control(u, u, 50, np.random.default_rng(0))
    assert r["density"]["tiled_over_control"]["value"] == pytest.approx(1.0, abs=1e-12)
    assert r["density"]["tiled_over_control"]["ci"] == pytest.approx([1.0, 1.0], abs=1e-12)
    half = {k: v[:8] for k, v in u.items()}
    with pytest.raises(ValueError):
        strip_ratios_against_control(u, half, 10, np.random.default_rng(0))

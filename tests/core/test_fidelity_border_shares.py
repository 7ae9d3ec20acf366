"""strew.metrics.fidelity: kind shares of an exemplar whose frame is a wall (issue 13).

An artist (and the suite's generator) keeps large stones wholly inside the frame and fills
the band along it with pebbles, so the whole frame under-counts large stones against the
texture's stationary interior, which is what a stationary result continues. The judge
counts kinds by minus sampling beyond the frame's wall reach (``_wall_reach``): such an
exemplar must accept a larger draw of the same process without the band, and must still
reject a result whose share is really wrong.

The process: large discs (radius 10) on a jittered 30-grid, small discs (radius 2) on a
jittered 8-grid wherever they clear every large disc; the exemplar keeps only the large
discs wholly inside its 160 x 160 frame and lets small discs fill the space the others
left. Its whole frame holds about 0.05 large, its interior about 0.14.
"""

from __future__ import annotations

import numpy as np
import pytest

from strew import Arrangement, Region, Shape

from strew.metrics import fidelity

BIG, SMALL, GAP = 10.0, 2.0, 1.0
SIDE = 160.0  # the exemplar's frame: large discs at 5 and 155 (+-4) cross it, 35 ... 125 do not


def _process(rng: np.random.Generator, hi: float) -> tuple[np.ndarray, np.ndarray]:
    """Candidate large and small centres over [-25, hi + 25]^2 (small ones not yet cleared)."""
    g = np.arange(-25.0, hi + 30.0, 30.0)
    big = np.stack(np.meshgrid(g, g), -1).reshape(-1, 2) + rng.uniform(-4.0, 4.0, (len(g) ** 2, 2))
    h = np.arange(-28.0, hi + 30.0, 8.0)
    small = np.stack(np.meshgrid(h, h), -1).reshape(-1, 2) + rng.uniform(-1.0, 1.0, (len(h) ** 2, 2))
    return big, small


def _arrangement(big: np.ndarray, small: np.ndarray, region: Region) -> Arrangement:
    from scipy.spatial import cKDTree

    d, _ = cKDTree(big).query(small) if len(big) else (np.full(len(small), np.inf), None)
    small = small[d >= BIG + SMALL + GAP]  # small discs wherever they clear the large ones
    xy = np.r_[big, small]
    kind = np.r_[np.zeros(len(big), int), np.ones(len(small), int)]
    shapes = {"large": Shape.circle(BIG), "small": Shape.circle(SMALL)}
    return Arrangement(shapes, kind, xy[:, 0], xy[:, 1], region=region)


def _inside(xy: np.ndarray, r: float, lo: float, hi: float) -> np.ndarray:
    return np.all((xy - r >= lo) & (xy + r <= hi), axis=1)


def banded_exemplar(seed: int = 1, side: float = SIDE) -> Arrangement:
    """Large discs kept wholly inside the frame; small ones fill the band they leave."""
    big, small = _process(np.random.default_rng(seed), side)
    big = big[_inside(big, BIG, 0.0, side)]
    small = small[_inside(small, SMALL, 0.0, side)]
    return _arrangement(big, small, Region.rectangle(side, side))


def stationary_draw(seed: int = 2, side: float = 600.0, thin: float = 0.0) -> Arrangement:
    """A larger draw of the same process without a band (a crop by centre); ``thin``: share
    of the large discs replaced by small ones (a genuinely wrong share)."""
    rng = np.random.default_rng(seed)
    big, small = _process(rng, side)
    if thin:
        big = big[rng.random(len(big)) >= thin]
    arr = _arrangement(big, small, Region.rectangle(side, side))
    return arr.select(np.all((arr.xy >= 0) & (arr.xy < side), axis=1))


def _shares(arr: Arrangement) -> float:
    return float(np.mean(np.asarray(arr.kind) == 0))


def test_banded_exemplar_is_banded():
    """The construction does what the test needs: the frame under-counts large discs."""
    ex, res = banded_exemplar(), stationary_draw()
    assert _shares(ex) < _shares(res) - 0.08
    core = np.all((ex.xy >= 2 * BIG) & (ex.xy <= SIDE - 2 * BIG), axis=1)
    assert abs(_shares(ex.select(core)) - _shares(res)) < 0.04


@pytest.mark.parametrize("seed", [1, 3])
def test_stationary_interior_matches_banded_exemplar(seed):
    """A larger draw without the band has the exemplar's fraction and density (fails at
    d66b77e: the whole frame's shares, fraction[large] about 0.12 off)."""
    ex, res = banded_exemplar(seed), stationary_draw(seed + 1)
    rep = fidelity(ex, res, eq5=False, local=False)
    for name, m in rep.metrics.items():
        if name.startswith(("fraction", "density")):
            assert m.applicable and m.passed, (name, m.value, m.tolerance, m.exemplar, m.result)
    assert rep.info["exemplar_wall_reach"] == pytest.approx(2 * BIG, rel=0.05)


def test_wrong_share_still_fails():
    """Half the large discs replaced by small ones: fraction and density still fail."""
    ex, res = banded_exemplar(), stationary_draw(thin=0.5)
    rep = fidelity(ex, res, eq5=False, local=False)
    assert not rep.faithful
    assert not rep.metrics["fraction[large]"].passed
    assert not rep.metrics["density[large]"].passed


def test_crop_and_single_kind_have_no_wall():
    """A crop (elements cross the frame) and one kind alone: no wall, every element counts."""
    rep = fidelity(stationary_draw(side=300.0), stationary_draw(seed=5), eq5=False, local=False)
    assert rep.info["exemplar_wall_reach"] == 0.0
    ex, res = banded_exemplar(), stationary_draw()
    rep = fidelity(ex.select(np.asarray(ex.kind) == 0), res.select(np.asarray(res.kind) == 0), eq5=False, local=False)
    assert rep.info["exemplar_wall_reach"] == 0.0

"""A vase panel's grid point beside its seed gets its flower (issue 19 point 4, vaf16).

§5 of Wong et al. 1998: the vine delivers the flowers to a grid fixed in the panel; the
growth starts at the seed (§4.1). A grid point within MIN_VINE of the seed can hold no vine
from the seed (too short), and a flower there from any other vine contained the seed's point
(or the seed's vine's start): at f1671ca the point stayed empty for good (untiled 225: 80
tries aimed at (5, 5), 3.5 from the seed, all hit the seed; a tiled world repeated it at every
first-phase tile whose seed lies that near a grid point). Now the seed opens that flower itself.
"""

from __future__ import annotations

import numpy as np
import pytest

import strew
from strew.ornament import grow_ornament
from strew.ornament.patterns import vase


def _flowers(arr) -> np.ndarray:
    want = [i for i, k in enumerate(arr.kinds) if k in ("lotus", "peony")]
    return np.asarray(arr.xy)[np.isin(np.asarray(arr.kind), want)]


@pytest.mark.parametrize(("side", "ij"), [(225.0, (5, 5)), (227.0, (5, 5)), (264.0, (6, 6))])
def test_grid_point_beside_the_seed_holds_a_flower(side, ij):
    # the seed (the panel's centre) lies 3.5 / 4.9 / 0 units from grid point ij
    seed = np.array([side / 2, side / 2])
    p = np.array(ij, float) * vase.GRID
    assert float(np.hypot(*(p - seed))) <= vase.MIN_VINE
    arr = grow_ornament("vase", strew.Region.rectangle(side, side), rng=1, max_elements=60)
    xy = _flowers(arr)
    d = np.hypot(*(xy - p).T)
    # a flower centred on the grid point, as every flower of the vase (f1671ca: none there)
    assert len(xy) >= 25 and float(d.min()) < 1e-9, (side, len(xy), float(d.min()))
    # and the flowers still keep apart: none overlaps another
    dd = np.hypot(*(xy[:, None] - xy[None]).transpose(2, 0, 1))
    assert float(dd[~np.eye(len(xy), dtype=bool)].min()) >= 2 * vase.FLOWER_RADIUS


def test_seed_flower_is_not_opened_far_from_the_grid():
    # a panel whose seed lies more than MIN_VINE from every grid point (200: 14.1 from the
    # nearest) opens with the seed's vine: every flower delivered by a vine
    arr = grow_ornament("vase", strew.Region.rectangle(200.0, 200.0), rng=1, max_elements=60)
    c = dict(zip(arr.kinds, np.bincount(np.asarray(arr.kind), minlength=len(arr.kinds)).tolist()))
    assert c.get("vine", 0) == c.get("lotus", 0) + c.get("peony", 0) > 0, c

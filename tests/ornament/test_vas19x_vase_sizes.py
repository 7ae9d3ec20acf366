"""A vase panel grows its flowers whatever its size (issue 19 point 4, vas19x).

The seed's goals lie beyond the vine's reach (the empty circle C touches the seed, §4.1 of
Wong et al. 1998), so the seed's vine looks for a free grid point near the chord's point
REACH - GRID out. Where the panel's centre (the seed) falls on the flowers' grid (§5: the
grid is fixed in the panel), the grid point at the seed itself was the nearest for every C,
and a vine there has no length: every try failed and the vines' phase ended with no flower.
Square panels 160..400 step 8, rng 1, at d67a7c3: 264 and 352 grew 0 flowers (308 too), the
others 15.5-19.9 per 10^4 area units. The whole vines' phase per size (flowers against the
grid points that hold one) is benchmarks/vas19x_sizes.py's, too slow for a test.
"""

from __future__ import annotations

import numpy as np
import pytest

import strew
from strew.ornament import grow_ornament
from strew.ornament.patterns import vase


def _counts(side: float, **kw) -> dict:
    arr = grow_ornament("vase", strew.Region.rectangle(side, side), rng=1, **kw)
    return dict(zip(arr.kinds, np.bincount(np.asarray(arr.kind), minlength=len(arr.kinds)).tolist()))


@pytest.mark.parametrize("side", [200.0, 232.0, 264.0, 300.0, 308.0, 352.0])
def test_vase_panel_opens_with_vines_and_flowers(side):
    # the vines' phase comes first: its first 100 elements are vines, each delivering a
    # flower, in every panel (d67a7c3: 264, 308 and 352, whose centre lies on the grid,
    # grow 0 flowers and 50 hooks with their teardrops)
    c = _counts(side, max_elements=100)
    flowers = c.get("lotus", 0) + c.get("peony", 0)
    # vaf16: where a grid point lies within MIN_VINE of the seed (the panel's centre: 264,
    # 300, 308, 352), the seed opens that flower itself, with no vine; every other flower is
    # delivered by a vine
    g = np.round(side / 2 / vase.GRID) * vase.GRID
    at_seed = int(float(np.hypot(g - side / 2, g - side / 2)) <= vase.MIN_VINE)
    assert flowers >= 45 and c.get("vine", 0) == flowers - at_seed, (side, c)


def test_free_grid_point_skips_the_vines_start():
    class _Ctx:
        def __init__(self):
            self.state = type("State", (), {})()
            self.state.flowers = []

    start = np.array([6 * vase.GRID, 6 * vase.GRID])
    # the seed's chord point REACH - GRID towards a far C down-left
    near = start + (vase.REACH - vase.GRID) * np.array([-0.70, -0.71])
    found = vase._free_grid_point(_Ctx(), near, start)
    assert found is not None
    d = float(np.hypot(*(found[2] - start)))
    assert vase.MIN_VINE < d <= vase.REACH, (found, d)

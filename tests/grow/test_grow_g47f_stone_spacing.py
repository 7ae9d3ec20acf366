"""Issue 14 point 1 (helper g47f): with two sizes, the large kind keeps the reference's
least distance to its own kind (``_Grower.pair_close``, ``OWN_TAIL_Q``).

``--varied`` EDGE two_sizes p2 (grit between stones: ratio 0.15, 50 large : 500 small),
exemplar drawn with seed 33 (stop 59's fresh draw): the stones are thrown to saturation,
their nearest-stone distances pile up at the least one (25.8; 10th percentile 28.1,
median 29.7). ``pair_close`` let a stone come the median's excess (3.9) below the least
distance, to 21.9, and the growth put 16-17 % of the stones under 0.95 of it:
nn[stone>stone] 0.314 / 0.26 at 3.5x (2/6 seeds on main), 0.27 / 0.28 at 2x (seeds 1,
2). With the spread of the lowest tail (2.3; 0.05 of the least distance at least) 1-5 %
of the stones are under 0.95 of it, nn[stone>stone] 0.16-0.17 at 2x, 6/6 seeds at 3.5x.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2])
def test_stones_keep_their_least_distance(seed):
    ex = fidelity_suite().make_exemplar("two_sizes", rng=33, ratio=0.15, n_large=50, n_small=500)
    stone = ex.kinds.index("stone")
    d = cKDTree(ex.xy[ex.kind == stone]).query(ex.xy[ex.kind == stone], k=2)[0][:, 1]
    least = float(d.min())
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0)), rng=seed)
    p = out.xy[out.kind == stone]
    d = cKDTree(p).query(p, k=2)[0][:, 1]
    d = d[d <= np.asarray(out.region.distance_to_boundary(p))]  # the judge's edge rule
    assert len(d) >= 100
    assert np.mean(d < 0.95 * least) < 0.08  # main: 0.167 / 0.156
    rep = fidelity(ex, out, eq5=False, local=False)
    nn = rep.metrics["nn[stone>stone]"]
    assert nn.value < 0.75 * nn.tolerance  # main: 0.270 / 0.266 against 0.281
    assert rep.faithful

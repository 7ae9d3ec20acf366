"""Issue 14 point 1 on untuned exemplars (helper gh0): three sizes 300:20:10
(``--harder`` three_sizes h0, exemplar drawn with seed 13).

The smallest kind kept the reference's least gap between bounding discs from itself only
where a larger kind's hollows could hold it across (grit: ``GAP_SMALLEST``). Drawn three
sizes keep a gap between every two discs; grown, 28 % of the small stones had their
nearest small one nearer than the reference ever has one (disc gaps down to -1.4 against
1.2), every decile of the nearest-small distances short (nn[small>small] 0.051-0.058
against 0.051-0.055 on seeds 1-3 of the audit's row). With three size levels or more the
smallest kind keeps ``GAP_SMALLEST`` of that gap from itself, grit or not.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow


def _small_disc_gaps(arr):
    """Each small stone's gap (bounding disc to bounding disc) to its nearest small one."""
    k = arr.kinds.index("small")
    sel = arr.kind == k
    r = float(arr.shapes["small"].radius) * np.abs(arr.scale[sel])
    xy = arr.xy[sel]
    d, j = cKDTree(xy).query(xy, k=2)
    return d[:, 1] - r - r[j[:, 1]]


def test_small_stones_keep_their_gap_among_three_sizes():
    ex = fidelity_suite().make_exemplar("three_sizes", rng=13, counts=(300, 20, 10))
    least = float(_small_disc_gaps(ex).min())
    assert least > 0  # drawn apart
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1)
    g = _small_disc_gaps(out)
    assert len(g) > 500
    # share of small stones with a small one nearer than half / all of the exemplar's
    # least gap: main 0.124 / 0.242; with the rule 0.000 / 0.127 (the placement keeps half
    # the gap; the relaxation may move a few a little nearer)
    assert float(np.mean(g < 0.5 * least)) <= 0.02
    assert float(np.mean(g < least)) <= 0.18

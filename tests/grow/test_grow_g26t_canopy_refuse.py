"""Issue 14 point 1 (helper g26t): a seed of a smaller kind whose conversion to the largest
kind (the canopy, ``_Place.try_larger``) the placement checks refused, where no large
element lies within the reference's reach (``reach_larger``), dies instead of being placed
as its own kind (``GrowParams.canopy_refuse``).

Three sizes 80:20:30 at size 150 (``--harder`` three_sizes h6, variant 13): the holes of the
large stones' lattice were filled with small stones before any large seed came, and a large
one no longer fitted there (``too_close_in_kind``): 103 of 818 small stones lay beyond the
reference's reach of every large one (the reference has none), 97 of them from refused
conversions, and nn[small>large] failed (0.0968 against 0.0607). Refused, the small seed
leaves the hole open and a later seed there becomes the large stone.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite, grow_keeping_grower

from strew import Region
from strew.metrics import fidelity


def test_small_seed_beyond_reach_of_large_dies_when_its_conversion_is_refused():
    ex = fidelity_suite().make_exemplar(
        "three_sizes", rng=13, size=150.0, counts=(80, 20, 30)
    )
    x0, y0, x1, y1 = ex.region.bounds
    W, H = 3.5 * (x1 - x0), 3.5 * (y1 - y0)
    out, g = grow_keeping_grower(ex, region=Region.rectangle(W, H), rng=1)
    names = list(ex.kinds)
    large, small = names.index("large"), names.index("small")
    kn = np.asarray(out.kind_names)
    xy = np.c_[out.x, out.y]
    r = float(g.reach_larger[small, large])
    sm = xy[kn == "small"]
    d = cKDTree(xy[kn == "large"]).query(sm)[0]
    edge = np.minimum.reduce([sm[:, 0], W - sm[:, 0], sm[:, 1], H - sm[:, 1]])
    inner = edge > r
    far = float(np.mean(d[inner] > r))
    # main (e80e8af): 0.144 of the interior small stones beyond reach of every large one
    assert far < 0.05, far
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["nn[small>large]"]
    assert m.passed, (m.value, m.tolerance)

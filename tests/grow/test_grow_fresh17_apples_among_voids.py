"""Sparse apples among fine voids keep their own distance (issue 14 point 1, held-out
exemplars: ``grow_variants.py --varied-variants 9,10``, sparse_voids p2s9 and p2s10
failed nn[apple>apple] on every seed, 0.056-0.082 against 0.05).

Apples drawn as saturated discs (spread 3.6-4.9 % of their median distance) among voids
whose rings' edges are shorter than the apples' least distance (1.14 l): the one-kind
distance rule (``_Grower.pair_close``) took them for a lattice, and apples came to half
the exemplar's least distance.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def _apple_nn(arr):
    a = arr.xy[arr.kind == arr.kinds.index("apple")]
    return cKDTree(a).query(a, 2)[0][:, 1]


def test_crowded_apples_among_voids_keep_their_distance():
    # the audit's EDGE set "crowded apples, small voids" drawn at variant seed 9
    ex = fidelity_suite().make_exemplar("sparse_voids", rng=9, spacing=18.0, apple=5.5, void=3.0, void_spacing=8.0)
    least = float(_apple_nn(ex).min())
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0))
    out = grow(ex, region=region, rng=1)
    assert len(out) >= 3 * len(ex)
    d = _apple_nn(out)
    # placement keeps apples at 0.95 of the exemplar's least distance (less its spread);
    # relaxation (§5.5) may move a few a little. At a07028f: 10 % quantile 0.80 of the
    # least distance, unrelaxed least 0.60, nn[apple>apple] 0.051 against 0.050; now
    # 0.99, 0.96 and 0.009
    assert np.quantile(d, 0.1) >= 0.93 * least, (np.quantile(d, 0.1), least)
    unrelaxed = grow(ex, region=region, rng=1, relax=False)
    assert _apple_nn(unrelaxed).min() >= 0.9 * least
    m = fidelity(ex, out, eq5=False, local=False).metrics["nn[apple>apple]"]
    assert m.passed, m

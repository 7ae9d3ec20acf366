"""Elements keep the reference's gaps between kinds (issue 14 point 1, untuned
exemplars: sparse stones, apples among voids).

§5.2's collision test is per element; grow extends it per pair of kinds
(``_Grower._pair_gaps``): where the kinds are of about one size, outlines keep the
reference's least outline gap between their two kinds, and a void element keeps the
least gap between bounding discs from a visible one.
"""

from __future__ import annotations

import numpy as np
import shapely
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import analyze, default_priority, grow
from strew.metrics import fidelity, overlaps


def _grow(ex, side, rng):
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(side * (x1 - x0), side * (y1 - y0))
    return grow(ex, region=region, rng=rng), region


def _least_outline_gap(arr, ka, kb):
    """The smallest outline distance from an element of kind ``ka`` to one of ``kb``."""
    G = np.asarray(arr.geometry, dtype=object)
    a = np.flatnonzero(arr.kind == arr.kinds.index(ka))
    b = np.flatnonzero(arr.kind == arr.kinds.index(kb))
    _, d = shapely.STRtree(G[b]).query_nearest(G[a], return_distance=True, exclusive=True, all_matches=False)
    return float(d.min())


def test_sparse_stones_keep_the_reference_outline_gap():
    # stones: sparse small stones drawn with a gap of 4 (an EDGE set of the audit, p2s7):
    # the reference keeps 5.3 units between any two outlines; grow let two come to 2.1
    ex = fidelity_suite().make_exemplar("stones", rng=7, radius=4.0, count=60, gap=4.0)
    out, region = _grow(ex, 2.0, 1)
    assert len(out) >= 3 * len(ex)
    least = _least_outline_gap(ex, "stone", "stone")
    assert least > 1.0
    assert _least_outline_gap(out, "stone", "stone") >= 0.9 * least * (1 - 1e-9)
    assert len(overlaps(out)[0]) == 0
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))


def test_sparse_stones_are_faithful():
    # the same exemplar at the audit's 3.5x: density[stone] 0.259 against a tolerance of
    # 0.247 on seed 1 before the per-pair gap
    ex = fidelity_suite().make_exemplar("stones", rng=7, radius=4.0, count=60, gap=4.0)
    out, _ = _grow(ex, 3.5, 1)
    assert len(out) >= 10 * len(ex)
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, [k for k, m in rep.metrics.items() if m.applicable and not m.passed]


def test_voids_rank_below_visible_kinds():
    # apples and voids of about one size: size_priority ranks them alike (no priority);
    # the default ranks the voids (synth's §5.6 convention) below the apples
    ex = fidelity_suite().make_exemplar("sparse_voids", rng=2)
    prio = default_priority(analyze(ex))
    assert prio["apple"] > prio["void"]


def test_voids_keep_their_distance_from_apples():
    # the reference never has a void nearer an apple than 20.5 (centres); grow put voids
    # 9 units from apples, where the reference would have had an apple
    ex = fidelity_suite().make_exemplar("sparse_voids", rng=2)
    out, _ = _grow(ex, 2.0, 1)
    assert len(out) >= 2.5 * len(ex)

    def least(arr):
        a = arr.xy[arr.kind == arr.kinds.index("apple")]
        v = arr.xy[arr.kind == arr.kinds.index("void")]
        return float(cKDTree(a).query(v)[0].min())

    assert least(out) >= 0.9 * least(ex)

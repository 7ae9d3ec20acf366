"""Issue 14 point 1: an unsaturated exemplar keeps its spacing (helper g34d).

Sparse small stones dart-thrown to a fixed count (``_variants.EDGE`` stones p2: radius
4, gap 4, 60 stones in 200 x 200, variant seed 23) leave a third of their interior
where one more stone would fit. §5.4 merges a new seed only within ``l_short`` and
matches it against its connected neighbours alone, so ring slots landed in the empty
parts of other elements' rings: grow came 22-38 % denser than the exemplar
(empty_circle 0.158 against 0.149 at 3.5x). Where the exemplar leaves such room
(:func:`strew.grow._spacing.free_share`), an element is not placed nearer a placed one
than 0.85 (``KEEP_SHARE``) of the larger of their reference elements' nearest distances.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.grow._spacing import FREE_MIN, KEEP_SHARE, free_share
from strew.metrics import summary

make_exemplar = fidelity_suite().make_exemplar


def _sparse_stones():
    ex = make_exemplar("stones", rng=23, radius=4.0, count=60, gap=4.0)
    x0, y0, x1, y1 = ex.region.bounds
    return ex, 2.0 * (x1 - x0), 2.0 * (y1 - y0)


def test_sparse_stones_keep_the_exemplars_density():
    ex, w, h = _sparse_stones()
    assert free_share(ex) >= FREE_MIN
    out = grow(ex, region=Region.rectangle(w, h), rng=1)
    assert summary(out)["overlap_pairs"] == 0
    x0, y0, x1, y1 = ex.region.bounds
    ratio = (len(out) / (w * h)) / (len(ex) / ((x1 - x0) * (y1 - y0)))
    # the region is still filled (not thinned to holes), near the exemplar's density
    # (1.15 here; without the rule 1.29-1.32 at seeds 1-3)
    assert 0.85 <= ratio <= 1.2, ratio


def test_sparse_stones_placed_at_their_references_nearest_distance():
    # placement alone (no relaxation, §5.5, to move elements after it): no pair nearer
    # than KEEP_SHARE of the larger of their two reference elements' nearest distances (the sub id
    # is the reference element)
    ex, w, h = _sparse_stones()
    out = grow(ex, region=Region.rectangle(w, h), rng=2, relax=False)
    assert len(out) >= 0.85 * len(ex) * (w * h) / 200.0**2
    enn = cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]
    sub = np.asarray(out.columns["sub_id"], dtype=int)
    d, q = cKDTree(out.xy).query(out.xy, k=2)
    need = np.maximum(enn[sub], enn[sub[q[:, 1]]])
    assert np.all(d[:, 1] >= KEEP_SHARE * need * (1 - 1e-9)), float(np.mean(d[:, 1] < KEEP_SHARE * need))


def test_saturated_stones_are_not_gated():
    # the default stones are a dart throw run until almost nothing fits: no room
    ex = make_exemplar("stones", rng=23)
    assert free_share(ex) < FREE_MIN

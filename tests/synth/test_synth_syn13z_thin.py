"""Issue 13 point 1 (helper syn13z): a one-kind exemplar whose scales vary keeps its
scale mix and density; the surplus of small stones growth crowded in is taken out
(``_thin.thin_small``)."""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize


def _density(arr, margin: float) -> float:
    """Elements per unit area at least ``margin`` inside the frame."""
    xy = np.asarray(arr.xy)
    x0, y0, x1, y1 = arr.region.bounds
    inn = (xy[:, 0] > x0 + margin) & (xy[:, 0] < x1 - margin) & (xy[:, 1] > y0 + margin) & (xy[:, 1] < y1 - margin)
    return float(inn.sum()) / ((x1 - x0 - 2 * margin) * (y1 - y0 - 2 * margin))


def test_one_kind_keeps_its_density():
    # stones, 120 asked with scales 1 +- 0.35, variant seed 7 (grow_variants.HARDER
    # ["stones"][2], --harder h2s7): copies' smaller stones fit where their larger ones
    # overlap, the output's scales drift small and it packs denser (density 1.08-1.11 of
    # the exemplar's at 3.5x, seeds 2 and 4 failed). Stones per area away from the
    # frame, output / exemplar, at 1.5x seed 1: d6d394e 1.074 (fails), now 1.026.
    ex = fidelity_suite().make_exemplar("stones", rng=7, count=120, spread=0.35)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(1.5 * (x1 - x0), 1.5 * (y1 - y0)), rng=1, measure=False)
    ratio = _density(out, 20.0) / _density(ex, 20.0)
    assert ratio <= 1.05, ratio

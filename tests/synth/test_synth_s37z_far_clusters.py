"""Far-apart clusters whose discs' neighbourhoods hold no other disc (helper s37z,
issue 13 point 1): ``benchmarks/synth_variants.py --varied`` clusters p2s27 and p2s28
(discs 90 apart in a 300 x 300 frame, full rings of six or seven dots). The disc
r-bar is capped at the depth of the deepest disc (``_palette.element_parameters``),
below the next disc, and synthesis stopped after the seed patch: 7 elements. With
``_prepare._far_hubs`` every element sees the next disc and growth crosses the gaps.
See ``_prepare.anchor_reach``."""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.metrics import overlaps
from strew.synth import synthesize

suite = fidelity_suite()

FAR_CLUSTERS = {"cluster_spacing": 90.0, "ring_gap": 3.0, "ring_min": 6, "ring_max": 7}


def _far(variant):
    ex = suite.make_exemplar("clusters", rng=variant, **FAR_CLUSTERS)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    return ex, out


@pytest.mark.parametrize("variant", [27, 28])
def test_far_clusters_grow_past_the_seed_patch(variant):
    ex, out = _far(variant)
    # 4x the exemplar's area: about 4x its count (main: the seed patch alone, 7 elements)
    assert len(out) >= 3 * len(ex)
    assert np.sum(out.kind == out.kinds.index("disc")) >= 3 * np.sum(ex.kind == ex.kinds.index("disc"))
    assert len(overlaps(out)[0]) == 0


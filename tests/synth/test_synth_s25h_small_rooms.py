"""Issue 13 point 1 (helper s25h): a three sizes exemplar whose small stones leave room
(rooms for one more over their count above ``_grow.ROOM_SHARE``) still has its small
stones brought to their density by ``fill_room`` (``_grow.ROOM_SHARE_SMALLEST``).

--harder h2s15 (60:30:40, the exemplar's rooms for a small stone 0.57 of its count):
fill_room left small out, and synth placed 568 small stones at 3.5x side where the
generator drawn at that size has 735; nn[small>small] 0.293 against 0.259."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize
from strew.synth._api import as_selection
from strew.synth._displace import _inner_density
from strew.synth._prepare import prepare


@pytest.mark.parametrize(("counts", "variant"), [((60, 30, 40), 15), ((30, 60, 60), 16)])
def test_small_stones_reach_their_density_where_the_exemplar_leaves_room(counts, variant):
    # 2x the exemplar's side, seed 1; each kind per area away from the edge (two of the
    # largest collision radii) over its exemplar's. Main: small 0.881 / 0.829; here
    # 0.936 / 0.917 (medium and large unchanged: 0.982, 1.023 / 1.178, 0.923).
    ex = fidelity_suite().make_exemplar("three_sizes", rng=variant, counts=counts)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    assert list(out.kinds) == ["small", "medium", "large"]
    prep = prepare(as_selection(ex, None))
    margin = 2.0 * float(prep.rc.max())
    inner = out.region.geometry.buffer(-margin)
    ins = shapely.contains_xy(inner, out.xy[:, 0], out.xy[:, 1])
    ratio = np.bincount(out.kind[ins], minlength=3) / inner.area / _inner_density(prep, margin)
    # the fill is capped at the exemplar's density (_room_cap): no overshoot
    assert 0.9 <= ratio[0] <= 1.05, ratio

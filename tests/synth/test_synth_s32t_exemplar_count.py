"""Helper s32t: sticks' shape-measured neighbour limits (issue 13) are counted on the
exemplar by the compiled loop (``_kernels.shape_counts``), and the share of each
element's reach zone inside the domain is measured by shapely only near the domain's
edge. The limits must be exactly the definition's: the number of the exemplar's other
shapes within the element's reach (shapely distance), over the share of its shape's
reach zone (buffer) inside the domain, rounded; no limit under half a share.
"""

import numpy as np
import pytest
import shapely
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import _grow, new_state
from strew.synth._shapes import element_geometries

suite = fidelity_suite()


@pytest.mark.parametrize("name, variation", [("sticks", {}), ("scales", {})])
def test_exemplar_shape_limits_are_the_shapely_definition(name, variation):
    ex = suite.make_exemplar(name, np.random.default_rng(3), **variation)
    prep = new_state(ex, Region.rectangle(40, 40), rng=1).prep
    lim, reach = _grow.shape_limits(prep)
    ids = np.flatnonzero(prep.source == 0)
    dom = prep.domains[0]
    g = element_geometries(prep, ids, prep.pos[ids])
    d = shapely.distance(g[:, None], g[None, :])
    np.fill_diagonal(d, np.inf)  # an element is not its own neighbour
    cnt = np.count_nonzero(d <= reach[ids][:, None], axis=1)
    zone = shapely.buffer(g, reach[ids], quad_segs=8)
    share = shapely.area(shapely.intersection(zone, dom)) / shapely.area(zone)
    want = np.where(share >= 0.5, np.round(cnt / np.maximum(share, 0.5)), -1).astype(np.int64)
    assert (share < 0.999).sum() >= 5 and (share > 0.999).sum() >= 5  # elements at the domain's edge and inside
    assert len(np.unique(want[want >= 0])) > 3
    np.testing.assert_array_equal(lim[ids], want)

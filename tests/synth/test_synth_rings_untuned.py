"""Issue 13 point 1 on untuned exemplars (benchmarks/_variants.py EDGE sets): rings of
six tiles whose r-bar (3a) reached the next hub kept ring-sized holes where growth
fronts met, and stripes of dots and long bars, split into two size classes by the
bars' bounding radius, lost their dot bands to the bars. See
``_palette._below_anchor_spacing`` and ``_prepare.size_classes``."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import fidelity
from strew.synth import new_state, synthesize
from strew.synth._palette import ANCHOR_REACH, RING_FACTOR, average_spacing, element_parameters

from strew_testing import fidelity_suite

suite = fidelity_suite()

SMALL_RINGS = dict(tiles=6, radius=11.0, hub=4.0, spacing=32.0)  # EDGE["rings"][1]
LONG_BARS = dict(band=45.0, angle=1.4, dot=2.5, bar=(12.0, 2.5))  # EDGE["stripes"][1]


def _hub_spacing(ex):
    hubs = ex.xy[np.asarray(ex.kind) == ex.kinds.index("hub")]
    d, _ = cKDTree(hubs).query(hubs, k=2)
    return float(d[:, 1].min())


def test_rbar_stays_below_the_hubs_spacing():
    """Small rings: r-bar is cut below the hubs' closest approach; the default rings
    (hubs farther apart than 3a) keep the paper's 3a."""
    ex = suite.make_exemplar("rings", rng=8, **SMALL_RINGS)
    _, rbar = element_parameters(ex)
    assert RING_FACTOR * average_spacing(ex.xy) > _hub_spacing(ex)  # the case: 3a reaches the next hub
    assert np.all(rbar <= ANCHOR_REACH * _hub_spacing(ex) + 1e-9)
    default = suite.make_exemplar("rings")
    _, rbar0 = element_parameters(default)
    np.testing.assert_allclose(rbar0, RING_FACTOR * average_spacing(default.xy))


def test_rbar_column_still_wins():
    ex = suite.make_exemplar("rings", rng=8, **SMALL_RINGS)
    ex = ex.with_columns(neighborhood_radius=np.full(len(ex), 40.0))
    _, rbar = element_parameters(ex)
    assert np.all(rbar == 40.0)


@pytest.mark.slow
def test_long_bars_share_the_dots_size_class():
    """Bars 12 x 2.5 (bounding radius 6.1, about 2.5 times the dots') are of the dots'
    size; three sizes keep their three classes."""
    ex = suite.make_exemplar("stripes", rng=8, **LONG_BARS)
    prep = new_state(ex, Region.rectangle(100, 100), rng=1).prep
    assert len(np.unique(prep.size_class)) == 1
    prep3 = new_state(suite.make_exemplar("three_sizes"), Region.rectangle(100, 100), rng=1).prep
    assert len(np.unique(prep3.size_class)) == 3


@pytest.mark.slow
@pytest.mark.parametrize("name, params, variant, seed", [("rings", SMALL_RINGS, 8, 2), ("stripes", LONG_BARS, 8, 1)])
def test_untuned_edge_exemplar_is_faithful(name, params, variant, seed):
    """At 3.5 times the frame's side (about 12x the area), as benchmarks/synth_variants.py.
    On 82a4322: rings empty_circle 0.48 (tol 0.1), density[tile] and [hub] 0.12;
    stripes fraction[dot] 0.185 (tol 0.143), density[dot] 0.40, nn[dot>dot]."""
    ex = suite.make_exemplar(name, rng=variant, **params)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
    rep = fidelity(ex, out)
    assert rep.faithful, [row for row in rep.table() if row[-1] == "FAIL"]

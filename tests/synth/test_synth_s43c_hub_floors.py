"""Issue 13 point 1 (helper s43c): far-apart clusters' discs are far hubs
(``_prepare._far_hubs``) whose copies growth keeps no closer to their k nearest output
discs than the exemplar's most crowded disc (``_grow.hub_floors``). Before, copies
from several sides put discs at the exemplar's closest disc distance all round:
``synth_variants.py --varied`` clusters p2s27 seed 1 held 116 discs in 1050 x 1050
(9,500 per disc against the exemplar's 11,250) and failed g[disc,dot]."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import new_state, synthesize

suite = fidelity_suite()

# benchmarks/_variants.py EDGE["clusters"][0] (far apart, full rings)
FAR = {"cluster_spacing": 90.0, "ring_gap": 3.0, "ring_min": 6, "ring_max": 7}


def _discs(arr):
    return arr.xy[np.asarray(arr.kind_names) == "disc"]


def test_hub_floors_are_the_exemplars_least_kth_disc_distances():
    """The floors sit on the discs only, and are the least 1st, 2nd and 3rd nearest
    disc distances of the exemplar; a one-kind exemplar gets none."""
    from strew.synth._grow import HUB_FLOOR_K, hub_floors

    ex = suite.make_exemplar("clusters", rng=27, **FAR)
    prep = new_state(ex, Region.rectangle(100, 100), rng=1).prep
    fl = hub_floors(prep)
    disc = prep.kind == prep.kind[np.flatnonzero(prep.size_class == prep.size_class.max())[0]]
    assert np.all(fl[disc, 0] > 0) and np.all(fl[~disc] == 0)
    d, _ = cKDTree(prep.pos[disc]).query(prep.pos[disc], k=HUB_FLOOR_K + 1)
    assert np.allclose(fl[disc][0], d[:, 1:].min(axis=0))
    stones = suite.make_exemplar("stones", rng=1)
    assert not hub_floors(new_state(stones, Region.rectangle(100, 100), rng=1).prep).any()


def test_far_clusters_keep_the_exemplars_disc_density():
    """3.5 times the frame's side, seed 1: the output's area per disc lies within 10 %
    of the exemplar's (0.84 of it before the floors), and the output is faithful."""
    from strew.metrics import fidelity

    ex = suite.make_exemplar("clusters", rng=27, **FAR)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1, measure=False)
    per_out = (3.5 * (x1 - x0)) * (3.5 * (y1 - y0)) / len(_discs(out))
    per_ex = (x1 - x0) * (y1 - y0) / len(_discs(ex))
    assert abs(per_out / per_ex - 1.0) < 0.10
    assert fidelity(ex, out, eq5=False, local=False).faithful

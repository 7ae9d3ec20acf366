"""Issue 13 point 1 (helper s26r): large rings of many tiles (fourteen, radius 20, hubs 52
apart; ``benchmarks/synth_variants.py --varied-variants 17,18`` rings p2s18). A fill put the
exemplar's central element (a hub 12.6 from its domain's centre) at the region's centre, and
the hub lattice grown on from it stood half a step off the exemplar's against the region's
edges: hubs fell just outside, their rings stayed as half rings with no hub, and
g[tile,hub] missed (0.206-0.210 against 0.179). The seed patch now keeps the central
element's offset from the domain's centre (``_grow._lattice_phase``)."""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize

suite = fidelity_suite()

LARGE_RINGS = {"tiles": 14, "radius": 20.0, "hub": 8.0, "spacing": 52.0}


def _edge_gaps(arr):
    """Distance from each side of the frame (left, right, bottom, top) to its nearest hub."""
    hub = arr.xy[arr.kind == arr.kinds.index("hub")]
    x0, y0, x1, y1 = arr.region.bounds
    return np.array([hub[:, 0].min() - x0, x1 - hub[:, 0].max(), hub[:, 1].min() - y0, y1 - hub[:, 1].max()])


def test_large_rings_meet_the_region_edges_as_the_exemplar_does():
    ex = suite.make_exemplar("rings", rng=18, **LARGE_RINGS)
    x0, y0, x1, y1 = ex.region.bounds
    # 2.5x the sides: the frame grows by whole lattice steps (3 rows, 6 half spacings) each side
    out = synthesize(ex, Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0)), rng=1)
    gap_ex, gap_out = _edge_gaps(ex), _edge_gaps(out)
    assert np.all(gap_ex < 24.0)  # the exemplar's hubs come within half a ring of each side
    # main: 25.7-27.7 from the left and right sides (a hub site on each side fell outside)
    assert np.all(np.abs(gap_out - gap_ex) < 0.1 * LARGE_RINGS["spacing"]), (gap_ex, gap_out)

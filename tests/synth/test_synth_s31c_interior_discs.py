"""Issue 13 point 1, clusters of large discs with full rings far apart (the audit's EDGE
set p4, fresh draw 22): a larger size class with fewer than k interior members (whole
neighbourhoods) gets its deepest members down to ``_prepare.SURROUND_DEPTH`` as
candidates too (``_prepare._surround_steps``). One interior disc, the exemplar's sparsest
(its nearest disc 1.22 cluster spacings away, the exemplar's median 1.08), was every
disc's only k-coherence candidate, and every copied cluster stood as far from the next:
at 3.5x the output's discs and dots were 0.84-0.87 of the exemplar's density
(``python benchmarks/s31c_where.py clusters:p4s22 1-4``)."""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize
from strew.synth._api import as_selection
from strew.synth._prepare import prepare

suite = fidelity_suite()

BIG_RINGS = {"large": 12.0, "small": 2.0, "ring_gap": 0.5, "ring_min": 7, "ring_max": 9, "cluster_spacing": 70.0}


def test_discs_have_several_candidates():
    """Every disc's k-coherence set co(e) (§5.1) holds at least three discs (before: one;
    the next discs lie 0.88 and 0.70 of their r-bar inside the frame, the fourth 0.58)."""
    ex = suite.make_exemplar("clusters", rng=22, **BIG_RINGS)
    prep = prepare(as_selection(ex), k=5)
    disc = np.flatnonzero(prep.r == prep.r.max())
    sets = prep.co[disc]
    assert np.all((sets >= 0).sum(axis=1) >= 3), sets
    assert np.all(prep.r[sets[sets >= 0]] == prep.r.max())


def test_discs_keep_their_density():
    """Twice the frame's side, seeds 1-3: the output holds at least 0.85 of the discs the
    exemplar's density gives the region (before: 0.75-0.79; after: 0.90-0.92)."""
    ex = suite.make_exemplar("clusters", rng=22, **BIG_RINGS)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0))
    want = np.count_nonzero(np.asarray(ex.kind_names) == "disc") / ex.region.area * region.area
    for seed in (1, 2, 3):
        out = synthesize(ex, region, rng=seed, measure=False)
        got = np.count_nonzero(np.asarray(out.kind_names) == "disc")
        assert got >= 0.85 * want, (seed, got, want)

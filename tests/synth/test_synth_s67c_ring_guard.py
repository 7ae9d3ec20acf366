"""Issue 13 point 1 (helper s67c): s65c's growth-time ring cap (``_prepare.ring_caps``)
caps only children whose parents hold rings. Its gates (one distance to a parent of a
larger size class, cv <= 0.05, half their kind) also pass medium stones touching large
ones: ``--harder`` three sizes h6s19 (size 150, counts 80:20:30), where 12 of 14 medium
stones were capped with one or two per large stone, and the cap cost
``test_synth_s30h_far_top.py`` (0.036 > 0.03). The guard: among the parents whose ring the
exemplar's frame leaves whole, at least ``RING_CAP_HELD`` hold two or more."""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import new_state

suite = fidelity_suite()


def _prep(cls, v, **kw):
    return new_state(suite.make_exemplar(cls, rng=v, **kw), Region.rectangle(100, 100), rng=1).prep


def test_contacts_at_one_distance_are_not_capped():
    """h6s19's medium stones pass the cap's gates (one distance, 12 of 14 of their kind)
    but most large stones hold one of them: nothing is capped, so growth skips the rule
    and the synthesis is main's."""
    from strew.synth._prepare import ring_caps, ring_groups

    prep = _prep("three_sizes", 19, size=150.0, counts=(80, 20, 30))
    gated = [g for g in ring_groups(prep) if g["gated"]]
    assert len(gated) == 1 and len(gated[0]["members"]) >= 10  # what s65c's cap took
    # one child per large stone for most of them (exemplar: 8 hold one, 2 hold two)
    kids = gated[0]["members"]
    _, cnt = np.unique(prep.parent[kids], return_counts=True)
    assert np.mean(cnt >= 2) < 0.5
    assert not ring_caps(prep)[0].any()


def test_rings_of_every_audit_size_stay_capped():
    """Clusters whose generator puts 2-3 (``--harder`` h1, the smallest rings of the
    audits' sets), 3-4 (h0: the grow set whose mean ring a frame-cropped exemplar brings
    under 3) and 7-9 dots (``--varied`` p4s38, the row the cap is for) on every disc:
    every disc whose ring the frame leaves whole holds two or more, and the dots stay capped."""
    from strew.synth._prepare import ring_caps, ring_groups

    for v, kw in ((10, {"ring_min": 2, "ring_max": 3, "cluster_spacing": 44.0}),
                  (7, {"large": 10.0, "small": 5.0, "ring_min": 3, "ring_max": 4}),
                  (38, {"large": 12.0, "small": 2.0, "ring_gap": 0.5, "ring_min": 7, "ring_max": 9, "cluster_spacing": 70.0})):
        prep = _prep("clusters", v, **kw)
        gated = [g for g in ring_groups(prep) if g["gated"]]
        assert len(gated) == 1 and gated[0]["held"] == 1.0
        capped = ring_caps(prep)[0]
        assert capped[gated[0]["members"]].all() and capped.sum() == len(gated[0]["members"])

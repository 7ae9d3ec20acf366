"""Issue 13 point 2 for clusters: a disc that ``_grow.fill_holes`` puts into a hole comes
with its ring of dots.

At 50x the exemplar's area (``python benchmarks/synth.py --seams --only clusters``), the
holes left where growth fronts meet were filled by single exemplar elements: 42 of the
47 discs so placed (seed 1) stood without a dot, and every window failing the local
fidelity map failed ``nn[disc>dot]`` (failing shares 0.083 / 0.062 / 0.021 at seeds
1-3, worst 6.5x the tolerance). A parent now comes with its children at their exemplar
offsets, or not at all.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.synth import fill, new_state
from strew.synth._grow import erase, fill_holes

from strew_testing import fidelity_suite

RING = 16.0  # a dot of the exemplar's clusters stands 12.5 (+5 %) from its disc


@pytest.mark.parametrize("seed", [1, 2])
def test_hole_filled_with_whole_clusters(seed):
    """Erase the middle of a fill, fill the holes: each disc added comes with at least
    as many dots as the fewest of an exemplar cluster's ring (4), none overlapping."""
    ex = fidelity_suite().make_exemplar("clusters")
    x0, y0, x1, y1 = ex.region.bounds
    size = 2.0 * (x1 - x0)
    st = new_state(ex, Region.rectangle(size, size), rng=seed)
    fill(st)
    erase(st, np.array([[0.5 * size, 0.5 * size]]), 0.22 * size)
    n0 = st.n
    added = fill_holes(st, since=0)
    assert added > 0, "the erased disc left no hole wider than the exemplar's largest empty circle"
    r = st.prep.r[st.src]
    disc = r == r.max()  # the large discs (radius 8; dots: 3)
    new_discs = np.flatnonzero(disc & (np.arange(st.n) >= n0))
    assert len(new_discs) > 0
    d = cKDTree(st.pos[~disc])
    counts = np.array([len(v) for v in d.query_ball_point(st.pos[new_discs], RING)])
    assert counts.min() >= 4, f"discs put into the hole with {counts.tolist()} dots within {RING}"
    # nothing added overlaps (the collision bound of SynthState.conflicts)
    for i in range(n0, st.n):
        others = np.r_[np.arange(i), np.arange(i + 1, st.n)]
        lim = np.maximum(st.prep.rc[st.src[i]] + st.prep.rc[st.src[others]], st.prep.min_dist[st.prep.skind[st.src[i]], st.prep.skind[st.src[others]]])
        assert np.all(np.hypot(*(st.pos[others] - st.pos[i]).T) >= lim - 1e-9)


@pytest.mark.slow
def test_clusters_without_seams_at_50x():
    """No failing window of the local fidelity map at 50x the exemplar's area (issue 13
    point 2; before: 12 of 144 windows failed nn[disc>dot] at seed 1, worst 6.5x), and
    no disc without a dot within RING (before: 42 of 1,050)."""
    from strew.metrics import fidelity
    from strew.synth import synthesize

    ex = fidelity_suite().make_exemplar("clusters")
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
    out = synthesize(ex, region, rng=1, measure=False)
    k = np.asarray(out.kinds, dtype=object)[np.asarray(out.kind)]
    assert (k == "disc").sum() > 500 and (k == "dot").sum() > 2000
    d, _ = cKDTree(out.xy[k == "dot"]).query(out.xy[k == "disc"])
    assert int((d > RING).sum()) == 0, f"{int((d > RING).sum())} discs without a dot within {RING}"
    rep = fidelity(ex, out, region, eq5=False)
    score = np.asarray(rep.local["score"], float)
    assert np.isfinite(score).sum() > 100
    assert rep.local["worst"]["score"] <= 1.0, rep.local["worst"]

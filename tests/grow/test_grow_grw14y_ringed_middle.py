"""Issue 14 point 1 on untuned exemplars (helper grw14y): three sizes with medium stones
the majority (``--harder`` three_sizes h1, counts 40:100:20, and h7, 20:120:20, exemplars
drawn with seed 7).

h1: 0.76 of the large stones' contacts with other kinds are medium; they grew from the
medium stones' rings and the outline test let medium stones into their bounding discs
(gaps q0/q10 -2.6/-1.1 against the reference's 1.21/1.39): nn[large>medium] 0.088-0.137
against 0.060. Medium stones now keep 0.9 of the reference's least disc gap from large
ones, and large ones stay outside the medium ones' discs (``DISC_WIDE_RINGED`` in
``grow/_growth.py``). h7: small stones left far from every medium one are moved snug
against one (``grow/_lone_smaller.py``), which adds no element.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import disc_gaps, fidelity_suite

from strew import Region
from strew.grow import grow


def test_large_stones_keep_medium_ones_off_their_discs():
    ex = fidelity_suite().make_exemplar("three_sizes", rng=7, counts=(40, 100, 20))
    radius = {k: float(ex.shapes[k].radius) for k in ex.kinds}
    least = float(disc_gaps(ex, radius, "large", "medium").min())
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(1.5 * (x1 - x0), 1.5 * (y1 - y0)), rng=1)
    gaps = disc_gaps(out, radius, "large", "medium")
    assert len(gaps) >= 30
    # lowest decile of the large stones' gaps to their nearest medium one (1.5x, seed 1)
    # against 0.8 of the exemplar's least gap (1.21): d67a7c3 -0.27, fails; now 1.08
    assert float(np.quantile(gaps, 0.1)) >= 0.8 * least


def test_lone_small_stones_move_and_none_is_added(monkeypatch):
    from strew.grow import _growth
    from strew.grow._lone_smaller import move_lone_smaller, smaller_reach
    from strew.grow._objects import ELEMENT

    seen = []

    def spy(g):
        q = smaller_reach(g)[0]
        small, medium = g.ref.exemplar.kinds.index("small"), g.ref.exemplar.kinds.index("medium")

        def state():
            els = np.asarray([i for i in g.order if g.state[i] == ELEMENT])
            k = g.kind[els]
            d = cKDTree(g.pos[els][k == medium]).query(g.pos[els][k == small])[0]
            return np.bincount(k, minlength=g.n_kinds), int(np.sum(d > q[small, medium]))

        before = state()
        made = move_lone_smaller(g)
        seen.append((made, before, state()))
        return made

    monkeypatch.setattr(_growth, "move_lone_smaller", spy)
    ex = fidelity_suite().make_exemplar("three_sizes", rng=7, counts=(20, 120, 20))
    x0, y0, x1, y1 = ex.region.bounds
    grow(ex, region=Region.rectangle(1.5 * (x1 - x0), 1.5 * (y1 - y0)), rng=1)
    made, (n0, far0), (n1, far1) = seen[0]
    assert made > 0
    # the pass moves elements and adds none
    assert n1.tolist() == n0.tolist()
    # fewer small stones beyond the reference's upper decile from every medium one
    assert far1 < far0

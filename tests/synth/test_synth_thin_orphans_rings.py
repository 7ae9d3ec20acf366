"""Issue 13 point 2: ``_thin.thin_orphans`` leaves a ring's tiles alone (seam17).

A ring's tile copied with another hub's exemplar ring keeps that hub as its exemplar
parent although it stands on this hub's ring, so by the orphan test alone it stands
"without its parent". At 50x the default rings exemplar's area every hole of seeds
1-16 came from the orphan pass taking such tiles out (``benchmarks/seam17_all50.py``).
Here a region is tiled with whole rings, every tile a copy of another hub's ring, shrunk
to 0.85 so that the tiles stand closer than the exemplar's tenth percentile and their
kind is denser than the exemplar's: exactly the orphans the pass would remove.
"""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

import strew.synth._grow as synth_grow
from strew import Region
from strew.synth import new_state
from strew.synth._grow import anchor_children
from strew.synth._thin import thin_orphans


def _rings_of_orphans():
    ex = fidelity_suite().make_exemplar("rings")
    state = new_state(ex, Region.rectangle(300.0, 300.0), rng=1)
    prep = state.prep
    _, cptr, cidx = anchor_children(prep)
    full = np.flatnonzero(np.diff(cptr) == 10)
    a, b = int(full[0]), int(full[1])  # two hubs with whole rings of ten tiles
    other = cidx[cptr[b] : cptr[b + 1]]
    off = 0.85 * (prep.pos[other] - prep.pos[b])
    step = 2.0 * float(np.max(np.hypot(*off.T))) + 2.0 * float(prep.r[other].max())
    for x in np.arange(0.5 * step, 300.0, step):
        for y in np.arange(0.5 * step, 300.0, step):
            c = np.array([x, y])
            state.add(np.array([a]), c[None])  # hub a's copy, ringed by hub b's tiles
            state.add(other, c + off)
    return state, a


@pytest.mark.slow  # about 3 s under load (the exemplar's preparation)
def test_ring_tiles_are_not_thinned_as_orphans(monkeypatch):
    state, a = _rings_of_orphans()
    n, pos = state.n, state.pos.copy()
    assert thin_orphans(state) == 0
    assert state.n == n and np.array_equal(state.pos, pos)

    # the same rings with the ring exclusion switched off: the pass would take tiles out,
    # so the rings above were real orphans in surplus, not a case the pass skips anyway
    state2, _ = _rings_of_orphans()
    real = synth_grow._ring_kids
    monkeypatch.setattr(synth_grow, "_ring_kids", lambda prep: (np.zeros(len(prep.kind), bool),) + real(prep)[1:])
    removed = thin_orphans(state2)
    assert removed > 0
    assert state2.n == n - removed

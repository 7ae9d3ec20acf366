"""Issue 13 point 2 (helper seam17): a hub's ring completed after growth
(``_grow._complete_anchor_rings``) takes the tiles left over beside its empty slots.

Default rings at 50x the exemplar's area, seed 1 (``benchmarks/seam17_all50.py``): one
ring held 9 tiles after growth, two of them copied with another hub's ring and turned
against this ring's slots (4.0 and 4.7 from the nearest slots, half the slots' spacing
4.6). The first stayed on its slot's claim but could not move past the second, which
no slot took; so the ring stayed a tile short, both kept the other hub as their
exemplar parent, and thin_orphans took them out: a ring of 7 tiles, the local map's
largest empty circle 3.6x the tolerance in four windows.
"""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import new_state
from strew.synth._grow import _complete_anchor_rings, anchor_children


def _turned(slot: np.ndarray, centre: np.ndarray, chord: float, sign: float) -> np.ndarray:
    """``slot`` turned about ``centre`` by the angle whose chord is ``chord``."""
    v = slot - centre
    a = sign * 2.0 * np.arcsin(chord / (2.0 * np.hypot(*v)))
    c, s = np.cos(a), np.sin(a)
    return centre + np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


@pytest.mark.slow  # 3.3 s under load (the exemplar's preparation)
def test_leftover_tiles_beside_empty_slots_complete_the_ring():
    ex = fidelity_suite().make_exemplar("rings")
    state = new_state(ex, Region.rectangle(300.0, 300.0), rng=1)
    prep = state.prep
    _, cptr, cidx = anchor_children(prep)
    full = np.flatnonzero(np.diff(cptr) == 10)
    a, b = int(full[0]), int(full[1])  # two hubs with whole rings of ten tiles
    kids, other = cidx[cptr[a] : cptr[a + 1]], cidx[cptr[b] : cptr[b + 1]]
    centre = np.array([150.0, 150.0])
    slots = centre + prep.pos[kids] - prep.pos[a]
    ang = np.arctan2(*(slots - centre).T[::-1])
    order = np.argsort(ang)
    kids, slots = kids[order], slots[order]
    spacing = float(np.min(np.hypot(*(slots - np.roll(slots, 1, axis=0)).T)))
    state.add(np.array([a]), centre[None])
    state.add(kids[:7], slots[:7])  # seven tiles on their slots; slots 7, 8 and 9 empty
    # two tiles of the other hub's ring, turned against this one's slots: one 4.0 past
    # slot 8 (toward 9), one midway between slots 7 and 8 (over half a spacing from both)
    t8 = min((_turned(slots[8], centre, 4.0, sg) for sg in (1.0, -1.0)), key=lambda p: float(np.hypot(*(p - slots[9]))))
    mid = 0.5 * (slots[7] + slots[8])
    mid = centre + (mid - centre) * np.hypot(*(slots[7] - centre)) / np.hypot(*(mid - centre))
    assert np.hypot(*(mid - slots[7])) > 0.5 * spacing and np.hypot(*(mid - slots[8])) > 0.5 * spacing
    state.add(other[:2], np.vstack([t8, mid]))
    _complete_anchor_rings(state)
    pos, src = state.pos, state.src
    d = np.hypot(*(pos - centre).T)
    ring = np.flatnonzero((d > 5.0) & (d < 25.0))
    # a whole ring of ten, every tile on a slot and a child of this hub's exemplar ring
    # (a07028f: nine, the two turned tiles off their slots and still the other hub's)
    assert len(ring) == 10
    assert np.all(prep.parent[src[ring]] == a)
    gap = np.min(np.hypot(pos[ring, None, 0] - slots[None, :, 0], pos[ring, None, 1] - slots[None, :, 1]), axis=1)
    assert np.all(gap < 1e-6)

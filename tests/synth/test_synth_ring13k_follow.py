"""Issue 13 point 1 (helper ring13l): a ring's hub snapped onto the hub lattice
(``_grow._snap_anchors_to_lattice``) brings the tiles copied with it (``pslot``).
Left behind, the tiles on its far side stood up to a quarter spacing beyond the ring
and stayed as orphans 25-30 from any hub (default rings at 20x the exemplar's area,
``tests/synth/test_synth_seams.py::test_rings_on_a_large_canvas_keep_hub_and_tiles``)."""

from __future__ import annotations

import numpy as np
import pytest

from strew import Region
from strew.synth import new_state
from strew.synth._grow import anchor_children, anchor_lattice, _snap_anchors_to_lattice

from strew_testing import fidelity_suite


@pytest.fixture
def lattice_on(monkeypatch):
    import strew.synth._grow as G

    monkeypatch.setattr(G, "LATTICE_CV", 0.05)


def test_snapped_hub_brings_its_tiles(lattice_on):
    ex = fidelity_suite().make_exemplar("rings")
    state = new_state(ex, Region.rectangle(400.0, 400.0), rng=1)
    prep = state.prep
    on, basis, spacing = anchor_lattice(prep)
    _, cptr, cidx = anchor_children(prep)
    ons = np.flatnonzero(on)
    a = int(ons[np.argmax(np.diff(cptr)[ons])])  # a hub with its whole ring
    kids = cidx[cptr[a] : cptr[a + 1]]
    assert len(kids) == 10 and np.isfinite(spacing)
    centre = np.array([200.0, 200.0])
    state.add(np.array([a]), centre[None])
    site = centre + basis[a][:, 0]  # one lattice step from the output hub
    # proposals: a hub 0.15 spacing off that site with its ring (pslot -> the hub),
    # a hub 0.4 spacing off another site, a tile copied without its hub (pslot -1)
    off = 0.15 * spacing * np.array([0.6, 0.8])
    hub1 = site + off
    far = centre - basis[a][:, 1] + 0.4 * spacing * np.array([1.0, 0.0])
    ex_ = np.concatenate([[a], kids, [a], [kids[0]]])
    ppos = np.vstack([hub1, hub1 + prep.pos[kids] - prep.pos[a], far, centre + [0.0, 80.0]])
    pslot = np.concatenate([[-1], np.zeros(len(kids), np.int64), [-1, -1]])
    valid = np.ones(len(ex_), bool)
    before = ppos.copy()
    _snap_anchors_to_lattice(state, ex_, ppos, valid, pslot)
    assert np.allclose(ppos[0], site, atol=1e-6)  # the hub is on its site ...
    ring = 1 + np.arange(len(kids))
    # ... and its tiles keep their places about it (they were left behind before)
    assert np.allclose(ppos[ring] - ppos[0], before[ring] - before[0], atol=1e-9)
    assert valid[: len(kids) + 1].all()
    assert not valid[len(kids) + 1]  # too far off its site: refused
    assert np.array_equal(ppos[-1], before[-1]) and valid[-1]  # no hub of its copy moved

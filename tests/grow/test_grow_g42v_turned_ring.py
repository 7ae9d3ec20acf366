"""grow's kept outlines (``_Collide.turned_ring``; issue 14 point 5, speed; byte-identical
output): the outlines ``element_geometry`` built before, with fewer products."""

from __future__ import annotations

import math

import numpy as np
import shapely


def _grower(monkeypatch, count=150):
    import strew.grow._growth as G
    from strew.grow import analyze, grow
    from strew.grow._exemplars import stone_exemplar

    grown = []
    init = G._Grower.__init__

    def keep(self, *a, **k):
        init(self, *a, **k)
        grown.append(self)

    monkeypatch.setattr(G._Grower, "__init__", keep)
    grow(analyze(stone_exemplar()), count=count, rng=1, relax=True)
    return grown[-1]


def test_turned_ring_keeps_the_outline_element_geometry_built(monkeypatch):
    """``element_geometry`` gives the coordinates the uncached product gave (exactly),
    the kept outline is read-only, and a fixed-mode growth of stones turns only as many
    outlines as there are (kind, rotation, scale) triples among its elements."""
    from strew.grow._collide import TURNED_KEEP

    g = _grower(monkeypatch)
    els = np.flatnonzero(g.state[: g.n] == 2)
    keys = {(int(g.kind[o]), float(g.rot[o]), float(g.scl[o])) for o in els.tolist()}
    assert 0 < len(g._turned) <= TURNED_KEEP
    # fixed mode: each element takes its reference's rotation and scale
    assert len(keys) <= len(g._turned) < len(els)
    rng = np.random.default_rng(5)
    for o in rng.choice(els, 40).tolist():
        kind, rot, scale = int(g.kind[o]), float(g.rot[o]), float(g.scl[o])
        for x, y in ((0.0, 0.0), (float(g.xy[o][0]), float(g.xy[o][1])), (1e3 / 7, -1e2 / 3)):
            m = np.array([[math.cos(rot) * scale, -math.sin(rot) * scale], [math.sin(rot) * scale, math.cos(rot) * scale]])
            want = g.local_ring[kind] @ m.T + np.array([x, y])
            got = shapely.get_coordinates(g.element_geometry(kind, x, y, rot, scale))
            assert np.array_equal(got, want)
        base = g.turned_ring(kind, rot, scale)
        assert not base.flags.writeable
        assert g.turned_ring(kind, rot, scale) is base
    # bounded: rotation mode turns every element its own way
    for q in range(TURNED_KEEP + 5):
        g.turned_ring(0, 1e-3 * q, 1.0)
    assert len(g._turned) <= TURNED_KEEP

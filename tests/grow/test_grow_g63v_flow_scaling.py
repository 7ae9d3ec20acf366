"""Issue 14 point 5 (helper g63v): flow mode's per-element cost that grew with the count.

Each trim of :mod:`strew.grow._flow_net`'s network passes gives the answer of what it
replaces, on every call of a hexagonal lattice grown along a field turning 90 degrees
(``benchmarks/grow.py --against``'s ``hexflow``, smaller):

- :func:`strew.grow._flow_net.placed` (the placed elements as one array) is the list
  ``[i for i in g.order if g.state[i] == ELEMENT]`` it replaces;
- :func:`strew.grow._flow_shear.fitted_moves` (which elements moved, over all at once)
  gives the moves and undo records, in the same order, that the loop over one element
  at a time gave;
- :func:`strew.grow._flow_net._place_all` (the settle steps' outlines made in one
  shapely call per kind; g60v's of stop 60) places every element where
  :func:`~strew.grow._flow_net._place` one by one does: the same positions, outlines
  (WKB), rotations and steps;
- :func:`strew.grow._flow_net.triangulation` (the last triangulation kept, for the same
  positions) gives the simplices and neighbour lists a fresh ``Delaunay`` gives, and
  is kept at least once;
- :meth:`strew.grow._collide._Collide.turned_ring` keeps as many outlines as a flow
  growth of several thousand elements turns (each its own rotation), and every kept
  outline is the product made afresh.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from strew import Region
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar


def _hexflow(W: float = 16):
    ref = analyze(hex_exemplar())
    sp = ref.mean_edge
    w = W * sp

    def field(p):
        a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]

    return grow(ref, rng=1, relax=True, region=Region.rectangle(w, W * 2 / 3 * sp), mode="flow", flow=field)


def _fitted_moves_one_at_a_time(g, els, pts, qs):
    # (the loop that fitted_moves replaced, as it was on main 67139e9a)
    moves, old = {}, {}
    tiny = 1e-9 * g.l
    for q in qs:
        o = int(els[q])
        nx, ny = float(pts[q, 0]), float(pts[q, 1])
        ox, oy = g.xy[o]
        if abs(nx - ox) + abs(ny - oy) > tiny:
            moves[o] = (nx, ny)
            old[o] = (ox, oy, g.geom[o], float(g.rot[o]))
    return moves, old


def test_network_pass_trims_answer_as_what_they_replace(monkeypatch):
    import strew.grow._flow_densify as FD
    import strew.grow._flow_net as FN
    import strew.grow._flow_shear as FS
    from strew.grow._objects import ELEMENT
    from strew.grow._flow_shear import undo_moves

    seen = {"placed": 0, "fitted": 0, "moved": 0, "place_all": 0, "settled": 0}

    real_placed = FN.placed

    def placed(g):
        got = real_placed(g)
        assert got.dtype == np.intp
        assert got.tolist() == [i for i in g.order if g.state[i] == ELEMENT]
        seen["placed"] += 1
        return got

    real_fitted = FS.fitted_moves

    def fitted(g, els, pts, qs):
        qs = list(qs)
        want = _fitted_moves_one_at_a_time(g, els, pts, qs)
        got = real_fitted(g, els, pts, qs)
        assert list(got[0].items()) == list(want[0].items())
        assert list(got[1].keys()) == list(want[1].keys())
        for o, (x, y, geom, rot) in want[1].items():
            gx, gy, ggeom, grot = got[1][o]
            assert (gx, gy, rot) == (x, y, grot) and ggeom is geom
        seen["fitted"] += 1
        seen["moved"] += len(want[0])
        return got

    real_all = FN._place_all

    def place_all(g, moves, old, level, turns=None):
        lv = dict(level)
        one = [o for o in moves if FN._place(g, o, moves, old, lv, turns)]
        want = {o: (g.xy[o], shapely.to_wkb(g.geom[o]), float(g.rot[o]), lv[o]) for o in moves}
        undo_moves(g, old)
        out = real_all(g, moves, old, level, turns)
        got = {o: (g.xy[o], shapely.to_wkb(g.geom[o]), float(g.rot[o]), level[o]) for o in moves}
        assert out == one
        assert got == want
        seen["place_all"] += 1
        seen["settled"] += len(moves)
        return out

    real_tri = FN.triangulation

    def tri(pts, g=None):
        from scipy.spatial import Delaunay

        was = FN._LAST_TRI.get(g) if g is not None else None
        got = real_tri(pts, g)
        fresh = Delaunay(pts)
        assert np.array_equal(got.simplices, fresh.simplices)
        for a, b in zip(got.vertex_neighbor_vertices, fresh.vertex_neighbor_vertices):
            assert np.array_equal(a, b)
        if was is not None and got is was[1]:
            seen["kept"] = seen.get("kept", 0) + 1
        return got

    monkeypatch.setattr(FN, "triangulation", tri)
    monkeypatch.setattr(FN, "placed", placed)
    monkeypatch.setattr(FD, "placed", placed)
    monkeypatch.setattr(FN, "fitted_moves", fitted)
    monkeypatch.setattr(FD, "fitted_moves", fitted)
    monkeypatch.setattr(FS, "fitted_moves", fitted)
    monkeypatch.setattr(FN, "_place_all", place_all)
    _hexflow()
    assert seen["placed"] > 10 and seen["fitted"] > 2 and seen["moved"] > 50 and seen["place_all"] > 2 and seen["settled"] > 50, seen
    assert seen.get("kept", 0) > 0, seen


def test_turned_ring_keeps_a_flow_growths_outlines(monkeypatch):
    """A flow growth turns each element its own way: the outlines of 3,000 rotations
    asked twice (a network pass over 3,000 elements, and the next) are kept from the
    first time to the second (1,024 were kept before: every second ask missed), and
    each is the product made afresh."""
    import strew.grow._growth as G

    grown = []
    init = G._Grower.__init__

    def keep(self, *a, **k):
        init(self, *a, **k)
        grown.append(self)

    monkeypatch.setattr(G._Grower, "__init__", keep)
    out = _hexflow(8)
    g = grown[-1]
    kind = int(g.kind[int(np.flatnonzero(g.state[: g.n] == 2)[0])])
    rots = [float(v) for v in np.random.default_rng(3).uniform(-math.pi, math.pi, 3000)]
    first = [g.turned_ring(kind, r, 1.0) for r in rots]
    again = [g.turned_ring(kind, r, 1.0) for r in rots]
    assert all(a is b for a, b in zip(first, again))
    for r, base in zip(rots[::97], first[::97]):
        m = np.array([[math.cos(r), -math.sin(r)], [math.sin(r), math.cos(r)]])
        assert np.array_equal(base, g.local_ring[kind] @ m.T)
    assert len(out) > 0

"""grow's batched overlap tests (``_Collide.overlaps_pool_many``, used by ``_nudge``, and
``_hits_any``'s overlap areas in one call): the answers of the one-by-one tests they
replaced (issue 14 point 5, speed; byte-identical output)."""

from __future__ import annotations

import numpy as np
import shapely


def _one_by_one(g, geom, kind, x, y, scale, pool):
    """``overlaps_pool`` as it was before the batching (89eb27f): the objects within the
    bounding radii, then shapely on each hit in turn."""
    kr = g.kind_radius
    rg = float(kr[kind]) * abs(scale)
    r2 = (kr[kind] * scale + g.other_rmax) ** 2
    others = []
    for j in pool:
        px, py = g.xy[j]
        d2 = (px - x) ** 2 + (py - y) ** 2
        if d2 > r2:
            continue
        if g.state[j] == 2 and g.kind[j] < len(kr):
            reach = (rg + float(kr[g.kind[j]]) * abs(float(g.scl[j]))) * (1.0 + 1e-9)
            if d2 > reach * reach:
                continue
        others.append(j)
    for j in others:
        if not shapely.intersects(geom, g.geom[j]):
            continue
        if not g.areal[kind] or not g.areal[g.kind[j]]:
            return True
        if shapely.intersection(geom, g.geom[j]).area > 1e-9 * max(geom.area, 1e-300):
            return True
    return False


def test_overlaps_pool_many_equals_the_one_by_one_tests(monkeypatch):
    """Candidate outlines about a growth of stones, in batches as ``_nudge`` makes them
    (and outlines moved to about touch a neighbour's): every answer as the one-by-one
    test gives it, both ways; also with the kinds taken as without area (any contact a
    hit, no area test)."""
    import strew.grow._growth as G
    from strew.grow import analyze, grow
    from strew.grow._exemplars import stone_exemplar
    from strew.grow._objects import ELEMENT

    grown = []
    init = G._Grower.__init__

    def keep(self, *a, **k):
        init(self, *a, **k)
        grown.append(self)

    monkeypatch.setattr(G._Grower, "__init__", keep)
    grow(analyze(stone_exemplar()), count=150, rng=1, relax=True)
    g = grown[-1]
    assert ELEMENT == 2 and g.tile is None
    els = np.flatnonzero(g.state[: g.n] == ELEMENT)
    rng = np.random.default_rng(3)
    seen = {"hit": 0, "free": 0}
    for areal_off in (False, True):
        if areal_off:
            g.areal = np.zeros_like(np.asarray(g.areal))
        for _ in range(60):
            o = int(rng.choice(els))
            kind = int(g.kind[o])
            scale = float(g.scl[o])
            rot = float(rng.uniform(0, 2 * np.pi))
            reach = float(rng.uniform(0.5, 2.0)) * g.l_short
            pool = g.overlap_pool(kind, *g.xy[o], scale, reach)
            pts, gs = [], []
            for q in range(int(rng.integers(1, 6))):
                t = rng.uniform(0, 2 * np.pi)
                d = rng.uniform(0, reach)
                x, y = g.xy[o][0] + d * np.cos(t), g.xy[o][1] + d * np.sin(t)
                pts.append((float(x), float(y)))
                gs.append(g.element_geometry(kind, float(x), float(y), rot, scale))
            # an outline moved to touch a neighbour's from outside (contact, no overlap)
            if rng.random() < 0.5:
                j = int(rng.choice(els))
                gj = g.geom[j]
                far = shapely.affinity.translate(gj, xoff=3 * g.kind_radius[int(g.kind[j])] * float(g.scl[j]))
                d = shapely.distance(far, gj)
                touch = shapely.affinity.translate(far, xoff=-d)
                c = touch.centroid
                pts.append((c.x, c.y))
                gs.append(touch)
                pool = sorted(set(pool) | {j})
            got = g.overlaps_pool_many(gs, kind, pts, scale, pool)
            for geom, (x, y), hit in zip(gs, pts, got):
                want = _one_by_one(g, geom, kind, x, y, scale, pool)
                assert hit == want
                assert hit == g.overlaps_pool(geom, kind, x, y, scale, pool)
                seen["hit" if want else "free"] += 1
    assert seen["hit"] > 40 and seen["free"] > 20, seen

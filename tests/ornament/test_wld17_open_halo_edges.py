"""A tiled world's halo edge that faces a later tile stops no circle (issue 19 point 4).

A tile grows in its rectangle widened by the halo, and Wong et al. §4.1 discard a circle
that the boundary stops before it reaches an element. Where the halo's edge lies in a
tile that runs later the world goes on, and one run would have measured the circle
against the elements alone: hierarchy's finished tiles (vines-phase circles of radius
>= 8, halo 12-17 at tiles 48-68) lost every circle centred past half the halo and
squeezed their vines into its first half (benchmarks/hie15_halo.py). strew.tiles passes
those edges (``_open_edges``) and the engine leaves them out of the boundary
(``_closed_part``); the region still bounds the circles' centres and the elements.
"""

from __future__ import annotations

import numpy as np

import strew
from strew.ornament._engine import grow_elements
from strew.tiles import _Job, _grow, _later_rects, _open_edges, plan


def _goals(orn, phase=None):
    return np.array([e.goal_circle for e in orn.elements if hasattr(e, "goal_circle") and (phase is None or e.phase == phase)])


def test_open_edge_stops_no_circle_closed_edges_do():
    reg = strew.Region.rectangle(60.0, 40.0)
    closed = grow_elements("hierarchy", reg, seeds=[[12.0, 20.0]], rng=1)
    opened = grow_elements("hierarchy", reg, seeds=[[12.0, 20.0]], rng=1, _open=[[60.0, 0.0, 60.0, 40.0]])
    tol = 1e-6
    gc, go = _goals(closed, "vines"), _goals(opened, "vines")
    # a closed panel: no vines-phase circle reaches past the right edge (§4.1)
    assert (gc[:, 0] + gc[:, 2] <= 60.0 + tol).all()
    # open on the right: circles measured against the elements reach past it
    assert (go[:, 0] + go[:, 2] > 60.0 + 1.0).sum() >= 2
    # the other edges still stop circles, and every element and centre stays inside
    allo = _goals(opened)
    assert (allo[:, 0] - allo[:, 2] >= -tol).all()
    assert (allo[:, 1] - allo[:, 2] >= -tol).all() and (allo[:, 1] + allo[:, 2] <= 40.0 + tol).all()
    assert (allo[:, 0] <= 60.0).all()
    for e in opened.elements:
        for pr in e.proxies:
            x0, y0, x1, y1 = pr.geometry.bounds
            assert x0 >= -tol and y0 >= -tol and x1 <= 60.0 + tol and y1 <= 40.0 + tol


def test_open_edges_lie_in_later_tiles_only():
    size, tile, halo = (96.0, 96.0), 24.0, 6.0
    tiles, nx, ny = plan(size, tile)
    job = _Job("ornament", "hierarchy", {}, size, halo, 1, (tile, tile), (nx, ny), False)
    for t in tiles:
        grown = _grow(t.rect, halo, size)
        segs = np.array(_open_edges(t, job, grown), float).reshape(-1, 4)
        later = _later_rects(t, job)
        if t.phase == 3:
            assert not len(segs)  # every neighbour has run: no open edge
        for x0, y0, x1, y1 in segs:
            mx, my = (x0 + x1) / 2, (y0 + y1) / 2
            # on the grown rectangle's edge, off the world's edge, inside a later tile
            assert mx in (grown[0], grown[2]) or my in (grown[1], grown[3])
            assert 0 < mx < size[0] and 0 < my < size[1]
            assert any(a <= mx <= c and b <= my <= d for a, b, c, d in later)
        # every point of the grown edge strictly inside a later tile is open
        for a, b, c, d in later:
            for px, py in ((grown[0], (b + d) / 2), (grown[2], (b + d) / 2), ((a + c) / 2, grown[1]), ((a + c) / 2, grown[3])):
                if a < px < c and b < py < d and (px in (grown[0], grown[2]) and grown[1] < py < grown[3] or py in (grown[1], grown[3]) and grown[0] < px < grown[2]):
                    assert any(min(x0, x1) <= px <= max(x0, x1) and min(y0, y1) <= py <= max(y0, y1) for x0, y0, x1, y1 in segs)

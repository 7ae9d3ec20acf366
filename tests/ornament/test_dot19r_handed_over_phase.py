"""A handed-over circle scales only the rules of the phase it was grown in (issue 19
point 4; strew.tiles._ornament_holes, strew.ornament._engine._Grower._holes_of_phase).

hierarchy grows vines, then flowers, leaves and fillers (Wong et al. §5). A finished
tile's dropped vine circles raised a later tile's leaves and fillers to a vine's scale:
the refill grew fewer, larger elements and the border strips thinned (tile 100, seed 1:
+-2 s density 0.835 against 0.996 with no hand-over).
"""

from __future__ import annotations

import numpy as np

import strew
import strew.tiles as T
from strew.ornament._engine import grow_elements

from strew_testing import TileRows


def _xy(orn):
    return [(e.type, tuple(np.round(np.concatenate([np.ravel(getattr(p, "center", getattr(p, "points", np.zeros(0)))) for p in e.proxies]), 9)))
            for e in orn.elements]


def test_a_circle_scales_only_its_own_phase():
    reg = strew.Region.rectangle(40.0, 40.0)
    seeds = [[20.0, 20.0]]
    plain = grow_elements("hierarchy", reg, seeds=seeds, rng=1)
    grid = np.arange(0.0, 41.0, 5.0)
    # circles of a phase the pattern never reaches: no rule is scaled, the same growth
    other = grow_elements("hierarchy", reg, seeds=seeds, rng=1, _holes=[[x, y, 9.0, "no such phase"] for x in grid for y in grid])
    assert _xy(other) == _xy(plain)
    # the fillers' circles: the vines, flowers and leaves grow as before, the fillers not
    fill = grow_elements("hierarchy", reg, seeds=seeds, rng=1, _holes=[[x, y, 9.0, "fillers"] for x in grid for y in grid])
    early = [p for p in _xy(plain) if p[0] != "quote"]
    assert [p for p in _xy(fill) if p[0] != "quote"][: len(early)] == early
    assert _xy(fill) != _xy(plain)


def test_finished_tile_hands_over_the_phase_of_each_circle(monkeypatch):
    import strew.ornament._context as C

    goal = np.empty(3, dtype=object)
    goal[:] = [(30.0, 50.0, 9.0), (40.0, 60.0, 3.0), (45.0, 60.0, 2.0)]
    rows = TileRows({"x": [30.0, 40.0, 45.0], "y": [50.0, 60.0, 60.0], "ornament_group": [1, 2, 3], "element": [1, 2, 3],
                     "parent": [0, 1, 2], "phase": ["vines", "fillers", ""], "ornament_proxies": [[0], [0], [0]], "ornament_goal": goal})
    tiles, nx, ny = T.plan((200.0, 200.0), 100.0)
    job = T._Job("ornament", "hierarchy", {}, (200.0, 200.0), 25.0, 1, (100.0, 100.0), (nx, ny))
    # every row a success placed at its parent (what _at_parent and parent_rows say of willow's)
    monkeypatch.setattr(T, "_at_parent", lambda arr, inv, tips: np.zeros(int(inv.max()) + 1, np.int64))
    monkeypatch.setattr(C, "parent_rows", lambda inp, proxies: np.ones(len(proxies), bool))
    got = T._ornament_holes(rows, np.zeros(3, bool), job, tiles[0].rect)
    # a row of no phase hands over (x, y, r) as before
    assert got == [[30.0, 50.0, 9.0, "vines"], [40.0, 60.0, 3.0, "fillers"], [45.0, 60.0, 2.0]]

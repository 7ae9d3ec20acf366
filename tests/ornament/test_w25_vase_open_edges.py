"""A vase tile whose halo edges are all open still delivers its flowers (issue 19 point 4, w25).

A tiled world opens the halo edges that face later tiles (strew.tiles._open_edges): the
engine measures a circle there against the elements alone, so a first-phase tile whose
neighbours all run later finds its vines-phase circles C centred past its edges (the
first: radius 48, 12 units past the edge, in tile 48's tile 10). §5's vine goes to the
free grid point nearest C's centre: past the panel, where no flower fits, so every try
failed and the tile grew no vine and no flower (helper wv2). The vine now goes to the
grid point within its reach, in the panel, nearest C's centre, and the next one if that
vine does not fit (vase._grid_points_in_panel); a vine that would pass over another free
grid point is refused there, as no flower fits at that point after it.
"""

from __future__ import annotations

import numpy as np
import shapely

import strew
from strew.ornament._engine import grow_elements
from strew.ornament.patterns import vase

# tile 10 of a 4 x 4 world of tiles 48 (halo 12): rectangle 96..144 grown to 84..156,
# every neighbour later, so every edge open, circle centres up to a halo past it
LO, HI, HALO = 84.0, 156.0, 12.0
OPEN = [[LO, LO, HI, LO, HALO], [HI, LO, HI, HI, HALO], [LO, HI, HI, HI, HALO], [LO, LO, LO, HI, HALO]]


def test_all_open_tile_grows_vines_to_grid_flowers_in_the_panel():
    reg = strew.Region(shapely.box(LO, LO, HI, HI))
    orn = grow_elements("vase", reg, rng=1, _open=OPEN, max_elements=9)
    vines = [e for e in orn.elements if e.type == "vine"]
    flowers = [e for e in orn.elements if e.type in ("lotus", "peony")]
    # the seed's four grid points around it get their flowers, each by a vine (main: none,
    # the vines phase failed its two tries, at C past the top and left edges, and ended)
    assert len(vines) >= 3 and len(flowers) >= 3, (len(vines), len(flowers))
    assert all(e.phase == "vines" for e in vines + flowers)
    for f in flowers:
        c, r = f.proxy.center, f.proxy.radius
        # on the world's grid, and wholly inside the panel
        assert np.allclose(c / vase.GRID, np.round(c / vase.GRID), atol=1e-9)
        assert LO <= c[0] - r and c[0] + r <= HI and LO <= c[1] - r and c[1] + r <= HI
    # one run (closed edges) is left as it was: C always lies in the panel there
    orn = grow_elements("vase", reg, rng=1, max_elements=9)
    got = sorted(tuple(np.round(e.proxy.center, 6)) for e in orn.elements if e.type in ("lotus", "peony"))
    assert got == [(110.0, 110.0), (110.0, 132.0), (132.0, 110.0), (132.0, 132.0)]


def test_open_edge_vine_leaves_no_grid_point_under_it():
    # tile 0 of a 4 x 4 world of tiles 60 (halo 15): grown to 0..75, the edges at 75 open
    # (later tiles). The first C lies past the right edge; the seed's vine to the grid
    # point nearest it, (66, 44), passed over (44, 44), 9.2 from the seed, which then
    # stayed empty (helper wv2's T60 world; without the refusal: 8 flowers, (44, 44) none)
    hi, halo = 75.0, 15.0
    reg = strew.Region(shapely.box(0.0, 0.0, hi, hi))
    orn = grow_elements("vase", reg, rng=1, _open=[[hi, 0.0, hi, hi, halo], [0.0, hi, hi, hi, halo]], max_elements=19)
    got = {tuple(np.round(e.proxy.center / vase.GRID).astype(int)) for e in orn.elements if e.type in ("lotus", "peony")}
    # every grid point whose flower fits in the panel holds one, as one closed run's
    assert got == {(i, j) for i in (1, 2, 3) for j in (1, 2, 3)}, sorted(got)

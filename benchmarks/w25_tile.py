"""One tile of a tiled vase world grown alone, its halo edges open or closed (helper w25,
issue 19.4): the elements by type and the flowers' grid points, and with ``--trace`` the
vines-phase tries (C, the vine's start, its parent, success).

``PYTHONPATH=src python benchmarks/w25_tile.py T INDEX open|closed [--trace]``

The tile is ``INDEX`` of a 4 x 4 world of tiles ``T`` (halo T / 4), grown in its rectangle
widened by the halo, with no context (a phase-0 tile is grown exactly so in the world); the
open edges are strew.tiles._open_edges' (those facing later tiles), with circle centres up
to a halo past them. The cause w25 measured: ``48 10 open`` at main grows no vine and no
flower (its two vines-phase Cs lie past the top and left edges; the grid point nearest each
holds no flower inside the panel), ``48 10 closed`` grows 4; ``60 0 open`` leaves (2, 2)
empty when the seed's vine may pass over it.
"""

from __future__ import annotations

import sys
from collections import Counter

import numpy as np
import shapely

import strew
import strew.ornament.patterns.vase as V
from strew.ornament._engine import grow_elements
from strew.tiles import _grow, _Job, _open_edges, plan, tile_rng


def main() -> None:
    tile, idx, mode = float(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    size, halo = (4 * tile, 4 * tile), tile / 4
    tiles, nx, ny = plan(size, tile)
    job = _Job("ornament", "vase", {}, size, halo, 1, (tile, tile), (nx, ny), False)
    t = tiles[idx]
    g = _grow(t.rect, halo, size)
    op = [e + [halo] for e in _open_edges(t, job, g)] if mode == "open" else None
    if "--trace" in sys.argv:
        orig = V.grow_vine

        def traced(ctx, parent, start, tangent, depth):
            c, r = ctx.goal.center, ctx.goal.radius
            ok = orig(ctx, parent, start, tangent, depth)
            print(f"C ({c[0]:.1f}, {c[1]:.1f}) r {r:.1f}, start ({start[0]:.1f}, {start[1]:.1f}) from {parent.type}: {bool(ok)}")
            return ok

        V.grow_vine = traced
    orn = grow_elements("vase", strew.Region(shapely.box(*g)), rng=tile_rng(1, idx), _open=op)
    print(f"tile {idx} {t.rect}, phase {t.phase}, grown {g}, {mode} edges {len(op or [])}")
    print(dict(Counter(e.type for e in orn.elements)))
    print("flowers at", sorted(tuple(int(v) for v in np.round(e.proxy.center / V.GRID)) for e in orn.elements if e.type in ("lotus", "peony")))


if __name__ == "__main__":
    main()

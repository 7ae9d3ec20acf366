"""How many rows keep_ancestors' bar drops in a tiled vase world (helper w26, issue 19.4).

``PYTHONPATH=TREE/src python benchmarks/w26_barred.py [T] [SEED]`` (default 48 1) grows the
4 x 4 vase world of tiles T (halo T / 4) and prints, per tile, the rows
strew.ornament._context.keep_ancestors would have kept without ``barred`` but keeps
not with it (the rescued chains and their lost successes, which keep_whole then drops:
holes deep in the finished tile), the barred rows, the tile's rows kept, and the world's
elements and grid flowers held.
"""

from __future__ import annotations

import sys

import numpy as np

import strew.ornament._context as C
import strew.tiles as T
from strew.ornament.patterns import vase as V

orig_ka = C.keep_ancestors
log: list = []


def ka(element, parent, group, placed, far, barred=None):
    out = orig_ka(element, parent, group, placed, far, barred)
    free = orig_ka(element, parent, group, placed, far, None)
    k1 = C.keep_whole(element, parent, group, out)
    k0 = C.keep_whole(element, parent, group, free)
    log.append((int((k0 & ~k1).sum()), 0 if barred is None else int(np.asarray(barred, bool).sum())))
    return out


C.keep_ancestors = ka
tile = float(sys.argv[1]) if len(sys.argv) > 1 else 48.0
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
arr = T.tiled("ornament", "vase", (4 * tile, 4 * tile), tile_size=tile, seed=seed)
print(f"T{tile:g} seed {seed}: per tile (rows dropped for a barred chain, barred rows):", log)
print("rows dropped for a barred chain, all tiles:", sum(a for a, _ in log), "; barred rows:", sum(b for _, b in log))
kinds = np.asarray(arr.kinds, dtype=object)[np.asarray(arr.kind, np.int64)]
fl = np.isin(kinds, ["lotus", "peony"])
pts = {(round(x / V.GRID), round(y / V.GRID)) for x, y in zip(np.asarray(arr.x)[fl], np.asarray(arr.y)[fl])}
print("elements", len(arr), "grid flowers", len(pts))

"""Ornament elements (vase, or the pattern named fourth) in one square panel by raster cells (issue 19.4, helpers w26b, w27h).

``PYTHONPATH=src python benchmarks/w26b_cells.py SIDE CELLS RNGS [PATTERN]``, e.g. ``72 d,96 1,2``:
for each rng, grow the vase in a SIDE x SIDE panel with each ``cells`` (``d``: the
engine's default, at least 256 along the side) and print the element count, the
count by kind and the CPU seconds. 72 is a tile's region at tile 48 (halo 12); 96 cells
give the untiled 192 x 192 world's cell of 0.75.
"""

import sys
import time

import numpy as np

import strew
from strew.ornament import grow_ornament

side = float(sys.argv[1])
cells = [None if c == "d" else int(c) for c in sys.argv[2].split(",")]
for s in [int(v) for v in sys.argv[3].split(",")]:
    for c in cells:
        t = time.process_time()
        a = grow_ornament(sys.argv[4] if len(sys.argv) > 4 else "vase", strew.Region.rectangle(side, side), rng=s, **({} if c is None else {"cells": c}))
        k = np.asarray(a.kind)
        cnt = {a.kinds[i]: int((k == i).sum()) for i in range(len(a.kinds))}
        print(f"side {side:g} rng {s} cells {c or 'default'}: {len(a)} elements {cnt} ({time.process_time() - t:.1f} s)", flush=True)

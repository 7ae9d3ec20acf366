"""Digests of grow outputs on several-size --harder rows at 2x, seeds 1-2 (compare two trees): python benchmarks/grow_several_digest.py three_sizes:1:7,two_sizes:4:7"""

import hashlib
import os
import sys

sys.path.insert(0, os.path.join(os.getcwd(), "benchmarks"))
import numpy as np
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import grow

mk = _harder_suite()
for c in sys.argv[1].split(","):
    cls, i, v = c.split(":")
    ex = mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    for seed in (1, 2):
        out = grow(ex, region=Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0)), rng=seed)
        h = hashlib.sha256()
        for a in (out.xy, out.kind, out.rotation, out.scale):
            if a is not None:
                h.update(np.ascontiguousarray(a).tobytes())
        print(c, seed, len(out.xy), h.hexdigest()[:16], flush=True)

# Helper s66h analysis of the npz files benchmarks/s66h_stages_h4.py writes to /tmp/s66h (run that first, --cap 0 and 1).
import sys

import numpy as np

sys.path.insert(0, "benchmarks"); sys.path.insert(0, __file__.rsplit("/", 1)[0])
from cls import circ
from grow_variants import _harder_suite
from synth_variants import _harder

mk = _harder_suite()
p = dict(_harder()["clusters"][4])
for size in (300, 1050):
    rows = []
    for r in range(9, 15):
        ex = mk.make_exemplar("clusters", rng=r, size=size, **p)
        xy = np.c_[ex.x, ex.y]; k = np.asarray(ex.kind)
        ra, _ = circ(xy, size)
        rows.append(f"rng {r}: q95 {np.quantile(ra, .95):.1f} discs/1e4 {np.sum(k == 0) / size**2 * 1e4:.2f} dots/disc {np.sum(k == 1) / np.sum(k == 0):.2f}")
    print(f"size {size}:\n  " + "\n  ".join(rows))

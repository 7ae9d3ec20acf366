"""Helper s66c: s64c_stages.py (ring shape after growth and after each pass of synth's grow) with the shape line
extended by what g[disc,dot] of clusters p4s39 turns on: disc nn p1/p10/p50, disc count per unit area of the
bounding box of the discs, ring dots' distance to their disc p50/p95 and the share of them at or beyond
1.4 s (15.08 for p4s39: the edge between g's bins r/s 1.3 and 1.5). Same arguments as s64c_stages.py.

    PYTHONPATH=src:benchmarks python benchmarks/s66c_stages.py clusters:p4s39 1 [--ring-cap ...]
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import s64c_stages as S

EDGE14 = [15.08]
_shape = S.shape


def shape(pos, kind):
    base = _shape(pos, kind)
    disc, dot = pos[kind == 0], pos[kind == 1]
    if len(disc) < 2 or len(dot) < 2:
        return base
    dn = cKDTree(disc).query(disc, k=2)[0][:, 1]
    d, _ = cKDTree(disc).query(dot)
    rd = d[d < S.REACH]
    return (base + f" | disc nn p1/p10/p50 {np.percentile(dn, [1, 10, 50]).round(1)} ring r p50/p95 {np.percentile(rd, [50, 95]).round(2)}"
            f" >=1.4s {np.mean(rd >= EDGE14[0]):.3f}")


S.shape = shape
if __name__ == "__main__":
    S.main()

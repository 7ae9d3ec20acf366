"""Helper grw14v: three sizes --harder rows, the large stones' nearest small stone (grow, fixed mode).

For ``--harder`` three_sizes variant ``I`` drawn with seed ``V``, grows the output as the
audit does (3.5x the frame's side) and prints the grower's per-pair bounding-disc gaps
(``_Grower.pair_disc``), and for the exemplar and the output the deciles of the large
stones' centre distance to their nearest small stone and of the gap between their scaled
bounding discs, then the failing metrics.

Measured at 4882d93 (h12s7, counts 400:15:15, seed 1): pair_disc[small, large] 0 (the
``small_outside`` rule's gap 0); the exemplar's disc gaps min/q10/q30/q50 1.20/1.22/1.25/1.45,
the output's 0.00/0.10/0.41/0.86; centre-distance deciles 15.7-16.9 against 14.2-16.6:
nn[large>small] 0.103 against 0.0741 (small stones too NEAR the large ones, not too far).

    PYTHONPATH=src python benchmarks/grw14v_gaps.py 12 7 1,2
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import _growth as G
from strew.grow import grow
from strew.metrics import fidelity

mk = _harder_suite()
i, v = int(sys.argv[1]), int(sys.argv[2])
ex = mk.make_exemplar("three_sizes", rng=v, **HARDER["three_sizes"][i])
cap = {}
r0 = G._Grower.result


def res(self, meta):
    cap["g"] = self
    return r0(self, meta)


G._Grower.result = res
x0, y0, x1, y1 = ex.region.bounds
for seed in map(int, sys.argv[3].split(",")):
    out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    g = cap["g"]
    print(f"h{i}s{v} seed {seed}: kinds {ex.kinds} level {g.size_level} radius {np.round(g.kind_radius, 2)}")
    print(" pair_disc\n", np.round(g.pair_disc, 2))
    for name, arr in (("exemplar", ex), ("output", out)):
        ks = list(arr.kinds)
        L, S = ks.index("large"), ks.index("small")
        Ra = np.array([g.kind_radius[ex.kinds.index(k)] for k in ks])[arr.kind] * np.abs(arr.scale)
        il, is_ = np.flatnonzero(arr.kind == L), np.flatnonzero(arr.kind == S)
        d, j = cKDTree(arr.xy[is_]).query(arr.xy[il])
        gap = d - Ra[il] - Ra[is_][j]
        print(f" {name}: nn large>small deciles {np.round(np.quantile(d, np.linspace(0.1, 0.9, 9)), 1)}")
        print(f" {name}: disc gap to nearest small min/q10/q30/q50/q70/q90 {np.round(np.quantile(gap, [0, 0.1, 0.3, 0.5, 0.7, 0.9]), 2)}")
    rep = fidelity(ex, out, eq5=False, local=False)
    print(" fails", [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed], flush=True)

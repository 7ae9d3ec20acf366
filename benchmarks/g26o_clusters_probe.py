"""Helper g26o: grow (fixed) on a clusters row: kind counts of exemplar and output, the hubs'
structure (satellite_structure) and how far each output dot is from its nearest disc.

    PYTHONPATH=src python benchmarks/g26o_clusters_probe.py [CLASS:LABEL=clusters:p2s18] [SEED=1]
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite
from fresh17_rows import exemplar
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import grow
from strew.grow._clusters import satellite_structure
from strew.metrics import fidelity

spec = sys.argv[1] if len(sys.argv) > 1 else "clusters:p2s18"
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
cls, label = spec.split(":")
mk = fidelity_suite()
ex = exemplar(mk, cls, label)


def counts(a):
    kn = np.asarray(a.kind_names)
    return {k: int((kn == k).sum()) for k in sorted(set(kn))}


def dot_disc(a):
    kn = np.asarray(a.kind_names)
    xy = np.c_[a.x, a.y]
    d, _ = cKDTree(xy[kn == "disc"]).query(xy[kn == "dot"])
    return np.percentile(d, [10, 50, 90, 99]).round(2)


sat = satellite_structure(ex)
print("exemplar", counts(ex), "bounds", np.round(ex.region.bounds, 1), "dot>disc q10/50/90/99", dot_disc(ex))
print("  hubs", None if sat is None else (len(sat.members), int(np.sum(sat.complete)), [len(m) for m in sat.members]))
x0, y0, x1, y1 = ex.region.bounds
scale = 3.5
for _ in range(2):
    out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=seed)
    print(f"  scale {scale:.2f}: n={len(out)} {counts(out)} dot>disc {dot_disc(out)}")
    if len(out) >= 10 * len(ex):
        break
    scale *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
rep = fidelity(ex, out, eq5=False, local=False)
print("fails", [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed])
print("meta", {k: v for k, v in out.meta.items() if k not in ("params",)} if hasattr(out, "meta") else None)

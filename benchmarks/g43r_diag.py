"""Helper g43r: nn deciles (result vs exemplar) for chosen grow --varied rows.

    PYTHONPATH=src:benchmarks python benchmarks/g43r_diag.py stripes:v29 1
"""
import sys
from types import SimpleNamespace

import numpy as np

import strew._fidelity as F
from fresh17_rows import exemplar
from _runner import fidelity_suite
from grow_variants import run

cap = []
orig = F._discrepancies


def wrap(a, b, kinds, s, **kw):
    cap.append((a, b, kinds, s))
    return orig(a, b, kinds, s, **kw)


F._discrepancies = wrap
spec, seed = sys.argv[1], int(sys.argv[2])
cls, label = spec.split(":")
ex = exemplar(fidelity_suite(), cls, label)
kinds = list(ex.kinds)
print("exemplar n", len(ex), {k: int((ex.kind == i).sum()) for i, k in enumerate(ex.kinds)}, "region", ex.region.bounds)
out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
print("result n", len(out), {k: int((out.kind == i).sum()) for i, k in enumerate(out.kinds)})
cap.clear()
rep = F.fidelity(ex, out, eq5=False, local=False)
a, b, kn, s = cap[0]
print("s", s, "faithful", rep.faithful)
for i, ki in enumerate(kn):
    for j, kj in enumerate(kn):
        m = rep.metrics[f"nn[{ki}>{kj}]"]
        print(f"nn[{ki}>{kj}] {m.value:.4f}/{m.tolerance:.4f}")
        print("   res", np.round(a.nn[i, j] / s, 3))
        print("   ex ", np.round(b.nn[i, j] / s, 3))
print("density", {k: (round(a.density[i], 6), round(b.density[i], 6)) for i, k in enumerate(kn)})
print("fraction", {k: (round(a.fraction[i], 4), round(b.fraction[i], 4)) for i, k in enumerate(kn)})
for k, m in rep.metrics.items():
    if m.applicable and m.value > 0.7 * m.tolerance:
        print("near", k, round(m.value, 4), round(m.tolerance, 4))

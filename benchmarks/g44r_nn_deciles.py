"""Helper g44r: a grow row's nearest-neighbour deciles, exemplar beside output (in units
of the exemplar's median nn, s), the fidelity's whole windows.

    PYTHONPATH=src:benchmarks python benchmarks/g44r_nn_deciles.py CLASS:LABEL SEEDS [A>B ...]
"""
import os
import sys
from types import SimpleNamespace

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run

from strew import _fidelity
from strew.metrics import fidelity

got = []
_orig = _fidelity._stats


def _keep(*a, **k):
    st = _orig(*a, **k)
    got.append(st)
    return st


_fidelity._stats = _keep
cls, label = sys.argv[1].split(":")
pairs = sys.argv[3:] or None
mk = fidelity_suite()
ex = exemplar(mk, cls, label)
s = _fidelity._median_nn(ex.xy)
for seed in _variants.ints(sys.argv[2]):
    got.clear()
    out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
    rep = fidelity(ex, out, eq5=False, local=False)
    es, rs = got[0], got[1]
    kinds = [k for i, k in enumerate(ex.kinds) if np.any(ex.kind == i)]
    print(f"{cls}:{label} seed {seed} n={len(out)} faithful={rep.faithful} s={s:.3f}")
    for i, a in enumerate(kinds):
        for j, b in enumerate(kinds):
            name = f"{a}>{b}"
            if pairs and name not in pairs:
                continue
            m = rep.metrics[f"nn[{name}]"]
            print(f"  nn[{name}] {m.value:.4f}/{m.tolerance:.3f}")
            print("    ex  " + " ".join(f"{v / s:.3f}" for v in es.nn[i, j]))
            print("    out " + " ".join(f"{v / s:.3f}" for v in rs.nn[i, j]))
            print("    d   " + " ".join(f"{(v - w) / s:+.3f}" for v, w in zip(rs.nn[i, j], es.nn[i, j])))

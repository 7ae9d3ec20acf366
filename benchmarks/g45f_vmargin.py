"""Helper g45f: --varied rows' metrics nearest their tolerance (grow fixed, seed 1).

    PYTHONPATH=src:benchmarks python benchmarks/g45f_vmargin.py two_sizes:p0s29,two_sizes:p0s30
"""
import os
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run

import strew
from strew.metrics import fidelity

mk = fidelity_suite()
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    out, _ = run(ex, 3.5, 1, SimpleNamespace(mode="fixed", times=10.0))
    rep = fidelity(ex, out, eq5=False, local=False)
    near = sorted((m.tolerance - m.value, k, m.value, m.tolerance) for k, m in rep.metrics.items() if m.applicable)[:2]
    print(f"{spec} {'pass' if rep.faithful else 'FAIL'} n={len(out)} " + " ".join(f"{k}={v:.3g}/{t:.3g}({d:+.3f})" for d, k, v, t in near), flush=True)
print(strew.__file__)

"""Helper g45f: each --harder row's metrics nearest their tolerance (seed 1), to find the
rows within 0.01 of tolerance that a change moves.

    PYTHONPATH=src:benchmarks python benchmarks/g45f_margin.py two_sizes:0:29,two_sizes:1:30 [seed]
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

import strew
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

mk = _harder_suite()
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
for c in sys.argv[1].split(","):
    cls, i, v = c.split(":")
    ex = mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    rep = fidelity(ex, out, eq5=False, local=False)
    near = sorted((m.tolerance - m.value, k, m.value, m.tolerance) for k, m in rep.metrics.items() if m.applicable)[:2]
    print(f"{c} {'pass' if rep.faithful else 'FAIL'} n={len(out)} " + " ".join(f"{k}={val:.3g}/{tol:.3g}({d:+.3f})" for d, k, val, tol in near), flush=True)
print(strew.__file__)

"""Helper grw14y: chosen --harder rows (any class) at more seeds (audit fidelity: eq5 and local off).

    PYTHONPATH=src python benchmarks/grw14y_rows.py three_sizes:1:7,two_sizes:11:7 1-6
    (class:suite:V for the fidelity suite's exemplar drawn with seed V)
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

import strew
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

mk = _harder_suite()
a, _, b = sys.argv[2].partition("-")
seeds = range(int(a), int(b) + 1)
tot = 0
for c in sys.argv[1].split(","):
    cls, i, v = c.split(":")
    if i == "suite":
        ex = mk.make_exemplar(cls, rng=int(v))
    else:
        ex = mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    res = []
    for seed in seeds:
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        res.append(int(rep.faithful))
        print(f"  {c} seed {seed}: {'pass' if rep.faithful else 'FAIL'} {fails}", flush=True)
    print(f"{c} {sum(res)}/{len(res)}", flush=True)
    tot += sum(res)
print(f"total {tot}  ({strew.__file__})", flush=True)

"""Helper grw14p: chosen --harder three_sizes rows at more seeds (audit fidelity: eq5 and local off).

    PYTHONPATH=src python benchmarks/grw14p_rows.py 10:7,10:8,11:7 1-6
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
for c in sys.argv[1].split(","):
    i, v = map(int, c.split(":"))
    ex = mk.make_exemplar("three_sizes", rng=v, **HARDER["three_sizes"][i])
    x0, y0, x1, y1 = ex.region.bounds
    res = []
    for seed in seeds:
        out = grow(ex, region=Region.rectangle(3.5*(x1-x0), 3.5*(y1-y0)), rng=seed)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        res.append(int(rep.faithful))
        print(f"  h{i}s{v} seed {seed}: {'pass' if rep.faithful else 'FAIL'} {fails}", flush=True)
    print(f"h{i}s{v} {sum(res)}/{len(res)}  ({strew.__file__})", flush=True)

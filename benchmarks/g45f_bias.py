"""Helper g45f: fraction[stone]/density[stone] and the output's stone share against the
exemplar's, for one --harder set over many variant seeds (seed 1): is the large kind
over-produced in general?

    PYTHONPATH=src:benchmarks python benchmarks/g45f_bias.py two_sizes:0 7-30 [seed]
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

import strew
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

mk = _harder_suite()
cls, i = sys.argv[1].split(":")
a, _, b = sys.argv[2].partition("-")
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
tot = []
for v in range(int(a), int(b) + 1):
    ex = mk.make_exemplar(cls, rng=v, **HARDER[cls][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    rep = fidelity(ex, out, eq5=False, local=False)
    big = 0  # the larger kind: kind 0 in these generators (stone)
    se = float(np.mean(ex.kind == big))
    so = float(np.mean(out.kind == big))
    m = {k: f"{x.value:.3g}/{x.tolerance:.3g}" for k, x in rep.metrics.items() if x.applicable and k.split("[")[0] in ("fraction", "density") and "0" not in k}
    fails = [k for k, x in rep.metrics.items() if x.applicable and not x.passed]
    tot.append(so - se)
    print(f"{cls}:{i}:{v} {'pass' if rep.faithful else 'FAIL'} n={len(out)} share ex {se:.3f} out {so:.3f} ({so - se:+.3f}) {m} fails={fails}", flush=True)
print(f"mean share diff {np.mean(tot):+.4f} over {len(tot)}  ({strew.__file__})")

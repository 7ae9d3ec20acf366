"""Helper g43m: the judge's per-kind density ratio (result / exemplar) of grow and of the
generator at the output's size, on --harder rows.

    PYTHONPATH=src:benchmarks python benchmarks/g43m_kinds.py three_sizes:7 23,24 1 [oracle]
"""
import sys

import numpy as np
from grow_variants import HARDER, _harder_suite
from svar13i_oracle import big_params

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

mk = _harder_suite()
cls, i = sys.argv[1].split(":")
vs = [int(v) for v in sys.argv[2].split(",")]
a, _, b = sys.argv[3].partition("-")
seeds = range(int(a), int(b or a) + 1)
orc = len(sys.argv) > 4


def dens(ex, out):
    rep = fidelity(ex, out, eq5=False, local=False)
    d = " ".join(f"{k[8:-1]}={m.result / m.exemplar:.3f}" for k, m in rep.metrics.items() if k.startswith("density") and m.applicable)
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    return d, fails


for v in vs:
    kw = HARDER[cls][int(i)]
    ex = mk.make_exemplar(cls, rng=v, **kw)
    x0, y0, x1, y1 = ex.region.bounds
    for seed in seeds:
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        d, f = dens(ex, out)
        print(f"{cls} h{i}s{v} seed {seed} grow n={np.bincount(out.kind)} {d} {f}", flush=True)
    if orc:
        for draw in (1, 2):
            big = mk.make_exemplar(cls, rng=v + 1000 * draw, **big_params(cls, kw, 3.5))
            d, f = dens(ex, big)
            print(f"{cls} h{i}s{v} oracle {draw} n={np.bincount(big.kind)} {d} {f}", flush=True)

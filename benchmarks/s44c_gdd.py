"""Helper s44c: g[disc,dot] of a clusters row's output against its exemplar, with disc counts and dots per disc.

    PYTHONPATH=src:benchmarks python benchmarks/s44c_gdd.py p2s27 1,2,3,4
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, "benchmarks")
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run

import strew
from strew._fidelity import BIN, R_MAX, _median_nn, pair_correlation
from strew.metrics import fidelity

ex = exemplar(fidelity_suite(), "clusters", sys.argv[1])
s = _median_nn(ex.xy)
nb = round(R_MAX / BIN)


def desc(a):
    k = np.asarray(a.kind_names)
    disc, dot = a.xy[k == "disc"], a.xy[k == "dot"]
    d, j = cKDTree(disc).query(dot)
    x0, y0, x1, y1 = a.region.bounds
    per = np.bincount(j[d < 22], minlength=len(disc))
    g = pair_correlation(a, r_max=R_MAX * s, bins=nb)
    return len(disc), (x1 - x0) * (y1 - y0) / len(disc), per.mean(), int((d >= 22).sum()), g["g"]["disc,dot"], g["r"]


n, apd, dpd, st, gex, r = desc(ex)
print(f"{sys.argv[1]} exemplar: discs {n} area/disc {apd:.0f} dots/disc {dpd:.2f} strays {st}   ({strew.__file__})")
print("  r      " + " ".join(f"{x:5.1f}" for x in r))
print("  g ex   " + " ".join(f"{x:5.2f}" for x in gex))
for seed in [int(x) for x in sys.argv[2].split(",")]:
    out, _ = run(ex, 3.5, seed, None)
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["g[disc,dot]"]
    n, apd, dpd, st, g, _ = desc(out)
    print(f" seed {seed}: discs {n} area/disc {apd:.0f} dots/disc {dpd:.2f} strays {st} g[disc,dot] {m.value:.3g}/{m.tolerance:.3g} {'pass' if rep.faithful else 'FAIL'}")
    print("  g out  " + " ".join(f"{x:5.2f}" for x in g))

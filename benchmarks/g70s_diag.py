"""Helper g70s (issue 14 point 1): nn[stone>stone] deciles of exemplar / generator / grow.

    PYTHONPATH=src:benchmarks python benchmarks/g70s_diag.py two_sizes:8:43,two_sizes:0:43 1-3 [draws] [grow params, "a=1,b=2"]
Prints, per row, the exemplar's nn[stone>stone] deciles (units of s), then for each output
(the generator drawn at 3.5x the side, and grow at seeds) the signed decile differences,
the metric value/tolerance and the stone density ratio.
"""
import sys

import numpy as np

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite
from svar13i_oracle import big_params

import strew._fidelity as F
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

cap = {}
_orig = F._discrepancies


def _spy(a, b, kinds, s, **kw):
    if "res" not in cap:
        cap["res"], cap["ex"], cap["kinds"], cap["s"] = a, b, kinds, s
    return _orig(a, b, kinds, s, **kw)


F._discrepancies = _spy

# G70S_OFF=name1,name2: the named post-growth passes of strew.grow._growth made no-ops
import os
import strew.grow._growth as _G
for _n in filter(None, os.environ.get("G70S_OFF", "").split(",")):
    setattr(_G, _n, lambda *a, **k: False)


def measure(ex, out):
    cap.clear()
    rep = fidelity(ex, out, eq5=False, local=False)
    k = cap["kinds"]
    i = k.index("stone")
    d = cap["res"].nn[i, i] - cap["ex"].nn[i, i]
    m = rep.metrics["nn[stone>stone]"]
    dens = rep.metrics.get("density[stone]")
    return rep, cap["ex"].nn[i, i] / cap["s"], d / cap["s"], m, dens


mk = _harder_suite()
a, _, b = sys.argv[2].partition("-")
seeds = range(int(a), int(b) + 1)
draws = int(sys.argv[3]) if len(sys.argv) > 3 else 2
params = eval("dict(" + sys.argv[4] + ")") if len(sys.argv) > 4 else {}
np.set_printoptions(precision=3, suppress=True, linewidth=200)
for c in sys.argv[1].split(","):
    cls, i, v = c.split(":")
    kw = dict(HARDER[cls][int(i)])
    ex = mk.make_exemplar(cls, rng=int(v), **kw)
    x0, y0, x1, y1 = ex.region.bounds
    print(f"== {c} {kw} exemplar n={len(ex)} stones={int((np.asarray(ex.kind) == 0).sum())}")
    outs = []
    for d in range(draws):
        outs.append((f"gen d{d}", mk.make_exemplar(cls, rng=int(v) + 1000 * d, **big_params(cls, kw, 3.5))))
    for seed in seeds:
        outs.append((f"grow s{seed}", grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, **params)))
    first = True
    for name, out in outs:
        rep, exq, dq, m, dens = measure(ex, out)
        if first:
            print(f"  exemplar deciles/s: {exq}")
            first = False
        fails = [f"{k}={mm.value:.3g}/{mm.tolerance:.3g}" for k, mm in rep.metrics.items() if mm.applicable and not mm.passed]
        ds = f"dens[stone] {dens.result:.4g}/{dens.exemplar:.4g}" if dens is not None and dens.result is not None else ""
        print(f"  {name:8s} n={len(out):5d} diff/s {dq}  nn={m.value:.3g}/{m.tolerance:.3g} {ds} {'pass' if rep.faithful else fails}", flush=True)

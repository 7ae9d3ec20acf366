"""Helper g47f: the large kind's nearest same-kind distances (deciles, in units of the
exemplar's median nn spacing s, minus the exemplar's, interior elements only: Hanisch's
border rule as the judge) after each grow stage, for --varied rows.

    PYTHONPATH=src:benchmarks python benchmarks/g47f_steps.py two_sizes:p2s33 1-2
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from types import SimpleNamespace

import _variants
import numpy as np
import shapely
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run
from scipy.spatial import cKDTree

from strew.grow import _growth as G
from strew.metrics import fidelity

DEC = np.linspace(0.1, 0.9, 9)
LOG = []
REF = {}


def nn_dec(xy, kind, k, geom, s):
    sel = kind == k
    p = xy[sel]
    if len(p) < 3:
        return np.full(9, np.nan), 0
    d, _ = cKDTree(p).query(p, 2)
    d = d[:, 1]
    edge = shapely.distance(geom.boundary, shapely.points(p))
    ok = d <= edge
    return np.quantile(d[ok], DEC) / s, int(sel.sum())


def state(g):
    idx = np.asarray(g.order, dtype=np.intp)
    k = g.kind[idx]
    xy = g.pos[idx]
    geom = g.region.geometry if hasattr(g.region, "geometry") else g.region
    q, n0 = nn_dec(xy, k, 0, geom, REF["s"])
    d = q - REF["q"]
    return f"n={len(idx)} n0={n0} share0={n0 / max(1, len(idx)):.4f} signed {np.array2string(d, precision=2)} mean {np.mean(d):+.3f}"


def wrap_fn(name):
    f = getattr(G, name)

    def w(g, *a, **k):
        r = f(g, *a, **k)
        LOG.append(f"  after {name}{'(toward)' if k.get('toward') else ''}: {state(g)}")
        return r
    setattr(G, name, w)


def wrap_meth(name):
    f = getattr(G._Grower, name)

    def w(self, *a, **k):
        r = f(self, *a, **k)
        LOG.append(f"  after {name}: {state(self)}")
        return r
    setattr(G._Grower, name, w)


for n in ("fill_void_holes", "swap_lone_larger", "move_lone_smaller", "reseed_lone_kin", "thin_to_holes"):
    wrap_fn(n)
for n in ("advance", "settle"):
    wrap_meth(n)

if __name__ == "__main__":
    mk = fidelity_suite()
    args = SimpleNamespace(mode="fixed", times=10.0)
    for spec in sys.argv[1].split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        from strew._fidelity import _median_nn
        s = _median_nn(ex.xy)
        REF["s"] = s
        REF["q"], n0 = nn_dec(ex.xy, ex.kind, 0, ex.region.geometry, s)
        print(f"{spec} exemplar n={len(ex)} n0={n0} share0={n0/len(ex):.4f} s={s:.3f} nn0 deciles/s {np.array2string(REF['q'], precision=2)}", flush=True)
        for seed in _variants.ints(sys.argv[2]):
            LOG.clear()
            out, _ = run(ex, 3.5, seed, args)
            rep = fidelity(ex, out, eq5=False, local=False)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and (not m.passed or k.startswith("nn[stone>stone]"))]
            print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {fails}")
            last = None
            for line in LOG:
                if line != last:
                    print(line)
                last = line
            sys.stdout.flush()

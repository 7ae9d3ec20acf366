"""Helper g45f: kind counts (and interior shares) after each grow step for --harder rows.

    PYTHONPATH=src:benchmarks python benchmarks/g45f_steps.py two_sizes:0:32 1-2
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import _growth as G
from strew.grow import grow
from strew.metrics import fidelity

LOG = []


def counts(g):
    idx = np.asarray(g.order, dtype=np.intp)
    k = g.kind[idx]
    c = np.bincount(k[k >= 0], minlength=2)
    # interior share (minus sampling: centres 1 large spacing inside the region)
    x0, y0, x1, y1 = g.region.bounds if hasattr(g.region, "bounds") else g.region.geometry.bounds
    m = 0.1 * (x1 - x0)
    p = g.pos[idx]
    ins = (p[:, 0] > x0 + m) & (p[:, 0] < x1 - m) & (p[:, 1] > y0 + m) & (p[:, 1] < y1 - m)
    ci = np.bincount(k[ins & (k >= 0)], minlength=2)
    return f"n={len(idx)} kinds={c.tolist()} share0={c[0]/max(1,c.sum()):.4f} inner={ci.tolist()} share0={ci[0]/max(1,ci.sum()):.4f}"


def wrap_fn(name):
    f = getattr(G, name)

    def w(g, *a, **k):
        r = f(g, *a, **k)
        LOG.append(f"  after {name}{'(toward)' if k.get('toward') else ''}: {counts(g)}")
        return r
    setattr(G, name, w)


def wrap_meth(name):
    f = getattr(G._Grower, name)

    def w(self, *a, **k):
        r = f(self, *a, **k)
        LOG.append(f"  after {name}: {counts(self)}")
        return r
    setattr(G._Grower, name, w)


for n in ("fill_void_holes", "swap_lone_larger", "move_lone_smaller", "reseed_lone_kin", "thin_to_holes"):
    wrap_fn(n)
for n in ("advance", "settle"):
    wrap_meth(n)
import collections
import json
import os

OVR = json.loads(os.environ.get("OVR", "{}"))
CNT = collections.Counter()
_tl = G._Grower.try_larger


def _try_larger(self, s):
    own = int(self.kind[s])
    r = _tl(self, s)
    if r:
        CNT[f"conv{own}->{int(self.kind[s])}"] += 1
    return r


G._Grower.try_larger = _try_larger
_pl = G._Grower.place


def _place(self, s, *a, **k):
    r = _pl(self, s, *a, **k)
    CNT[f"place{int(self.kind[s])}{'ok' if r else 'fail'}"] += 1
    return r


G._Grower.place = _place
_df = G._Grower._defer


def _defer(self, s):
    CNT[f"defer{int(self.kind[s])}"] += 1
    return _df(self, s)


G._Grower._defer = _defer

mk = _harder_suite()
a, _, b = sys.argv[2].partition("-")
for c in sys.argv[1].split(","):
    cls, i, v = c.split(":")
    ex = mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    ek = np.bincount(ex.kind, minlength=2)
    ex0, ey0, ex1, ey1 = ex.region.bounds
    mx = 0.1 * (ex1 - ex0)
    ins = (ex.x > ex0 + mx) & (ex.x < ex1 - mx) & (ex.y > ey0 + mx) & (ex.y < ey1 - mx)
    eki = np.bincount(ex.kind[ins], minlength=2)
    print(f"{c} exemplar kinds={ek.tolist()} share0={ek[0]/ek.sum():.4f} inner={eki.tolist()} share0={eki[0]/eki.sum():.4f} radii? shapes={len(ex.shapes)}")
    for seed in range(int(a), int(b) + 1):
        LOG.clear()
        out = grow(ex, region=Region.rectangle(3.5 * (ex1 - ex0), 3.5 * (ey1 - ey0)), rng=seed, **OVR)
        print('  ', dict(sorted(CNT.items()))); CNT.clear()
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and ("fraction" in k or "density" in k or not m.passed)]
        print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} {fails}")
        last = None
        for l in LOG:
            if l != last:
                print(l)
            last = l

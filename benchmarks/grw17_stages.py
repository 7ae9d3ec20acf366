"""grw17 probe: kind counts of a --harder row after each stage of _Grower.run (the
growth, the hole fills, the lone passes), and the place refusals per kind.

    PYTHONPATH=TREE/src python benchmarks/grw17_stages.py two_sizes:3:10 1,4
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

import strew.grow._growth as G
from strew import Region
from strew.grow import grow
from strew.grow._objects import ELEMENT

cls = G._Grower
log = []


def counts(g):
    n = g.n
    k = g.kind[:n][g.state[:n] == ELEMENT]
    return np.bincount(k[k >= 0], minlength=g.n_kinds).tolist()


for name in ("fill_void_holes", "swap_lone_larger", "move_lone_smaller", "reseed_lone_kin"):
    f = getattr(G, name)

    def w(g, *a, _f=f, _n=name, **k):
        r = _f(g, *a, **k)
        log.append((_n, r, counts(g)))
        return r

    setattr(G, name, w)
oa = cls.advance


def adv(self, *a, **k):
    r = oa(self, *a, **k)
    log.append(("advance", None, counts(self)))
    return r


cls.advance = adv
op = cls.place
tries = {}


def place(self, s, *a, **k):
    kd = int(self.kind[s])
    r = op(self, s, *a, **k)
    t = tries.setdefault(kd, [0, 0])
    t[0] += 1
    t[1] += int(not r)
    return r


cls.place = place
mk = _harder_suite()
for spec in sys.argv[1].split(","):
    c, i, v = spec.split(":")
    ex = mk.make_exemplar(c, rng=int(v), **HARDER[c][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    for seed in [int(s) for s in sys.argv[2].split(",")]:
        log.clear()
        tries.clear()
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        print(spec, seed, "final", np.bincount(np.asarray(out.kind)).tolist(), "place tries/refused", dict(sorted(tries.items())))
        for e in log:
            print("   ", e)

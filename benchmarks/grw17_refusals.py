"""grw17 probe: why placements of each kind are refused in a --harder row (the last
check place() asked before it returned False), and how seeds die per kind.

    PYTHONPATH=TREE/src python benchmarks/grw17_refusals.py two_sizes:3:10 1,4
"""
import sys
from collections import Counter

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

import strew.grow._growth as G
from strew import Region
from strew.grow import grow

cls = G._Grower
trail = []
why = Counter()
refuse_val = {"too_close_in_kind": True, "crowds_own_kind": True, "lean_ok": False, "fits_domain": False,
              "overlaps_any": True, "crowds_gap": True}
for name, bad in refuse_val.items():
    f = getattr(cls, name)

    def w(self, *a, _f=f, _n=name, _bad=bad, **k):
        r = _f(self, *a, **k)
        trail.append((_n, r == _bad))
        return r

    setattr(cls, name, w)
op = cls.place


def place(self, s, a, *rest, **k):
    trail.clear()
    kind = int(self.ex_kind[int(self.ref_ids[a])])
    r = op(self, s, a, *rest, **k)
    if not r:
        bad = [n for n, b in trail if b]
        why[(kind, bad[-1] if bad else "other")] += 1
    else:
        why[(kind, "placed")] += 1
    return r


cls.place = place
oc = cls.choose


def choose(self, s, *a, **k):
    r = oc(self, s, *a, **k)
    if r is None:
        why[(int(self.kind[s]), "choose None")] += 1
    return r


cls.choose = choose
mk = _harder_suite()
for spec in sys.argv[1].split(","):
    c, i, v = spec.split(":")
    ex = mk.make_exemplar(c, rng=int(v)) if i == "suite" else mk.make_exemplar(c, rng=int(v), **HARDER[c][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    for seed in [int(s) for s in sys.argv[2].split(",")]:
        why.clear()
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        print(spec, seed, np.bincount(np.asarray(out.kind)).tolist())
        for k in sorted(why):
            print("   ", k, why[k])

"""Helper gh0: which object refuses a seed's placement by ``too_close_in_kind`` (grow, fixed mode).

For one --harder row, records every placement of kind KIND refused by ``too_close_in_kind``
(placing=True) and prints, by the blocking element's kind, the count and the deciles of its
distance over ``pair_close`` (how far inside the rule it sat), plus the pair_close matrix
over the exemplar's s.

    PYTHONPATH=src python benchmarks/gh0_close_probe.py three_sizes:6:13 1 large
"""
import sys
from collections import defaultdict

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

import strew.grow._collide as C
from strew import Region
from strew.grow import grow
from strew.grow._objects import ELEMENT

cls_, i, v = sys.argv[1].split(":")
seed = int(sys.argv[2])
want = sys.argv[3]
mk = _harder_suite()
ex = mk.make_exemplar(cls_, rng=int(v), **HARDER[cls_][int(i)])
NAMES = list(ex.kinds)
rec = defaultdict(list)
G = {}
orig = C._Collide.too_close_in_kind


def wrapped(self, x, y, kind, s, states=(C.SEED, ELEMENT), placing=False):
    out = orig(self, x, y, kind, s, states, placing)
    G["g"] = self
    if out and placing and NAMES[kind] == want:
        ps = self.pair_close
        best = None
        for o in range(self.n):
            if self.state[o] != ELEMENT or o == s:
                continue
            ko = int(self.kind[o])
            if ko < 0:
                continue
            d = float(np.hypot(*(np.asarray(self.xy[o]) - (x, y))))
            r = d / ps[kind, ko]
            if r < 1 and (best is None or r < best[1]):
                best = (ko, r)
        if best is not None:
            rec[NAMES[best[0]]].append(best[1])
    return out


C._Collide.too_close_in_kind = wrapped
x0, y0, x1, y1 = ex.region.bounds
out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
g = G["g"]
print("kinds", NAMES, "l", round(g.l, 3))
print("pair_close / l\n", np.round(g.pair_close / g.l, 3))
for k, r in rec.items():
    print(f"{want} refused near {k}: {len(r)}  d/pair_close deciles", np.round(np.quantile(r, np.linspace(0.1, 0.9, 9)), 3))

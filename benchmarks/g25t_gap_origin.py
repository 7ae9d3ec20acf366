"""Helper g25t: why a grown small stone lies beyond the reference's reach from every large one.

For one --harder three_sizes row and seed (grow, fixed mode), records at each placement of a
seed whether the canopy (``_Place.try_larger``) looked for a large stone there and what it
found: "seed" (a large SEED within reach, no large element: the canopy stood down for a
seed that may later die), "elem" (a large element within reach), "tried" (converted, placement
refused), "full" (gated by ``canopy_full``), "placed" (converted). For the small/medium
stones of the output that lie beyond reach_larger[k, large] of every large one (interior),
prints the counts by that origin, and how the large seeds that stood in for them ended.

    PYTHONPATH=src python benchmarks/g25t_gap_origin.py three_sizes:11:16 1
"""
import sys
from collections import Counter

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite
from scipy.spatial import cKDTree

import strew.grow._place as P
from strew import Region
from strew.grow import grow
from strew.grow._objects import ELEMENT, SEED

cls_, i, v = sys.argv[1].split(":")
seed = int(sys.argv[2])
mk = _harder_suite()
ex = mk.make_exemplar(cls_, rng=int(v), **HARDER[cls_][int(i)])
NAMES = list(ex.kinds)
origin: dict[int, str] = {}
stood: dict[int, int] = {}  # small seed -> the large seed that stood in for it
G = {}
orig_try = P._Place.try_larger
orig_full = P._Place.canopy_full


def try_larger(self, s):
    G["g"] = self
    k = int(self.kind[s])
    out = orig_try(self, s)
    if out:
        origin[s] = "placed"
        return True
    L = int(np.argmax(self.size_level))
    if k < 0 or k == L or not np.isfinite(self.reach_larger[k, L]):
        return False
    if s in origin:  # tried / full set by the wrappers
        return False
    x, y = self.xy[s]
    r = self.reach_larger[k, L]
    el = se = None
    for o in self.near(x, y, r):
        if int(self.kind[o]) == L and o != s and (self.xy[o][0] - x) ** 2 + (self.xy[o][1] - y) ** 2 <= r * r:
            if self.state[o] == ELEMENT:
                el = o
            elif self.state[o] == SEED:
                se = o
    if el is not None:
        origin[s] = "elem"
    elif se is not None:
        origin[s] = "seed"
        stood[s] = se
    else:
        origin[s] = "tried"
    return False


def canopy_full(self, s, b):
    out = orig_full(self, s, b)
    if out:
        origin[s] = "full"
    return out


import strew.grow._collide as C

why = Counter()


def wrap(cls, name, bad):
    f = getattr(cls, name)

    def w(self, *a, **k):
        out = f(self, *a, **k)
        if out == bad and G.get("conv"):
            G["why"] = name
        return out
    setattr(cls, name, w)


for name, bad in (("too_close_in_kind", True), ("overlaps_any", True), ("crowds_gap", True), ("lean_ok", False), ("fits_domain", False)):
    wrap(C._Collide, name, bad)
for name, bad in (("crowds_own_kind", True), ("_nudge", None)):
    wrap(P._Place, name, bad)
orig_place = P._Place.place


def place(self, s, a, k, th, reach=None):
    G["conv"] = reach is not None
    G["why"] = "?"
    out = orig_place(self, s, a, k, th, reach)
    if reach is not None and not out:
        why[G["why"]] += 1
    G["conv"] = False
    return out


P._Place.place = place
P._Place.try_larger = try_larger
P._Place.canopy_full = canopy_full
x0, y0, x1, y1 = ex.region.bounds
W, H = 3.5 * (x1 - x0), 3.5 * (y1 - y0)
out = grow(ex, region=Region.rectangle(W, H), rng=seed)
g = G["g"]
print("refused conversions by the last failing check:", dict(why))
L = int(np.argmax(g.size_level))
kn = np.asarray(out.kind_names)
xy = np.c_[out.x, out.y]
# map output rows to grower objects by position (the grower's elements in order)
el = [o for o in g.order if g.state[o] == ELEMENT]
pos = np.array([g.xy[o] for o in el])
t = cKDTree(pos)
big = xy[kn == NAMES[L]]
tb = cKDTree(big)
edge = np.minimum.reduce([xy[:, 0], W - xy[:, 0], xy[:, 1], H - xy[:, 1]])
for k in range(len(NAMES)):
    if k == L:
        continue
    r = g.reach_larger[k, L]
    idx = np.flatnonzero(kn == NAMES[k])
    d = tb.query(xy[idx])[0]
    far = idx[(d > r) & (edge[idx] > r)]
    c = Counter()
    fate = Counter()
    for q in far:
        o = el[int(t.query(xy[q])[1])]
        c[origin.get(o, "?")] += 1
        if o in stood:
            fate["large seed now " + {ELEMENT: "element", SEED: "seed"}.get(g.state[stood[o]], f"state{g.state[stood[o]]}")] += 1
    tot = Counter(origin.get(o, "?") for o in el if int(g.kind[o]) == k)
    print(f"{NAMES[k]}: {len(idx)} placed, {len(far)} beyond reach {r:.3g} of large; by origin {dict(c)}; large stand-in seeds' fate {dict(fate)}; all {dict(tot)}")

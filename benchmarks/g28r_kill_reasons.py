"""g28r: why seeds die, per kind, in one growth of a --harder row (seed 1).

Counts, per seed kind, the check of ``_Place.place`` that refused it first (too_close_in_kind,
crowds_own_kind, lean_ok, fits_domain, _nudge, crowds_gap; "overlap/nudge_open" otherwise)
and choose() returning None. Monkey-patches ``_Grower`` for the count only.

    PYTHONPATH=src python benchmarks/g28r_kill_reasons.py two_sizes 4 17,19,20
"""
import collections, sys
sys.path.insert(0, "benchmarks")
import numpy as np
from grow_variants import HARDER, _harder_suite
from strew import Region
from strew.grow import _growth, grow
G = _growth._Grower
C = collections.Counter()
state = {"in": False, "last": None}
def wrap(name, refuse_when):
    f = getattr(G, name)
    def w(self, *a, **k):
        r = f(self, *a, **k)
        if state["in"] and r == refuse_when and state["last"] is None:
            state["last"] = name
        return r
    setattr(G, name, w)
for n, rw in [("too_close_in_kind", True), ("crowds_own_kind", True), ("lean_ok", False), ("fits_domain", False), ("_nudge", None), ("crowds_gap", True)]:
    wrap(n, rw)
_place, _choose = G.place, G.choose
def place(self, s, a, k, th, reach=None):
    own = int(self.kind[s]); state["in"] = True; state["last"] = None
    ok = _place(self, s, a, k, th, reach); state["in"] = False
    if not ok:
        C[own, state["last"] or "overlap/nudge_open"] += 1
    return ok
def choose(self, s):
    r = _choose(self, s)
    if r is None: C[int(self.kind[s]), "choose_none"] += 1
    return r
G.place, G.choose = place, choose
mk = _harder_suite()
cls, i = sys.argv[1], int(sys.argv[2])
for v in [int(x) for x in sys.argv[3].split(",")]:
    ex = mk.make_exemplar(cls, rng=v, **HARDER[cls][i]); C.clear()
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1)
    print(v, sorted(C.items()))

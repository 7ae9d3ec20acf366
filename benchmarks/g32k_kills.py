"""g32k: why stick placements are refused in one growth of a --varied row (grow, fixed).

Counts the check of ``_Grower.place`` that refused each placement first (as g28r_kill_reasons)
and choose() returning None, then prints the element count and the exemplar's / output's
nearest-centre quantiles.

    PYTHONPATH=src python benchmarks/g32k_kills.py sticks:p0s21 1 [PARAM=VALUE ...]

PARAM=VALUE are GrowParams set on the grower after its setup, or (upper case) ``_growth``
constants such as THIN_RETRY=4 (None, or a float).
"""
import collections, sys
sys.path.insert(0, "benchmarks")
import numpy as np
from scipy.spatial import cKDTree
from fresh17_rows import exemplar
from _runner import fidelity_suite
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
    if hasattr(G, n):
        wrap(n, rw)
_place, _choose = G.place, G.choose
def place(self, s, a, k, th, reach=None):
    state["in"] = True; state["last"] = None
    ok = _place(self, s, a, k, th, reach); state["in"] = False
    C["ok" if ok else (state["last"] or "overlap/nudge_open")] += 1
    return ok
def choose(self, s):
    r = _choose(self, s)
    if r is None: C["choose_none"] += 1
    return r
G.place, G.choose = place, choose
cls, label = sys.argv[1].split(":")
ex = exemplar(fidelity_suite(), cls, label)
x0, y0, x1, y1 = ex.region.bounds
kw = {k: (None if v == 'None' else float(v)) for k, v in (a.split('=') for a in sys.argv[3:])}
for kk in [kk for kk in kw if kk.isupper()]:
    setattr(_growth, kk, int(kw.pop(kk)))  # module constants (THIN_RETRY=4)
_init = G.__init__
def init(self, *a, **k):
    _init(self, *a, **k)
    for kk, vv in kw.items():
        object.__setattr__(self.p, kk, vv)
G.__init__ = init
out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=int(sys.argv[2]))
print(len(out), sorted(C.items(), key=lambda t: -t[1]))
for name, a in (("ex", ex), ("out", out)):
    d = cKDTree(a.xy).query(a.xy, k=2)[0][:, 1]
    print(name, len(a), "nn q10/50/90", np.round(np.percentile(d, [10, 50, 90]), 2))

"""Helper g3s2: the canopy's conversions (try_larger) on one three_sizes row: per kind pair, the count, and
the seed's distance to its nearest larger object (in reaches) and local share ratio at canopy_local reaches.

(canopy_local, canopy_local_margin, canopy_band exist only with
benchmarks/results/g3s2_rejected_canopy_local_share.patch applied: git apply it first.)

    PYTHONPATH=src python benchmarks/g3s2_conv.py three_sizes:suite:0 1 [canopy_local=None] [off: the gate off, its shares logged]
"""
import math
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

import strew.grow._growth as G
from strew import Region
from strew.grow import grow
from strew.grow._objects import ELEMENT

kw = {}
OFF = "off" in sys.argv[3:]
for s in [a for a in sys.argv[3:] if a != "off"]:
    k, v = s.split("=")
    kw[k] = eval(v)
from dataclasses import replace

_init = G._Grower.__init__
GS = []


def _patched(self, ref, params, *a, **k):
    _init(self, ref, replace(params, **kw), *a, **k)
    GS.append(self)
    global REF
    REF = _init_ref(self, ref, params).copy()
    if OFF:
        self.canopy_radius[:] = 0.0  # the gate off; its shares kept for the log


G._Grower.__init__ = _patched
LOG = []
_try = G._Grower.try_larger


def _tl(self, s):
    k = int(self.kind[s])
    x, y = self.xy[s]
    row = self.reach_larger[k]
    fin = np.isfinite(row)
    rad = 3 * float(row[fin].max()) if fin.any() else 0.0
    n_b = np.zeros(self.n_kinds)
    for o in self.near(x, y, rad):
        if o != s and int(self.kind[o]) >= 0 and (self.xy[o][0] - x) ** 2 + (self.xy[o][1] - y) ** 2 <= rad * rad:
            n_b[int(self.kind[o])] += 1
    ok = _try(self, s)
    if ok:
        b = int(self.kind[s])
        dmin = math.inf
        for o in self.near(x, y, 4 * float(row[fin].max())):
            if o != s and int(self.kind[o]) == b:
                dmin = min(dmin, math.hypot(self.xy[o][0] - x, self.xy[o][1] - y))
        LOG.append((k, b, dmin / row[b], n_b[b] / max(n_b.sum(), 1) / REF[k, b]))
    return ok


def _init_ref(self, ref, params):
    # the reference's local shares at 3 reaches (as the gate computes them)
    from scipy.spatial import cKDTree
    ex = self.ex if hasattr(self, "ex") else None
    return self.canopy_share if np.isfinite(self.canopy_share).any() else np.ones((self.n_kinds, self.n_kinds))


G._Grower.try_larger = _tl
mk = _harder_suite()
cls, i, v = sys.argv[1].split(":")
ex = mk.make_exemplar(cls, rng=int(v)) if i == "suite" else mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
x0, y0, x1, y1 = ex.region.bounds
out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=int(sys.argv[2]))
g = GS[0]
print("kinds", list(np.asarray(out.kind_names)[:0]), "reach_larger / l:\n", np.round(g.reach_larger / g.l, 2))
names = {i: n for i, n in enumerate(getattr(g, "kind_names", []) or [])}
L = np.array(LOG) if LOG else np.zeros((0, 4))
print("canopy_share", np.round(g.canopy_share, 3), "radius/l", np.round(g.canopy_radius / g.l, 2))
print("conversions", len(L), "elements", len(out), "l", round(g.l, 2))
for (a, b) in sorted({(int(r[0]), int(r[1])) for r in L}):
    m = (L[:, 0] == a) & (L[:, 1] == b)
    d = L[m, 2]
    sh = L[m, 3]
    print(f" {a}->{b}: {m.sum()}  dnear/reach q10,50,90 {np.round(np.quantile(d[np.isfinite(d)], [.1, .5, .9]), 2) if np.isfinite(d).any() else '-'} inf {np.isinf(d).sum()}"
          f"  share/ref q10,50,90 {np.round(np.quantile(sh, [.1, .5, .9]), 2)}")

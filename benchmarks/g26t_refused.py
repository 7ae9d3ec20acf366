"""Helper g26t: where the canopy's refused conversions leave small stones beyond reach.

For one --harder three_sizes row and seed (grow, fixed mode): for each seed whose
conversion to the large kind (``_Place.try_larger``) was refused or gated and which was then
placed as its own kind beyond ``reach_larger[k, large]`` of every large element/seed, the
distance to the nearest large element at that time (units: reach), and the reference's
pair_close[large, large], reach, and large-large nn deciles.

    PYTHONPATH=src python benchmarks/g26t_refused.py three_sizes:6:13 1 [param=value ...]
"""
import sys
from collections import Counter
from dataclasses import replace

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite
from scipy.spatial import cKDTree

import strew.grow._growth as G
import strew.grow._place as P
from strew import Region
from strew.grow import grow
from strew.grow._objects import ELEMENT
from strew.metrics import fidelity

cls_, i, v = sys.argv[1].split(":")
seed = int(sys.argv[2])
kw = {k: eval(x) for k, x in (a.split("=", 1) for a in sys.argv[3:])}
if kw:
    _init = G._Grower.__init__

    def _patched(self, ref, params, *a, **k):
        _init(self, ref, replace(params, **kw), *a, **k)

    G._Grower.__init__ = _patched
ex = mk = _harder_suite().make_exemplar(cls_, rng=int(v), **HARDER[cls_][int(i)])
names = list(ex.kinds)
info = {}
orig_try = P._Place.try_larger


def try_larger(self, s):
    info["g"] = self
    L = int(np.argmax(self.size_level))
    k = int(self.kind[s])
    miss = k >= 0 and k != L and L in self.missing_larger(s)
    out = orig_try(self, s)
    if miss and not out:
        x, y = self.xy[s]
        d = min((np.hypot(self.xy[o][0] - x, self.xy[o][1] - y) for o in self.near(x, y, 4 * self.reach_larger[k, L])
                 if self.state[o] == ELEMENT and int(self.kind[o]) == L), default=np.inf)
        info.setdefault("ref", []).append((s, k, d / self.reach_larger[k, L]))
    return out


P._Place.try_larger = try_larger
x0, y0, x1, y1 = ex.region.bounds
W, H = 3.5 * (x1 - x0), 3.5 * (y1 - y0)
out = grow(ex, region=Region.rectangle(W, H), rng=seed)
g = info["g"]
L = int(np.argmax(g.size_level))
rep = fidelity(ex, out, eq5=False, local=False)
print(sys.argv[1:], "faithful", rep.faithful, [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed])
exy = np.c_[ex.x, ex.y]
ek = np.asarray(ex.kind_names)
lxy = exy[ek == names[L]]
dl = cKDTree(lxy).query(lxy, k=2)[0][:, 1]
print("ref counts", Counter(ek.tolist()), "pair_close[L,L]", round(float(g.pair_close[L, L]), 2), "reach", np.round(g.reach_larger[:, L], 2),
      "l", round(g.l, 2))
print("ref L-L nn deciles", np.round(np.quantile(dl, np.linspace(0.1, 0.9, 9)), 1))
kn = np.asarray(out.kind_names)
xy = np.c_[out.x, out.y]
big = xy[kn == names[L]]
tb = cKDTree(big)
edge = np.minimum.reduce([xy[:, 0], W - xy[:, 0], xy[:, 1] - 0, H - xy[:, 1]])
dlo = tb.query(big, k=2)[0][:, 1]
print("out L-L nn deciles", np.round(np.quantile(dlo, np.linspace(0.1, 0.9, 9)), 1), "n large", len(big))
final = {s: None for s in g.order if g.state[s] == ELEMENT}
ref = [(s, k, d) for s, k, d in info.get("ref", []) if s in final and int(g.kind[s]) == k]
for k in range(len(names)):
    if k == L:
        continue
    r = g.reach_larger[k, L]
    rr = [d for s, kk, d in ref if kk == k]
    idx = np.flatnonzero(kn == names[k])
    dfin = tb.query(xy[idx])[0]
    far = (dfin > r) & (edge[idx] > r)
    print(f"{names[k]}: refused-then-placed {len(rr)}; nearest large at refusal / reach deciles", np.round(np.quantile(rr, np.linspace(0.1, 0.9, 9)), 2) if rr else "-",
          f"; final beyond reach {far.sum()} of {len(idx)}; their nearest large / reach deciles",
          np.round(np.quantile(dfin[far] / r, np.linspace(0.1, 0.9, 9)), 2) if far.any() else "-")

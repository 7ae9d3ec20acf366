"""g29h: how close a stone placement refused by too_close_in_kind is to the stone that refuses it.

For one --harder row (method seed 1), wraps ``_Grower.too_close_in_kind`` on placing and, for every
refusal, records the distance d from the placement to the nearest element of each kind, over the
exemplar's own smallest same-kind distance (lo) and median (med); also the bound pair_close. Prints
the exemplar's own stone-stone and pebble-pebble nearest distances for comparison, and where the seed
was before ``_fit_position`` moved it (the seed's proposal) and how far the fit moved it.

    PYTHONPATH=src python benchmarks/g29h_close_probe.py two_sizes 4 19
"""
import collections, sys
sys.path.insert(0, "benchmarks")
import numpy as np
from scipy.spatial import cKDTree
from grow_variants import HARDER, _harder_suite
from strew import Region
from strew.grow import _growth, grow
G = _growth._Grower
rec = []
pre = {}
_fit = G._fit_position
def fit(self, s, *a, **k):
    pre["xy"] = tuple(self.xy[s])
    return _fit(self, s, *a, **k)
G._fit_position = fit
_place = G.place
def place(self, s, a, k, th, reach=None):
    pre["xy"] = tuple(self.xy[s]); pre["s"] = s
    return _place(self, s, a, k, th, reach)
G.place = place
_tc = G.too_close_in_kind
def tc(self, x, y, kind, s, states=(_growth.SEED, _growth.ELEMENT), placing=False):
    r = _tc(self, x, y, kind, s, states, placing)
    if placing and r and states == (_growth.ELEMENT,):
        n = len(self.xy)
        st = np.asarray(self.state[:n]); kk = np.asarray(self.kind[:n]); XY = np.asarray(self.xy[:n], dtype=float)
        d = [np.min(np.hypot(*(XY[(st == _growth.ELEMENT) & (kk == k2)] - (x, y)).T), initial=np.inf) for k2 in range(self.n_kinds)]
        p0 = pre.get("xy")
        rec.append((kind, d, float(np.hypot(x - p0[0], y - p0[1])), self))
    return r
G.too_close_in_kind = tc
mk = _harder_suite()
cls, i = sys.argv[1], int(sys.argv[2])
for v in [int(x) for x in sys.argv[3].split(",")]:
    ex = mk.make_exemplar(cls, rng=v, **HARDER[cls][i]); rec.clear()
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1)
    print("draw", v, "kinds", ex.kinds, "refusals", len(rec))
    if not rec:
        continue
    g = rec[0][3]
    print(" pair_close", np.round(g.pair_close, 4).tolist(), "pair_short", np.round(g.pair_short, 4).tolist(), "l", round(g.l, 4), "l_short", round(g.l_short, 4))
    los = {}
    for k in range(g.n_kinds):
        for k2 in range(g.n_kinds):
            a = np.flatnonzero(g.ex_kind == k); b = np.flatnonzero(g.ex_kind == k2)
            if len(a) < 2 or len(b) < 2:
                continue
            d, q = cKDTree(ex.xy[b]).query(ex.xy[a], k=2)
            dn = np.where(b[q[:, 0]] == a, d[:, 1], d[:, 0])
            los[k, k2] = dn.min()
            print(f" exemplar nn[{k}>{k2}]: n {len(a)} min {dn.min():.4f} q10 {np.quantile(dn, .1):.4f} med {np.median(dn):.4f}; pair_close {g.pair_close[k, k2]:.4f}")
    for kind in range(g.n_kinds):
        R = [r for r in rec if r[0] == kind]
        if not R:
            continue
        D = np.array([r[1] for r in R]); M = np.array([r[2] for r in R])
        print(f" refused kind {kind}: {len(R)}; fit moved median {np.median(M):.4f}")
        for k2 in range(g.n_kinds):
            lo = los.get((kind, k2))
            dd = D[:, k2]
            hit = dd < g.pair_close[kind, k2]
            print(f"   by kind {k2}: {hit.sum()} within bound; d/lo of those q10 {np.quantile(dd[hit]/lo, .1) if hit.any() else 0:.3f} med {np.median(dd[hit]/lo) if hit.any() else 0:.3f} q90 {np.quantile(dd[hit]/lo, .9) if hit.any() else 0:.3f}; bound/lo {g.pair_close[kind, k2]/lo:.3f}")

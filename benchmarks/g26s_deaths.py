"""Helper g26s: why seeds die inside a fixed-mode lattice (scales EDGE p2, variant 18):
each killed seed's reason (the first test of ``_Place.place`` that refused it, or no
match), which killed interior seeds left a vacancy (no element within 6.5 of the seed's
place at the end), the room the hole had when the seed died, and how many of the judge's
regularity misses lie within 1.3 s of a vacancy.

    PYTHONPATH=src python benchmarks/g26s_deaths.py [CLASS:LABEL=scales:p2s18] [SEED=1]
"""
import collections
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite
from fresh17_rows import exemplar
from scipy.spatial import cKDTree

from strew import Region, _fidelity
from strew.grow import _growth, grow
from strew.grow._objects import ELEMENT

spec = sys.argv[1] if len(sys.argv) > 1 else "scales:p2s18"
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
cls, label = spec.split(":")
ex = exemplar(fidelity_suite(), cls, label)
G = _growth._Grower
last = {}
names = ["too_close_in_kind", "crowds_own_kind", "lean_ok", "fits_domain", "overlaps_any", "_nudge", "crowds_gap"]
fail_when = {"too_close_in_kind": True, "crowds_own_kind": True, "lean_ok": False, "fits_domain": False,
             "overlaps_any": True, "_nudge": None, "crowds_gap": True}
for nm in names:
    f = getattr(G, nm)

    def wrap(self, *a, _f=f, _nm=nm, **k):
        r = _f(self, *a, **k)
        if (r is None and fail_when[_nm] is None) or (fail_when[_nm] is not None and bool(r) == fail_when[_nm]):
            last.setdefault("why", _nm)
        return r
    setattr(G, nm, wrap)
reasons = {}
pre = {}
oplace, ochoose, okill = G.place, G.choose, G.kill
grower = {}


def place(self, s, *a, **k):
    grower["g"] = self
    last.clear()
    pre[s] = tuple(self.xy[s])
    ok = oplace(self, s, *a, **k)
    if not ok:
        reasons[s] = last.get("why", "other")
    return ok


def choose(self, s):
    r = ochoose(self, s)
    if r is None:
        reasons[s] = "no match"
    return r


killed = {}


def kill(self, s):
    grower["g"] = self
    el = [o for o in range(len(self.xy)) if self.state[o] == ELEMENT]
    dn = min((np.hypot(self.xy[o][0] - self.xy[s][0], self.xy[o][1] - self.xy[s][1]) for o in el), default=np.inf)
    # the room the hole has: the largest nearest-element distance over points within 8 of the seed
    exy = np.array([self.xy[o] for o in el]).reshape(-1, 2)
    gx, gy = np.meshgrid(np.linspace(-8, 8, 33), np.linspace(-8, 8, 33))
    pts = np.c_[gx.ravel() + self.xy[s][0], gy.ravel() + self.xy[s][1]]
    dq = cKDTree(exy).query(pts)[0] if len(exy) else np.full(len(pts), np.inf)
    room = float(dq.max())
    best = pts[int(np.argmax(dq))]
    p0 = pre.get(s, self.xy[s])
    dpre = float(cKDTree(exy).query(np.array(p0))[0]) if len(exy) else np.inf
    room = (room, dpre, float(np.hypot(*(best - np.array(self.xy[s])))), float(np.hypot(*(np.array(p0) - np.array(self.xy[s])))))
    killed[s] = (tuple(self.xy[s]), reasons.get(s, "kill (domain/other)"), sum(self.state[o] == ELEMENT for o in self.adj[s]), dn, room)
    return okill(self, s)


G.place, G.choose, G.kill = place, choose, kill
extra = set()  # seeds made by Fig. 6e (an extra seed on a long edge, _ring_edges)
orings = G._ring_edges


def ring_edges(self, *a, **k):
    n0 = len(self.xy)
    r = orings(self, *a, **k)
    extra.update(range(n0, len(self.xy)))
    return r


G._ring_edges = ring_edges
x0, y0, x1, y1 = ex.region.bounds
W, H = 3.5 * (x1 - x0), 3.5 * (y1 - y0)
out = grow(ex, region=Region.rectangle(W, H), rng=seed)
g = grower["g"]
xy = np.array([g.xy[i] for i in range(len(g.xy)) if g.state[i] == ELEMENT])
t = cKDTree(xy)
m = 25.0
print(f"{spec} seed {seed}: {len(xy)} elements, {len(killed)} seeds killed")
allr = collections.Counter(r for _, r, _, _, _ in killed.values())
print("   all killed by reason:", dict(allr))
inner = {s: v for s, v in killed.items() if m < v[0][0] < W - m and m < v[0][1] < H - m}
d, _ = t.query(np.array([v[0] for v in inner.values()]).reshape(-1, 2))
vac = {s: v for (s, v), dd in zip(inner.items(), d) if dd > 6.5}
print(f"   interior killed: {len(inner)} {dict(collections.Counter(r for _, r, _, _, _ in inner.values()))}")
print(f"   pair_close {np.round(g.pair_close, 2).tolist()} exemplar least distance {cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1].min():.2f}")
print("   vacancies: nearest element at death (q10/50/90)", np.round(np.quantile([v[3] for v in vac.values()], [0.1, 0.5, 0.9]), 2).tolist() if vac else [])
print("   vacancies at death: (room: the largest nearest-element distance within 8 of the seed, nearest element "
      "from the seed before place's fit, from after, room point's distance from the seed, fit's move)")
for v in sorted(vac.values(), key=lambda v: v[4][0]):
    print("      ", v[1], "placed nb", v[2], np.round([v[4][0], v[4][1], v[3], v[4][2], v[4][3]], 1).tolist())
print(f"   interior killed with no element within 6.5 at the end (vacancies): {len(vac)} "
      f"{dict(collections.Counter(r for _, r, _, _, _ in vac.values()))}; placed neighbours at death "
      f"{dict(collections.Counter(n for _, _, n, _, _ in vac.values()))}")
print(f"   Fig. 6e extra seeds made: {len(extra)}; placed {sum(1 for i in extra if i < len(g.state) and g.state[i] == ELEMENT)}; "
      f"among the interior killed {sum(1 for q in inner if q in extra)} of {len(inner)}, among the vacancies {sum(1 for q in vac if q in extra)} of {len(vac)}")
calls = []
orig_lm = _fidelity._lattice_match


def spy(sm, tree, s_, template):
    calls.append((sm, tree, s_, template))
    return orig_lm(sm, tree, s_, template)


_fidelity._lattice_match = spy
rep = _fidelity.fidelity(ex, out, eq5=False, local=False)
sm, tree, s_, tpl = calls[-1]
import shapely

edge = shapely.distance(sm.region.boundary, shapely.points(sm.xy))
inn = np.flatnonzero((edge >= _fidelity.LATTICE_REACH * s_ + 0.5 * s_) & shapely.contains_xy(sm.window, sm.xy[:, 0], sm.xy[:, 1]))
ok = orig_lm(sm, tree, s_, tpl)[inn]
bad = sm.xy[inn[~ok]]
vxy = np.array([v[0] for v in vac.values()]).reshape(-1, 2)
near_vac = int(np.sum(cKDTree(vxy).query(bad)[0] <= _fidelity.LATTICE_REACH * s_)) if len(vxy) and len(bad) else 0
print(f"   judge: regularity {rep.metrics['regularity'].result:.4f}, {len(bad)} of {len(inn)} interior elements miss the pattern; "
      f"{near_vac} of them within 1.3 s = {_fidelity.LATTICE_REACH * s_:.1f} of a vacancy")

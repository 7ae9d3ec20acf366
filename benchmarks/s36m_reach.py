"""Helper s36m (issue 13 point 1): which exemplar elements growth can copy, and how often.

    PYTHONPATH=src:benchmarks python benchmarks/s36m_reach.py CLASS:H:V KIND

For each exemplar element of KIND: its depth (distance to the domain's edge), parent and parent
distance, and the number of interior candidates c (Prepared.interior) whose n(c) holds it (within
r-bar of c, and within n(c)'s full reach), and of those, how many hold its parent too (or are its
parent): the candidates that can copy it without making it an orphan (_kernels.generate_proposals).
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import new_state

name, i, v = sys.argv[1].split(":")
kind_name = sys.argv[2]
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
x0, y0, x1, y1 = ex.region.bounds
st = new_state(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1)
p = st.prep
kn = np.asarray(ex.kind_names)
depth = shapely.distance(p.domains[0].exterior, shapely.points(p.pos))
inter = np.zeros(len(p.pos), bool)
inter[np.concatenate(p.interior)] = True
print("interior per kind", {k: int(np.sum(inter & (kn == k))) for k in sorted(set(kn))}, "rbar", float(np.median(p.rbar)))
hold = np.zeros(len(p.pos), int)
hold_r = np.zeros(len(p.pos), int)
hold_p = np.zeros(len(p.pos), int)
hold_pr = np.zeros(len(p.pos), int)
for c in np.flatnonzero(inter):
    seg = slice(p.nb_ptr[c], p.nb_ptr[c + 1])
    nb = p.nb_idx[seg]
    dd = np.hypot(*p.nb_off[seg].T)
    s = set(nb.tolist())
    for e, d in zip(nb, dd):
        par = p.parent[e]
        ok = par == -1 or par == c or (par >= 0 and par in s)
        hold[e] += 1
        hold_p[e] += ok
        if d <= p.rbar[c]:
            hold_r[e] += 1
            hold_pr[e] += ok
ids = np.flatnonzero(kn == kind_name)
print("idx depth parent pd | held(reach) held+parent | held(rbar) held+parent")
for e in ids[np.argsort(depth[ids])]:
    par = p.parent[e]
    pd = np.hypot(*(p.pos[par] - p.pos[e])) if par >= 0 else np.nan
    print(f"{e:4d} {depth[e]:6.1f} {par:4d} {pd:6.1f} | {hold[e]:3d} {hold_p[e]:3d} | {hold_r[e]:3d} {hold_pr[e]:3d}")
for k in sorted(set(kn)):
    m = kn == k
    print(f"{k}: mean held+parent (reach) {hold_p[m].mean():.2f}  (rbar) {hold_pr[m].mean():.2f}  held {hold[m].mean():.2f}")

"""Helper syc16: which exemplar discs synth's growth copies on a clusters --harder set (state before fill_holes):
per exemplar disc its ring size (dots nearest it) and how many output discs copy it; the copies per ring size
against the exemplar's discs per ring size (issue 13 point 1, clusters h3s9).

    PYTHONPATH=TREE/src:benchmarks python benchmarks/syc16_usage.py 3:9:1
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, "benchmarks")
from grow_variants import _harder_suite
from synth_variants import _harder

import strew.synth._grow as G
from strew import Region
from strew.synth import synthesize

REC = {}
_fh = G.fill_holes


def fh(state, *a, **k):
    REC["src"] = state.src[: state.n].copy()
    REC["prep"] = state.prep
    REC["pos"] = state.pos[: state.n].copy()
    return _fh(state, *a, **k)


G.fill_holes = fh
h, v, seed = map(int, sys.argv[1].split(":"))
ex = _harder_suite().make_exemplar("clusters", rng=v, **_harder()["clusters"][h])
x0, y0, x1, y1 = ex.region.bounds
out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
p = REC["prep"]
di, do = ex.kinds.index("disc"), ex.kinds.index("dot")
vis = ~p.void
dids = np.flatnonzero((p.kind == di) & vis)
dots = np.flatnonzero((p.kind == do) & vis)
own = dids[cKDTree(p.pos[dids]).query(p.pos[dots])[1]]
ringsz = np.bincount(own, minlength=len(p.kind))
src = REC["src"]
use = np.bincount(src[p.kind[src] == di], minlength=len(p.kind))
sel = p.selected_elements
print(f"h{h}s{v} seed {seed}: exemplar discs {len(dids)}, selected {int(sel[dids].sum())}; growth's discs {int(use.sum())}")
for r in range(2, 8):
    m = dids[ringsz[dids] == r]
    print(f"  ring {r}: exemplar discs {len(m)} copies {int(use[m].sum())} (per disc {use[m].sum() / max(len(m), 1):.1f}); interior cand (parent!=-3, selected) {int(np.sum(sel[m]))}")
top = dids[np.argsort(-use[dids])][:10]
print("  most copied discs (uses, ring):", [(int(use[t]), int(ringsz[t])) for t in top])
print("  copies per disc quantiles 0/25/50/75/100:", np.quantile(use[dids], [0, .25, .5, .75, 1]).tolist())
# output rings before fill_holes: each visible dot to its nearest disc; is the dot's exemplar parent the disc's source?
pos, vs = REC["pos"], ~p.void[src]
od = np.flatnonzero(vs & (p.kind[src] == di))
oo = np.flatnonzero(vs & (p.kind[src] == do))
near = od[cKDTree(pos[od]).query(pos[oo])[1]]
mine = p.parent[src[oo]] == src[near]
cnt = np.bincount(np.searchsorted(od, near), minlength=len(od))
foreign = np.bincount(np.searchsorted(od, near[~mine]), minlength=len(od))
srcring = ringsz[src[od]]
print(f"  output dots {len(oo)}: whose exemplar parent is their nearest disc's source {mine.mean():.3f}")
for r in (4, 5, 6):
    m = cnt == r
    print(f"  output discs with {r} dots: {int(m.sum())}; their source ring sizes {np.bincount(srcring[m], minlength=8)[:8].tolist()}; with a foreign dot {int(np.sum(foreign[m] > 0))}")
print(f"  exemplar dots whose parent is their nearest disc: {np.mean(p.parent[dots] == own):.3f}")
fp = p.parent[src[oo[~mine]]]
print(f"  foreign dots' exemplar parent: none (-1) {np.mean(fp == -1):.3f}, frame-cut (-3) {np.mean(fp == -3):.3f}, another disc {np.mean(fp >= 0):.3f}")
import shapely
dom = p.domains[0]
fd = shapely.distance(dom.boundary, shapely.points(p.pos[dids]))
for lo, hi in ((0, 20), (20, 40), (40, 1e9)):
    m = (fd >= lo) & (fd < hi)
    for r in (4, 5):
        mm = m & (ringsz[dids] == r)
        print(f"  discs {lo}-{hi} from the frame, ring {r}: {int(mm.sum())} discs, copies per disc {use[dids[mm]].sum() / max(mm.sum(), 1):.1f}")
# dots whose own copy's disc is missing: no output disc copied from the dot's exemplar parent within 1.2x the exemplar offset (+1)
par = p.parent[src[oo]]
pd = np.hypot(*(p.pos[src[oo]] - p.pos[np.maximum(par, 0)]).T)
tree = cKDTree(pos[od])
orph = 0
for j, q in enumerate(oo):
    cand = od[tree.query_ball_point(pos[q], 1.2 * pd[j] + 1.0)]
    orph += not np.any(src[cand] == par[j])
print(f"  dots whose exemplar parent's copy is not beside them (orphans): {orph} of {len(oo)} ({orph / len(oo):.3f})")
# counterfactual (measurement only): the final output less those orphan dots (still standing at the end), and less as
# many dots drawn at random, scored by the fidelity metric
from strew.metrics import fidelity

orph_pos = []
for j, q in enumerate(oo):
    cand = od[tree.query_ball_point(pos[q], 1.2 * pd[j] + 1.0)]
    if not np.any(src[cand] == par[j]):
        orph_pos.append(pos[q])
hit = cKDTree(out.xy).query(np.array(orph_pos))
drop = hit[1][hit[0] < 1e-6]
keep = np.ones(len(out), bool); keep[drop] = False
dotsi = np.flatnonzero(out.kind == do)
keep2 = np.ones(len(out), bool); keep2[np.random.default_rng(0).choice(dotsi, len(drop), replace=False)] = False
for lab, arr in (("as is", out), (f"less {len(drop)} orphans", out.select(keep)), (f"less {len(drop)} random dots", out.select(keep2))):
    m = fidelity(ex, arr, eq5=False, local=False).metrics
    print(f"  {lab}: nn[dot>dot] {m['nn[dot>dot]'].value:.4f} density[dot] {m['density[dot]'].value:.3f} nn[disc>dot] {m['nn[disc>dot]'].value:.4f}")
# counterfactual: only enough orphans to bring dots to the exemplar's density (density[dot] is |ratio - 1|, ratio > 1
# here), those nearest another dot first, against as many random dots
n_dot = len(dotsi)
k = int(round(n_dot * (1 - 1 / (1 + fidelity(ex, out, eq5=False, local=False).metrics["density[dot]"].value))))
ddist = cKDTree(out.xy[dotsi]).query(out.xy[drop], 2)[0][:, 1]
for lab, rm in ((f"less {k} closest orphans", drop[np.argsort(ddist)[:k]]), (f"less {k} random dots", np.random.default_rng(0).choice(dotsi, k, replace=False))):
    kk = np.ones(len(out), bool); kk[rm] = False
    m = fidelity(ex, out.select(kk), eq5=False, local=False).metrics
    print(f"  {lab}: nn[dot>dot] {m['nn[dot>dot]'].value:.4f} density[dot] {m['density[dot]'].value:.3f} nn[disc>dot] {m['nn[disc>dot]'].value:.4f} (tol {m['nn[dot>dot]'].tolerance:.3f})")

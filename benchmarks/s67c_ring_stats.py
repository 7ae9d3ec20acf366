"""s67c: the groups ``_prepare.ring_caps`` looks at (children of a larger size class, per
(kind, parent kind, exemplar)), with the s65c gates (>= 3 members, share of their kind,
distance cv) and the guard's statistic: mean children per parent among the group's parents
(every parent in the group holds >= 1 child of it), with the median, the largest, and the
mean over parents whose ring the exemplar's frame leaves whole (no child cropped away).
Prints every group the s65c patch caps ("CAP") and every group that nearly does
("near": cv <= 2 x RING_CAP_CV and share >= RING_CAP_SHARE / 2); exemplars only.

    PYTHONPATH=src:benchmarks python benchmarks/s67c_ring_stats.py varied clusters,rings 7-40
    PYTHONPATH=src:benchmarks python benchmarks/s67c_ring_stats.py harder three_sizes,clusters 7-40
"""
import sys

import numpy as np
import shapely

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import new_state
from strew.synth._prepare import RING_CAP_CV, RING_CAP_SHARE

which, classes, seeds = sys.argv[1], sys.argv[2].split(","), _variants.ints(sys.argv[3])
assert max(seeds) <= 40, "held-out variant seeds"
mk = fidelity_suite() if which == "varied" else _harder_suite()
for cls in classes:
    if which == "varied":
        nsets = len(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))
        labels = [f"v{s}" for s in seeds] + [f"p{i}s{s}" for i in range(nsets) for s in seeds]
    else:
        labels = [f"h{i}s{s}" for i in range(len(_harder().get(cls, []))) for s in seeds]
    for lab in labels:
        if lab.startswith("h"):
            i, _, v = lab[1:].partition("s")
            ex = mk.make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
        else:
            ex = exemplar(mk, cls, lab)
        prep = new_state(ex, Region.rectangle(50, 50), rng=1).prep
        has = np.flatnonzero((prep.parent >= 0) & ~prep.void)
        has = has[prep.size_class[prep.parent[has]] != prep.size_class[has]]
        if not len(has):
            continue
        par = prep.parent[has]
        d = np.hypot(*(prep.pos[has] - prep.pos[par]).T)
        pair = np.c_[prep.skind[has], prep.skind[par], prep.source[has]]
        _, inv = np.unique(pair, axis=0, return_inverse=True)
        inv = inv.ravel()
        names = np.asarray(ex.kind_names)
        # parents whose ring the frame may cut (as ring_caps' cap: nearer the domain's
        # edge than their farthest child plus its rc, or 1.2 x the median child distance)
        kids = np.flatnonzero(prep.parent >= 0)
        dist = np.hypot(*(prep.pos[kids] - prep.pos[prep.parent[kids]]).T)
        far = np.zeros(len(prep.kind))
        np.maximum.at(far, prep.parent[kids], dist + prep.rc[kids])
        cut = np.zeros(len(prep.kind), bool)
        for s, dom in enumerate(prep.domains):
            ids = np.flatnonzero(prep.source == s)
            own = prep.source[kids] == s
            if len(ids) == 0 or dom is None:
                continue
            r = np.maximum(far[ids], 1.2 * np.median(dist[own]) if own.any() else 0.0)
            cut[ids[shapely.distance(shapely.boundary(dom), shapely.points(prep.pos[ids])) < r]] = True
        for g in np.unique(inv):
            m = inv == g
            c0 = has[m][0]
            kin = np.sum((prep.kind == prep.kind[c0]) & (prep.source == prep.source[c0]) & ~prep.void)
            cv = d[m].std() / d[m].mean()
            share = m.sum() / kin
            cap = m.sum() >= 3 and share >= RING_CAP_SHARE and cv <= RING_CAP_CV
            near = m.sum() >= 3 and share >= RING_CAP_SHARE / 2 and cv <= 2 * RING_CAP_CV
            if not (cap or near):
                continue
            up, cnt = np.unique(par[m], return_counts=True)
            hist = np.bincount(cnt)
            w = cnt[~cut[up]]
            whole = f"whole {len(w)} wmean {w.mean():.2f} wmedian {np.median(w):.1f} wmin {w.min()}" if len(w) else "whole 0 wmean nan wmedian nan wmin 0"
            print(f"{which} {cls} {lab} {names[c0]}<{names[par[m][0]]} {'CAP ' if cap else 'near'} members {int(m.sum())} share {share:.2f} "
                  f"cv {cv:.3f} parents {len(cnt)} mean {cnt.mean():.2f} median {np.median(cnt):.1f} max {cnt.max()} hist {hist.tolist()} {whole}", flush=True)

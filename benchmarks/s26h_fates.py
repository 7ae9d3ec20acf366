"""Helper s26h (issue 13 point 1): fates of growth's proposals per kind for one --harder synth row.

Counts, over grow()'s iterations, per kind: proposals that passed the static checks (overlap free
space, in domain), those blocked by an element of O that does not yield (``_split_conflicts``),
those offered to ``place_proposals`` and those placed, and elements evicted (yielded) per kind; then
the kind counts right after growth (before the fill passes).

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s26h_fates.py CLASS:H:V:SEED [--set G.NAME=VALUE] [--yield-window N]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from synth_variants import _harder

import strew.synth._grow as G
import strew.synth._kernels as K
from strew import Region
from strew.synth import synthesize

argv = sys.argv[1:]
yw = None
while "--set" in argv:
    j = argv.index("--set")
    lhs, val = argv[j + 1].split("=")
    nm = lhs.split(".", 1)[1]
    setattr(G, nm, type(getattr(G, nm))(val))
    del argv[j : j + 2]
if "--yield-window" in argv:
    j = argv.index("--yield-window")
    yw = int(argv[j + 1])
    del argv[j : j + 2]
name, i, v, seed = argv[0].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
S = {}
st = {"blocked": None, "offered": None, "placed": None, "evicted": None, "state": None}
ORIG_SPLIT, ORIG_PLACE, ORIG_EVICT, ORIG_CAR = G._split_conflicts, K.place_proposals, G._evict, G._complete_anchor_rings


def add(key, v):
    st[key] = v if st.get(key) is None else st[key] + v


def split(state, pts, src, visible_only):
    st["state"] = state
    hard = ORIG_SPLIT(state, pts, src, visible_only)
    nk = int(state.prep.skind.max()) + 1
    add("tested", np.bincount(state.prep.skind[src], minlength=nk))
    add("blocked", np.bincount(state.prep.skind[src[hard]], minlength=nk))
    # who blocks: per (query kind, blocking kind, blocker yields-but-not-to-this) among hard-blocked
    prep = state.prep
    osrc = state.src
    vis = ~prep.void[osrc] if visible_only else np.ones(state.n, bool)
    opos, osrc2 = state.pos[vis], osrc[vis]
    oy = (state.horizon & (state._born[: state.n] >= G._yield_from(state)))[vis]
    owed = G.owed_classes(state)
    from scipy.spatial import cKDTree
    tr = cKDTree(opos)
    rmax = float(prep.rc.max())
    tab = st.setdefault("blockers", np.zeros((nk, nk, 2), np.int64))
    for i in np.flatnonzero(hard):
        q = src[i]
        qc = prep.size_class[q] if owed[prep.size_class[q]] else 0
        for j in tr.query_ball_point(pts[i], prep.rc[q] + rmax + float(prep.min_dist.max())):
            o = osrc2[j]
            lim = max(prep.rc[q] + prep.rc[o], prep.min_dist[prep.skind[q], prep.skind[o]])
            if np.sum((pts[i] - opos[j]) ** 2) < lim * lim and not (oy[j] and prep.size_class[o] < qc):
                tab[prep.skind[q], prep.skind[o], int(state.horizon[vis][j])] += 1
    return hard


LAST = {}


def place(costs, slack, out_ptr, count, ppos, pr, psk, md, ok, *a):
    placed, s_ok = ORIG_PLACE(costs, slack, out_ptr, count, ppos, pr, psk, md, ok, *a)
    nk = len(md)
    add("offered", np.bincount(psk[ok], minlength=nk))
    add("placed", np.bincount(psk[placed], minlength=nk))
    return placed, s_ok


def evict(state, new, *, voids):
    before = np.bincount(state.prep.skind[state.src], minlength=int(state.prep.skind.max()) + 1)
    ORIG_EVICT(state, new, voids=voids)
    after = np.bincount(state.prep.skind[state.src], minlength=len(before))
    add("evicted", before - after)


def car(state, *a, **k):
    nk = int(state.prep.skind.max()) + 1
    print("after growth counts per kind", np.bincount(state.prep.skind[state.src[~state.prep.void[state.src]]], minlength=nk))
    print("iterations", state.iterations, "owed now", G.owed_classes(state))
    return ORIG_CAR(state, *a, **k)


G._split_conflicts, K.place_proposals, G._evict, G._complete_anchor_rings = split, place, evict, car
x0, y0, x1, y1 = ex.region.bounds
kw = {} if yw is None else {"yield_window": yw}
out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=int(seed), measure=False, **kw)
print("exemplar kinds", ex.kind_names if hasattr(ex, "kind_names") else None, "counts", ex.counts() if callable(getattr(ex, "counts", None)) else None)
for key in ("tested", "blocked", "offered", "placed", "evicted"):
    print(f"{key:8s}", st.get(key))
print("blockers [query kind][blocker kind][old/horizon]:")
print(st.get("blockers"))
print("final", out.counts() if callable(getattr(out, "counts", None)) else None)

"""Helper s29m (issue 13 point 1, three_sizes h6): WHICH element of O refuses the copies of
one size class in synth's growth (§5.1's collision test, ``_split_conflicts``), extending
s28h_funnel.py's "refused by O" tally. For each refused proposal of class KIND the nearest
violating O element is named: the proposal's own seed (the copy's centre), or another
element, by size class and by age (born this iteration's window or earlier), with the
distance over the bound ``max(rc_p + rc_q, min_dist)``; and the bound against the
exemplar's own closest pairs of those classes.

    PYTHONPATH=src:benchmarks python benchmarks/s29m_blockers.py CLASS:H:V:SEEDS [KIND] [NAME=VALUE ...]

KIND is the size class index (default 1: medium of three_sizes).
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from scipy.spatial import cKDTree
from synth_variants import _harder, run

import strew.synth._grow as G
import strew.synth._kernels as K

args = sys.argv[2:]
KIND = 1
if args and "=" not in args[0]:
    KIND = int(args.pop(0))
for kv in args:
    nm, val = kv.split("=")
    setattr(G, nm, eval(val))
    print("set", nm, val)
name, i, v, seeds = sys.argv[1].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
S = len(ex.kinds)
LAST = {}
REC = []
DEL = []
_gen, _split = K.generate_proposals, G._split_conflicts


def gen(*a):
    r = _gen(*a)
    seed_pos, cands, out_ptr = a[0], a[6], a[13]
    kc = max(cands.shape[1], 1)
    so = np.repeat(np.arange(len(seed_pos) * kc) // kc, np.diff(out_ptr))
    LAST["seed_pos"] = np.asarray(seed_pos).copy()
    LAST["ppos"] = r[2].copy()
    LAST["seed_of"] = so
    LAST["cid"] = np.repeat(np.arange(len(out_ptr) - 1), np.diff(out_ptr))
    LAST["ex"] = r[1].copy()
    LAST["key"] = {tuple(p): k for k, p in enumerate(r[2])}
    return r


def split(state, pts, src, visible_only):
    hard = _split(state, pts, src, visible_only)
    prep = state.prep
    LAST["prep"] = prep
    cls = prep.size_class
    sel = np.flatnonzero(hard & (cls[src] == KIND))
    if len(sel) == 0 or state.n == 0:
        return hard
    opos = state.pos
    osrc = state.src
    tree = cKDTree(opos)
    reach = max(2 * float(prep.rc.max()), float(prep.min_dist.max())) + 1e-9
    seed_tree = cKDTree(opos)
    for q in sel:
        nb = np.asarray(tree.query_ball_point(pts[q], reach), int)
        if len(nb) == 0:
            continue
        lim = np.maximum(prep.rc[src[q]] + prep.rc[osrc[nb]], prep.min_dist[prep.skind[src[q]], prep.skind[osrc[nb]]])
        d = np.hypot(*(opos[nb] - pts[q]).T)
        bad = d < lim
        if not bad.any():
            continue  # refused by something else (crowding is after this)
        nbb, db, lb = nb[bad], d[bad], lim[bad]
        j = nbb[np.argmin(db / lb)]
        k = LAST["key"].get(tuple(pts[q]), -1)
        own = False
        if k >= 0:
            sp = LAST["seed_pos"][LAST["seed_of"][k]]
            own = bool(np.hypot(*(opos[j] - sp)) < 1e-9)
        delta, ccls = np.inf, -1
        if k >= 0:
            mem = np.flatnonzero((LAST["cid"] == LAST["cid"][k]) & (LAST["ex"] >= 0))
            same = mem[cls[LAST["ex"][mem]] == cls[osrc[j]]]
            if len(same):
                delta = float(np.hypot(*(LAST["ppos"][same] - opos[j]).T).min())
            DEL.append((cls[osrc[j]], delta, float(np.min(db / lb))))
        md_used = prep.min_dist[prep.skind[src[q]], prep.skind[osrc[j]]] >= prep.rc[src[q]] + prep.rc[osrc[j]]
        REC.append((cls[osrc[j]], own, state.iterations - state._born[j], float(np.min(db / lb)), float(lb[np.argmin(db / lb)]), float(db[np.argmin(db / lb)]), md_used, int(bad.sum()), prep.skind[osrc[j]], prep.skind[src[q]]))
    return hard


K.generate_proposals, G._split_conflicts = gen, split


def exemplar_pairs():
    pos = np.asarray(ex.xy, float)
    from strew.synth import _prepare  # noqa: F401

    kind = np.asarray(ex.kind)
    r = np.asarray(ex.radius, float) if hasattr(ex, "radius") else None
    print(f"  exemplar counts {np.bincount(kind, minlength=S)} kinds {list(ex.kinds)}")
    for a in range(S):
        for b in range(S):
            pa, pb = pos[kind == a], pos[kind == b]
            if len(pa) == 0 or len(pb) == 0:
                continue
            d, _ = cKDTree(pb).query(pa, k=2 if a == b else 1)
            d = d[:, -1] if a == b else d
            print(f"  exemplar nn[{ex.kinds[a]}>{ex.kinds[b]}] min {d.min():.2f} q05 {np.quantile(d, 0.05):.2f} q25 {np.quantile(d, 0.25):.2f} median {np.median(d):.2f}")


print(f"{name} h{i}s{v} size class {KIND}")
exemplar_pairs()
for seed in [int(x) for x in seeds.split(",")]:
    REC.clear()
    DEL.clear()
    out, _ = run(ex, 3.5, seed, None)
    st = None
    R = np.array([(c, o, a, rt, lb, db, m, nb) for c, o, a, rt, lb, db, m, nb, _, _ in REC], float)
    pp = LAST["prep"]
    sk_cls = np.zeros(int(pp.skind.max()) + 1, int)
    sk_cls[pp.skind] = pp.size_class
    sk_rc = np.zeros(len(sk_cls))
    sk_rc[pp.skind] = pp.rc
    print(f"  skind size class {sk_cls} rc {np.round(sk_rc, 2)}; min_dist\n{np.round(pp.min_dist, 2)}")
    print(f"  seed {seed}: {len(R)} refused proposals of class {KIND}")
    if len(R) == 0:
        continue
    for c in np.unique(R[:, 0]).astype(int):
        m = R[:, 0] == c
        print(f"    blocker class {c}: {m.sum()} ({m.mean():.3f}); own seed {R[m, 1].mean():.3f}; age 0-3 it {(R[m, 2] <= 3).mean():.3f}; "
              f"d/lim median {np.median(R[m, 3]):.3f} q75 {np.quantile(R[m, 3], 0.75):.3f} >0.9 {(R[m, 3] > 0.9).mean():.3f}; "
              f"lim {np.median(R[m, 4]):.2f} (min_dist the bound {R[m, 6].mean():.2f}); violators/proposal {R[m, 7].mean():.2f}")
    # per (query skind, blocker skind): the bound used
    pairs = {}
    for rec in REC:
        pairs.setdefault((rec[9], rec[8]), []).append(rec)
    print("    by (proposal skind, blocker skind): count, bound, median distance")
    for (a, b), lst in sorted(pairs.items(), key=lambda t: -len(t[1]))[:8]:
        print(f"      ({a},{b}) {len(lst)} bound {lst[0][4]:.2f} median d {np.median([x[5] for x in lst]):.2f}")
    D = np.array(DEL, float)
    for c in np.unique(D[:, 0]).astype(int):
        m = D[:, 0] == c
        dd = D[m, 1]
        print(f"    blocker class {c}: the copy holds no stone of that class {np.isinf(dd).mean():.3f}; "
              f"else distance from the blocker to the copy's nearest one q25/median/q75 {np.round(np.quantile(dd[np.isfinite(dd)], [0.25, 0.5, 0.75]), 2) if np.isfinite(dd).any() else '-'}")
    # the bound against the exemplar's own closest pairs of the proposal's class and each class
    from scipy.spatial import cKDTree as _T

    sel = pp.selected_elements & ~pp.void
    ids = np.flatnonzero(sel)
    for b in range(int(pp.size_class.max()) + 1):
        qa, qb = ids[pp.size_class[ids] == KIND], ids[pp.size_class[ids] == b]
        if len(qa) == 0 or len(qb) < 2:
            continue
        d, j = _T(pp.pos[qb]).query(pp.pos[qa], k=2)
        pick = np.where(qb[j[:, 0]] == qa, 1, 0)
        jj = qb[j[np.arange(len(qa)), pick]]
        dd = d[np.arange(len(qa)), pick]
        bound = np.maximum(pp.rc[qa] + pp.rc[jj], pp.min_dist[pp.skind[qa], pp.skind[jj]])
        print(f"    exemplar: class {KIND} to its nearest class {b}: distance / bound min {np.min(dd / bound):.3f} q05 {np.quantile(dd / bound, 0.05):.3f} median {np.median(dd / bound):.3f}")

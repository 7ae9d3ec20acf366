"""Helper s27k: per-iteration trace of synth growth (Algorithm 1) on a fresh17_rows.py label: horizon size,
seeds, proposals valid / overlapping free space / in the domain / refused by conflicts / by the crowd rule /
by _not_owned, placed, and free-space points alive.

    PYTHONPATH=src:benchmarks python benchmarks/s27k_growth_trace.py clusters p2s20 1 [--scale 3.5] [--set G.NAME=VALUE]
"""
import argparse
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar

import strew.synth._grow as G
from strew import Region
from strew.synth import synthesize

ap = argparse.ArgumentParser()
ap.add_argument("cls"); ap.add_argument("label"); ap.add_argument("seed", type=int)
ap.add_argument("--scale", type=float, default=3.5)
ap.add_argument("--set", action="append", default=[])
ap.add_argument("--detail", action="store_true")
ap.add_argument("--every", type=int, default=1)
a = ap.parse_args()
for kv in a.set:
    n, v = kv.split("="); setattr(G, n.split(".")[1], eval(v)); print("set", n, v)

REC = {}
DETAIL = a.detail
K = G.K
_ov, _sc, _cr, _no, _pp = K.overlaps_any, G._split_conflicts, G._crowded, G._not_owned, K.place_proposals
_gp = K.generate_proposals
_gr = G.grow
ST = {}


def gp(*x):
    r = _gp(*x); ST["ex"] = r[1]; ST["cands"] = x[6]; ST["seed_pos"] = x[0]; return r


def gr(state, **kw):
    ST["state"] = state; return _gr(state, **kw)


G.grow = gr
K.generate_proposals = gp


def ov(*x):
    r = _ov(*x); REC["valid"] = len(r); REC["free"] = int(r.sum()); return r


def sc(state, pts, src, visible_only):
    r = _sc(state, pts, src, visible_only); REC["indom"] = len(r); REC["conflict"] = int(r.sum())
    prep = state.prep
    REC["conf_kinds"] = np.bincount(prep.skind[src[r]], minlength=2).tolist()
    return r


def cr(state, pts, src, lim):
    r = _cr(state, pts, src, lim); REC["crowd"] = int(r.sum()); return r


def no(prep, seed_pos, seed_of, ppos, exv):
    r = _no(prep, seed_pos, seed_of, ppos, exv); REC["notowned"] = int(r.sum()); return r


def pp(*x):
    placed, s_ok = _pp(*x)
    okp = x[8]
    costs, slack, out_ptr, count, ppos, pr, psk, md, _, c, f, cell, pslot, pfree, pcls = x
    ns, k = costs.shape
    sel = []; ratio_rej = 0; best_has = 0
    for i in range(ns):
        order = np.argsort(costs[i], kind="mergesort"); d0 = costs[i, order[0]]
        if not np.isfinite(d0): continue
        for jj, j in enumerate(order):
            cj = costs[i, j]
            w = out_ptr[i * k + j]; ids = np.arange(w, w + count[i * k + j])
            if not np.isfinite(cj) or cj > c * d0 + slack[i]:
                ratio_rej += int(okp[out_ptr[i*k]:out_ptr[(i+1)*k]].sum()) if False else 1
                break
            if okp[ids].any():
                sel.extend(ids[okp[ids]].tolist()); break
    sel = np.array(sel, int)
    if DETAIL and int(placed.sum()) == 0 and okp.any():
        prep = ST["state"].prep; exa = ST["ex"]; cands = ST["cands"]
        for i in range(ns):
            order = np.argsort(costs[i], kind="mergesort")
            print(f"   seed {i} at {np.round(ST['seed_pos'][i], 1)} costs {np.round(costs[i][order][:5], 1)} slack {slack[i]:.1f}")
            for jj, j in enumerate(order[:3]):
                e = cands[i, j]
                if e < 0: continue
                w = out_ptr[i * k + j]; ids = np.arange(w, w + count[i * k + j])
                print(f"    cand {e} kind {prep.kind[e]} interior {bool(np.isin(e, prep.interior[0]))} cost {costs[i, j]:.1f}: props",
                      [(int(prep.kind[exa[t]]), int(okp[t]), int(pslot[t]), round(float(np.hypot(*(ppos[t] - ST['seed_pos'][i]))), 0)) for t in ids if exa[t] >= 0])
    orph = 0
    if len(sel):
        ps = pslot[sel]
        orph = int(((ps == -2) | ((ps >= 0) & ~placed[np.maximum(ps, 0)] & ~pfree[np.maximum(ps, 0)])).sum())
        REC["sel_kinds"] = np.bincount(psk[sel], minlength=2).tolist()
        REC["sel_pslot"] = [int((pslot[sel] == -2).sum()), int((pslot[sel] == -1).sum()), int((pslot[sel] >= 0).sum())]
    REC["selected"] = len(sel); REC["orphan"] = orph; REC["seeds_ratio_stop"] = ratio_rej
    REC["offered"] = int(okp.sum()); REC["placed"] = int(placed.sum()); REC["seeds"] = len(s_ok); REC["seed_ok"] = int(s_ok.sum())
    return placed, s_ok


K.generate_proposals = gp
K.overlaps_any, G._split_conflicts, G._crowded, G._not_owned, K.place_proposals = ov, sc, cr, no, pp
_rec = G._record
IT = [0]


def record(state, t0, skipped):
    _rec(state, t0, skipped)
    IT[0] += 1
    if REC and IT[0] % a.every == 0:
        alive = int(state._alive.sum()) if hasattr(state, "_alive") else -1
        print(f"it {IT[0]:3d} n={state.n} hz={int(state.horizon.sum())} alive_free={alive}", {k: v for k, v in REC.items()}, flush=True)
    REC.clear()


G._record = record
mk = fidelity_suite()
ex = exemplar(mk, a.cls, a.label)
x0, y0, x1, y1 = ex.region.bounds
out = synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=a.seed, measure=False)
print("n", len(out), {k: int(np.sum(out.kind == i)) for i, k in enumerate(out.kinds)})

"""Helper sm (issue 13 point 1): where growth's medium stones come from (three sizes h12).

For each element growth places (the loop of ``_grow.grow``), whether it stood nearer another
seed of its step than the seed whose copy brought it (the union of overlapping copies,
see ``_grow._not_owned``) and whether placing it evicted young smaller horizon elements
(``_grow._evict``); per size class, plus the ratio to the exemplar's inner-frame density
right after growth (as syn15_stages.py).

    PYTHONPATH=src:benchmarks python benchmarks/sm_growth_diag.py three_sizes:12:11:1 [--set G.NAME=VALUE]
"""
import argparse
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from synth_variants import _harder

import strew.synth._displace as DP
import strew.synth._grow as G
import strew._fidelity as F
from strew import Region
from strew.synth import synthesize

HARDER = _harder()
EXAREA = [1.0]
K = G.K
CUR = {}
STAT = {}


def _bump(key, cls, n=1):
    STAT.setdefault(key, np.zeros(8, int))[cls] += n


_no = G._not_owned


def not_owned(prep, seed_pos, seed_of, ppos, exv):
    d_own = np.hypot(*(ppos - seed_pos[seed_of]).T)
    d_near = cKDTree(seed_pos).query(ppos, k=1)[0]
    CUR["nearer"] = d_own > d_near + 1e-9
    return _no(prep, seed_pos, seed_of, ppos, exv)


G._not_owned = not_owned
_pp = K.place_proposals


def place(costs, slack, out_ptr, count, ppos, pr, skind, md, okp, c, w, cell, pslot, pfree, order_key, gen):
    placed, s_ok = _pp(costs, slack, out_ptr, count, ppos, pr, skind, md, okp, c, w, cell, pslot, pfree, order_key, gen)
    CUR["placed"] = placed.copy()
    CUR["okp"] = okp.copy()
    return placed, s_ok


K.place_proposals = place
_ev = G._evict


def evict(state, new, *, voids):
    prep = state.prep
    cls_new = prep.size_class[state.src[new]]
    n0 = state.n
    pos_before = state.pos.copy(); src_before = state.src.copy()
    _ev(state, new, voids=voids)
    # which old elements went: compare positions (removal keeps order)
    gone = n0 - state.n
    if gone:
        keep = cKDTree(state.pos).query(pos_before, k=1)[0] > 1e-9
        gp, gs = pos_before[keep], src_before[keep]
        np_ = state.pos[np.flatnonzero(np.isin(np.arange(state.n), np.arange(state.n)))]  # noqa
        # attribute each evicted element to its nearest new element's class
        newpos = pos_before[new]
        j = cKDTree(newpos).query(gp, k=1)[1]
        for cn, cg in zip(cls_new[j], prep.size_class[gs]):
            _bump(f"evicted_by{cn}", cg)
        for cn in np.unique(cls_new[np.unique(j)]):
            pass
        disp = np.zeros(len(new), bool); disp[np.unique(j)] = True
        for c in np.unique(cls_new):
            _bump("new_displacing", c, int(np.sum(disp & (cls_new == c))))
    for c in np.unique(cls_new):
        _bump("new", c, int(np.sum(cls_new == c)))
    if "placed" in CUR and "nearer" in CUR:
        pl = np.flatnonzero(CUR["placed"])
        exc = CUR["exc"][pl] if "exc" in CUR else None


G._evict = evict
_add = G.SynthState.add if hasattr(G, "SynthState") else None
_sc = G._split_conflicts


def split(state, pts, src, visible_only):
    hard = _sc(state, pts, src, visible_only)
    owed = G.owed_classes(state)
    CUR["owed"] = owed
    return hard


G._split_conflicts = split
# placed-and-nearer: hook state.add via grow's call: wrap SynthState.add to read CUR
from strew.synth._state import SynthState

_sadd = SynthState.add


def sadd(self, src, pos, *, horizon=True, fixed=False):
    idx = _sadd(self, src, pos, horizon=horizon, fixed=fixed)
    if horizon and "placed" in CUR and len(idx):
        pl = np.flatnonzero(CUR["placed"])
        if len(pl) == len(idx):
            cls = self.prep.size_class[np.asarray(src)]
            near = CUR["nearer"][pl]
            for c in np.unique(cls):
                _bump("placed_nearer_other", c, int(np.sum(near & (cls == c))))
            ow = CUR.get("owed")
            if ow is not None:
                for c in np.unique(cls):
                    _bump("placed_while_owed", c, int(np.sum(cls == c)) if ow[c] else 0)
        CUR.pop("placed")
    return idx


SynthState.add = sadd
_gr = G.grow


def ratios(state):
    prep = state.prep
    margin = 2.0 * float(prep.rc.max())
    dens = DP._inner_density(prep, margin)
    inner = state.region.geometry.buffer(-margin)
    vis = np.flatnonzero(~prep.void[state.src])
    p = state.pos[vis]
    ins = shapely.contains_xy(inner, p[:, 0], p[:, 1])
    k = prep.skind[state.src[vis[ins]]]
    return np.bincount(k, minlength=len(dens))[: len(dens)] / inner.area / dens


_car = G._complete_anchor_rings


def car(state, *a, **k):
    CUR["after_growth"] = ratios(state)
    ex = state.prep
    vis = ~ex.void[state.src]
    ce = np.bincount(ex.skind[ex.selected_elements & ~ex.void], minlength=len(CUR["after_growth"]))
    co = np.bincount(ex.skind[state.src[vis]], minlength=len(ce))
    CUR["count_ratio"] = co / ce / (state.region.geometry.area / EXAREA[0])
    if GROWTH_ONLY:
        raise StopIteration
    CUR["placed"] = None
    CUR.pop("placed")
    return _car(state, *a, **k)


G._complete_anchor_rings = car

ap = argparse.ArgumentParser()
ap.add_argument("specs", nargs="+")
ap.add_argument("--scale", type=float, default=3.5)
ap.add_argument("--set", action="append", default=[])
ap.add_argument("--growth-only", action="store_true")
args = ap.parse_args()
GROWTH_ONLY = args.growth_only
for kv in args.set:
    name, val = kv.split("=")
    mod, attr = name.split(".")
    setattr({"G": G}[mod], attr, eval(val))
mk = _harder_suite()
for spec in args.specs:
    cls, h, v, seeds = spec.split(":")
    ex = mk.make_exemplar(cls) if h == "suite" else mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(h)])
    x0, y0, x1, y1 = ex.region.bounds
    EXAREA[:] = [ex.region.geometry.area]
    for seed in [int(s) for s in seeds.split(",")]:
        STAT.clear(); CUR.clear()
        try:
            out = synthesize(ex, Region.rectangle(args.scale * (x1 - x0), args.scale * (y1 - y0)), rng=seed, measure=False)
        except StopIteration:
            print(f"== {spec} seed {seed} after growth", np.round(CUR.get("after_growth", []), 3), "counts/area", np.round(CUR["count_ratio"], 3), {k_: v_[:3].tolist() for k_, v_ in sorted(STAT.items())})
            continue
        rep = F.fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        print(f"== {spec} seed {seed} n={len(out)} faithful={rep.faithful} {fails}")
        print("   after growth", np.round(CUR.get("after_growth", []), 3))
        for k_, v_ in sorted(STAT.items()):
            print(f"   {k_:22s}", v_[:3])

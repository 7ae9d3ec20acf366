"""Helper s67t: counterfactuals of synth's class balance on --harder three-size rows, by monkeypatching
``strew.synth._grow`` in this script (src untouched), and a census of how growth's copies of the largest
size class competed in ``_split_conflicts`` (owed by share -> its own class; owed where it stands,
``owed_here`` -> ``OWED_HERE_CLASS``; else 0) and how many smaller elements ``_evict`` removed for them.

    PYTHONPATH=src:benchmarks python benchmarks/s67t_counter.py MODE three_sizes:h8s41[,three_sizes:h8s30] 1-6

MODE: main | here0 (OWED_HERE_Q = 0: owed_here off) | lgnever (the largest class never owed by share,
exemplars of 3 classes or more) | lgmargin1 (the largest class's margin 1 se where it keeps one) |
lgjudge (the largest class owed only while the output's share of it inside its frame less the metric's
wall reach is under the exemplar's share counted the same way, no margin) | lgnone (here0 + lgnever) |
noshort (``_larger_short`` always False: fill_room gives the smallest class ROOM_SHARE_SMALLEST even while a
larger kind is short of its density) | shortroom (``_larger_short`` only while a larger kind short of its
density also has room in the output: more open circles fitting it, counted as fill_room counts them, than
the exemplar's room rate times the region's area) | after (fill_room as on main, then, where
``_larger_short`` held, once more with ``_larger_short`` as shortroom: once the short larger kinds have
taken the rooms they fit, the smallest class takes part at ROOM_SHARE_SMALLEST) | twice (as after, but the
second fill_room with ``_larger_short`` False: the larger kinds take their rooms first, then the smallest).
"""
import sys

import numpy as np
import shapely

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew._fidelity as F
import strew.synth._grow as G
from strew.metrics import fidelity

MODE = sys.argv[1]
CAP = []
_disc = F._discrepancies


def disc(a, b, *args, **kw):
    CAP.append((a, b))
    return _disc(a, b, *args, **kw)


F._discrepancies = disc
CENSUS = {"props": np.zeros(3, int), "evicted": 0, "owed_calls": 0, "owed_large": 0}
_owed, _here, _split, _evict = G.owed_classes, G.owed_here, G._split_conflicts, G._evict


def owed(state):
    o = _owed(state)
    prep = state.prep
    ncls = len(o)
    if ncls >= 3 and MODE in ("lgnever", "lgnone"):
        o = o.copy()
        o[-1] = False
    elif ncls >= 3 and MODE == "lgmargin1":
        sel = prep.selected_elements & ~prep.void
        share = np.bincount(prep.size_class[sel], minlength=ncls) / sel.sum()
        se = np.sqrt(share * (1 - share) / sel.sum())
        if 2 * se[-1] <= G.LARGEST_RARE * share[-1]:
            src = state.src[sel[state.src]]
            out = np.bincount(prep.size_class[src], minlength=ncls) / max(len(src), 1)
            o = o.copy()
            o[-1] = out[-1] < share[-1] + se[-1]
    elif ncls >= 3 and MODE == "lgjudge":
        reach = JUDGE_REACH[0]
        sel = prep.selected_elements & ~prep.void
        ins = np.zeros(len(prep.kind), bool)
        for s, dom in enumerate(prep.domains):
            ids = np.flatnonzero(sel & (prep.source == s))
            ins[ids] = shapely.contains_xy(dom.buffer(-reach), prep.pos[ids, 0], prep.pos[ids, 1])
        share = np.bincount(prep.size_class[ins], minlength=ncls) / max(ins.sum(), 1)
        vis = np.flatnonzero(sel[state.src])
        inner = state.region.geometry.buffer(-reach)
        iv = vis[shapely.contains_xy(inner, state.pos[vis, 0], state.pos[vis, 1])]
        out = np.bincount(prep.size_class[state.src[iv]], minlength=ncls) / max(len(iv), 1)
        o = o.copy()
        o[-1] = out[-1] < share[-1]
    CENSUS["owed_calls"] += 1
    CENSUS["owed_large"] += int(o[-1])
    return o


JUDGE_REACH = [25.64]


def split(state, pts, src, **kw):
    hard = _split(state, pts, src, **kw)
    prep = state.prep
    ncls = int(prep.size_class.max()) + 1
    big = prep.size_class[src] == ncls - 1
    if big.any() and ncls >= 3:
        oc = G.owed_classes(state)[-1]
        oh = G.owed_here(state, pts[big], src[big])
        kept = ~hard[big]
        CENSUS["props"] += [int(np.sum(kept & oc)), int(np.sum(kept & ~oc & oh)), int(np.sum(kept & ~oc & ~oh))]
    return hard


def evict(state, new, *, voids):
    n0 = state.n
    _evict(state, new, voids=voids)
    CENSUS["evicted"] += n0 - state.n


G.owed_classes = owed
G._split_conflicts = split
G._evict = evict
if MODE in ("here0", "lgnone"):
    G.OWED_HERE_Q = 0.0
_short = G._larger_short
SHORT = {"calls": 0, "true": 0, "main_true": 0}


def larger_short(state):
    r = _short(state)
    SHORT["calls"] += 1
    SHORT["main_true"] += int(r)
    if MODE == "noshort" or (MODE == "twice" and SECOND[0]):
        r = False
    elif (MODE == "shortroom" or SECOND[0]) and r:
        r = _short_with_room(state)
    SHORT["true"] += int(r)
    return r


def _short_with_room(state):
    """Whether a larger kind short of its inner density has more output rooms than its exemplar rate."""
    from strew.synth._displace import _inner_density
    prep = state.prep
    margin = 2.0 * float(prep.rc.max())
    dens = _inner_density(prep, margin)
    inner = state.region.geometry.buffer(-margin)
    sel = prep.selected_elements & ~prep.void
    S = len(dens)
    cls_of = np.full(S, -1, np.int64)
    cls_of[prep.skind[sel]] = prep.size_class[sel]
    v = np.flatnonzero(~prep.void[state.src])
    vin = v[shapely.contains_xy(inner, state.pos[v, 0], state.pos[v, 1])]
    have = np.bincount(prep.skind[state.src[vin]], minlength=S)[:S] / float(inner.area)
    rate = G._room_rate(prep, share=np.inf)
    cen, rad, tri = G.circumcircles(state.pos[v])
    keep = state.in_domain(cen)
    cen, rad, tri = cen[keep], rad[keep], tri[keep]
    s_tri = state.src[v[tri]]
    area = float(state.region.geometry.area)
    for k in np.flatnonzero((cls_of > cls_of[cls_of >= 0].min()) & np.isfinite(dens)):
        nk_ex = dens[k] * float(prep.domains[0].buffer(-margin).area)  # as _larger_short counts it
        if not (nk_ex > 0 and have[k] < dens[k] * (1.0 - 1.0 / np.sqrt(nk_ex))):
            continue
        m = np.flatnonzero(sel & (prep.skind == k))
        m = m[np.argmin(prep.rc[m])]
        nk = np.maximum(prep.rc[m] + prep.rc[s_tri], prep.min_dist[k, prep.skind[s_tri]]).max(axis=1)
        fit = np.flatnonzero(rad >= nk)
        rooms = len(G._greedy_rooms(cen[fit], rad[fit], 2.0 * prep.rc[m]))
        if rooms > (rate[k] if np.isfinite(rate[k]) else 0.0) * area:
            return True
    return False


G._larger_short = larger_short
_fill_room = G.fill_room
SECOND = [False]


def fill_room(state, *a, **k):
    r = _fill_room(state, *a, **k)
    if MODE in ("after", "twice") and SHORT["main_true"]:
        SECOND[0] = True
        try:
            r += _fill_room(state, *a, **k)
        finally:
            SECOND[0] = False
    return r


G.fill_room = fill_room


def per1e4(arr, margin):
    g = arr.region.geometry.buffer(-margin)
    xy = np.asarray(arr.xy)
    kn = np.asarray(arr.kind_names)
    ins = shapely.contains_xy(g, xy[:, 0], xy[:, 1])
    return [round(float(np.sum(ins & (kn == k)) / g.area * 1e4), 2) for k in ("small", "medium", "large")]


def main():
    np.set_printoptions(precision=3, suppress=True, linewidth=220)
    mk = _harder_suite()
    H = _harder()
    for spec in sys.argv[2].split(","):
        cls, label = spec.split(":")
        i, _, v = label[1:].partition("s")
        ex = mk.make_exemplar(cls, rng=int(v), **H[cls][int(i)])
        for seed in _variants.ints(sys.argv[3]):
            for k in ("props",):
                CENSUS[k] = np.zeros(3, int)
            CENSUS.update(evicted=0, owed_calls=0, owed_large=0)
            SHORT.update(calls=0, true=0, main_true=0)
            CAP.clear()
            out, _ = run(ex, 3.5, seed, None)
            cen = dict(CENSUS)
            CAP.clear()
            rep = fidelity(ex, out, eq5=False, local=False)
            a, b = CAP[0]
            S = len(a.density)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            nn = rep.metrics.get("nn[small>small]")
            print(f"{MODE} {spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} per1e4 s/m/l {per1e4(out, 26.8)}"
                  f" judge density out/ex-1 {np.round(a.density[:S] / b.density[:S] - 1, 3)} nn[s>s] {nn.value:.4f}/{nn.tolerance:.4f}"
                  f" | large copies kept: owed-by-share {cen['props'][0]} owed-here {cen['props'][1]} not-owed {cen['props'][2]};"
                  f" owed_classes calls {cen['owed_calls']} large owed {cen['owed_large']}; evicted {cen['evicted']};"
                  f" larger_short main/used {SHORT['main_true']}/{SHORT['true']} of {SHORT['calls']} {' '.join(fails)}", flush=True)


if __name__ == "__main__":
    main()

"""Helper s64c: ring shape of a clusters row of synth after growth and after each later pass of
``_grow.grow`` (dots per disc, rings over the exemplar's largest, dot nn deciles), by wrapping the passes
in this script (src untouched); ``--off NAME[,NAME]`` turns passes into no-ops (a counterfactual).

    PYTHONPATH=src:benchmarks python benchmarks/s64c_stages.py clusters:p4s38 1 [--off fill_holes] [--snap F]

``--ring-cap`` (counterfactual of growth, §5.1's collision test only): a copy of a ring child (an exemplar
element with a ``prep.parent``) proposed within 1.5 of its exemplar child-parent distance of an output element
of its parent's kind is refused when that output element's ring already holds as many elements of the child's
kind as the ring of the exemplar element it was copied as (``--ring-cap own``), as the largest ring of the
exemplar's elements of that kind (``--ring-cap max``), own but max for rings the exemplar's frame cuts
(``--ring-cap ownin``), ownin only for children of a larger size class at one distance from their parent,
std / mean <= 0.05 (``--ring-cap ownincv``) or M (``--ring-cap M``).
``--snap F`` (counterfactual of ``_grow._snap_to_anchor_rings``): the ring slot a child proposed beside an
output anchor snaps to may lie up to F times the child's collision radius away (1: main).
"""
import functools
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import strew.synth._displace as DP
import strew.synth._farmix as FM
import strew.synth._grow as G
import strew.synth._pebbles as PB
import strew.synth._shell as SH
import strew.synth._swap as SW
import strew.synth._thin as TH
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run
from strew.metrics import fidelity

REACH = 25.0  # a dot within this of a disc counts to its ring (rings 14.5, discs about 70 apart)
OFF = sys.argv[sys.argv.index("--off") + 1].split(",") if "--off" in sys.argv else []
RING_MAX = [9]
SNAP = float(sys.argv[sys.argv.index("--snap") + 1]) if "--snap" in sys.argv else 1.0
SNAPS = [0, 0]  # proposals offered to snap_to_slots, of them moved onto a slot


CAP_ARG = sys.argv[sys.argv.index("--ring-cap") + 1] if "--ring-cap" in sys.argv else None
REFUSED = [0]


def _cut(prep):
    """(n,) bool: exemplar elements whose children's ring the frame may cut (the element nearer its
    domain's edge than its farthest child plus that child's collision radius, or 1.2 times the median
    child distance where it has none)."""
    got = getattr(prep, "_s64c_cut", None)
    if got is not None:
        return got
    import shapely
    has = prep.parent >= 0
    dist = np.hypot(*(prep.pos[has] - prep.pos[prep.parent[has]]).T)
    reach = np.full(len(prep.kind), 1.2 * np.median(dist) if len(dist) else 0.0)
    np.maximum.at(reach, prep.parent[has], dist + prep.rc[has])
    out = np.zeros(len(prep.kind), bool)
    for s, dom in enumerate(prep.domains):
        ids = np.flatnonzero(prep.source == s)
        out[ids] = shapely.distance(dom.exterior, shapely.points(prep.pos[ids])) < reach[ids]
    prep._s64c_cut = out
    return out


def _tight(prep, cv=0.05):
    """(n,) bool: as ``_optimize.ring_children`` but at std / mean <= ``cv`` (clusters' dots: 0.020-0.023,
    above its RING_CV): children of a larger size class that keep one distance to their parent."""
    got = getattr(prep, "_s64c_tight", None)
    if got is not None:
        return got
    out = np.zeros(len(prep.kind), bool)
    has = np.flatnonzero((prep.parent >= 0) & ~prep.void)
    has = has[prep.size_class[prep.parent[has]] != prep.size_class[has]]
    if len(has):
        d = np.hypot(*(prep.pos[has] - prep.pos[prep.parent[has]]).T)
        pair = np.c_[prep.skind[has], prep.skind[prep.parent[has]]]
        _, inv = np.unique(pair, axis=0, return_inverse=True)
        inv = inv.ravel()
        for g in np.unique(inv):
            m = inv == g
            if m.sum() >= 3 and d[m].std() <= cv * d[m].mean():
                out[has[m]] = True
    prep._s64c_tight = out
    return out


def _ring_capped(f):
    @functools.wraps(f)
    def w(state, pts, src, **kw):
        hard = f(state, pts, src, **kw)
        prep = state.prep
        par = prep.parent[src]
        t = np.flatnonzero(~hard & (par >= 0) & (_tight(prep)[src] if CAP_ARG.endswith("cv") else True))
        if len(t) == 0 or state.n == 0:
            return hard
        okids = np.bincount(prep.parent[prep.parent >= 0], minlength=len(prep.kind))  # exemplar ring sizes
        reach = 1.5 * np.hypot(*(prep.pos[src[t]] - prep.pos[par[t]]).T)
        okind = prep.kind[state.src]
        for pk in np.unique(prep.kind[par[t]]):
            hubs = np.flatnonzero(okind == pk)
            if len(hubs) == 0:
                continue
            tt = t[prep.kind[par[t]] == pk]
            rr = reach[prep.kind[par[t]] == pk]
            d, j = cKDTree(state.pos[hubs]).query(pts[tt])
            near = d <= rr
            tt, j, rr = tt[near], j[near], rr[near]
            for ck in np.unique(prep.kind[src[tt]]):
                m = prep.kind[src[tt]] == ck
                kids = np.flatnonzero(okind == ck)
                if len(kids) == 0:
                    continue
                cnt = cKDTree(state.pos[kids]).query_ball_point(state.pos[hubs[j[m]]], rr[m], return_length=True)
                if CAP_ARG == "own":
                    cap = okids[state.src[hubs[j[m]]]]
                elif CAP_ARG in ("ownin", "ownincv"):  # own, but a ring the exemplar's frame cuts counts as the largest
                    cap = np.where(_cut(prep)[state.src[hubs[j[m]]]], okids[prep.kind == pk].max(), okids[state.src[hubs[j[m]]]])
                elif CAP_ARG == "max":  # the largest ring of any exemplar element of the hub's kind
                    cap = np.full(int(m.sum()), okids[prep.kind == pk].max())
                else:
                    cap = np.full(int(m.sum()), int(CAP_ARG))
                full = cnt >= cap
                hard[tt[m][full]] = True
                REFUSED[0] += int(full.sum())
        return hard
    return w


def _snap_wrapped(f):
    @functools.wraps(f)
    def w(targets, anchor_pos, anchor_src, cptr, cidx, e_pos, rc, ex, pos):
        before = pos[targets].copy()
        f(targets, anchor_pos, anchor_src, cptr, cidx, e_pos, np.ascontiguousarray(SNAP * rc), ex, pos)
        SNAPS[0] += len(targets)
        SNAPS[1] += int(np.sum(np.any(pos[targets] != before, axis=1)))
    return w


def shape(pos, kind):
    disc, dot = pos[kind == 0], pos[kind == 1]
    if len(disc) == 0 or len(dot) < 2:
        return f"discs {len(disc)} dots {len(dot)}"
    d, j = cKDTree(disc).query(dot)
    per = np.bincount(j[d < REACH], minlength=len(disc))
    dd = cKDTree(dot).query(dot, k=2)[0][:, 1]
    over = per > RING_MAX[0]
    return (f"discs {len(disc)} dots {len(dot)} rings>{RING_MAX[0]}: {int(over.sum())} (dots in them {int(per[over].sum())})"
            f" per-disc hist {np.bincount(per).tolist()} stray {int(np.sum(d >= REACH))} dot-nn p10/p30/p50 {np.percentile(dd, [10, 30, 50]).round(2)}")


def phases(state):
    """After growth: of each output ring's dots, from how many exemplar discs' rings (``prep.parent`` of
    their source) they came, and how many not from the ring of the exemplar disc the output disc copies."""
    prep = state.prep
    keep = np.flatnonzero(~state.ghost)
    pos, src = state.pos[keep], state.src[keep]
    kind = prep.kind[src]
    di, do = np.flatnonzero(kind == 0), np.flatnonzero(kind == 1)
    d, j = cKDTree(pos[di]).query(pos[do])
    j, do = j[d < REACH], do[d < REACH]
    per = np.bincount(j, minlength=len(di))
    par = prep.parent[src[do]]
    own = src[di][j]
    lines = []
    for lab, sel in (("rings<=9", per <= RING_MAX[0]), ("rings>9", per > RING_MAX[0])):
        m = sel[j]
        nsrc = [len(np.unique(par[m & (j == r)])) for r in np.flatnonzero(sel)]
        lines.append(f"{lab}: {int(sel.sum())} rings, {int(m.sum())} dots, distinct exemplar parents per ring mean {np.mean(nsrc) if nsrc else 0:.2f}"
                     f" (hist {np.bincount(nsrc).tolist() if nsrc else []}), dots not from the output disc's own source ring {int(np.sum(m & (par != own)))}, with no parent {int(np.sum(m & (par < 0)))}")
    return "    growth phases: " + " | ".join(lines)


def snap(state):
    keep = ~state.ghost if hasattr(state, "ghost") else slice(None)
    return state.pos[keep].copy(), np.asarray(state.kind)[keep].copy()


def wrap(mod, name, log):
    f = getattr(mod, name)

    @functools.wraps(f)
    def w(state, *a, **k):
        p0, k0 = snap(state)
        if name == "_complete_anchor_rings":
            log.append(f"  after growth          : {shape(p0, k0)}")
            log.append(phases(state))
        r = 0 if name in OFF else f(state, *a, **k)
        p1, k1 = snap(state)
        tag = f"{name}{' (OFF)' if name in OFF else ''}"
        log.append(f"  after {tag:<17}: n {len(p0)}->{len(p1)}  {shape(p1, k1)}")
        return r

    setattr(mod, name, w)


def main():
    np.set_printoptions(precision=2, suppress=True, linewidth=200)
    log = []
    for mod, names in ((G, ["_complete_anchor_rings", "fill_room", "fill_holes", "fill_hub_rooms", "fill_far_hub_rooms"]),
                       (DP, ["fill_displaced"]), (SH, ["fill_beside_largest", "fill_beside_far_small"]),
                       (FM, ["trade_far_small", "trade_far_top"]), (PB, ["fill_partners"]), (SW, ["fill_swapped"]),
                       (TH, ["thin_small", "thin_orphans", "thin_crowded", "thin_edge_strays"])):
        for n in names:
            wrap(mod, n, log)
    G.K.snap_to_slots = _snap_wrapped(G.K.snap_to_slots)
    if CAP_ARG is not None:
        G._split_conflicts = _ring_capped(G._split_conflicts)
    mk = fidelity_suite()
    cls, label = sys.argv[1].split(":")
    ex = exemplar(mk, cls, label)
    exd = np.c_[ex.x, ex.y]
    print(f"== {sys.argv[1]} off={OFF} snap={SNAP} ring-cap={CAP_ARG} exemplar: {shape(exd, np.asarray(ex.kind))}", flush=True)
    for seed in _variants.ints(sys.argv[2]):
        log.clear()
        SNAPS[:] = [0, 0]
        REFUSED[0] = 0
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and (not m.passed or k in ("nn[dot>dot]", "density[disc]", "density[dot]"))]
        print(f" seed {seed}:")
        print("\n".join(log))
        print(f"  ring cap {CAP_ARG}: {REFUSED[0]} ring-child copies refused in growth")
        print(f"  snap_to_slots: {SNAPS[0]} child proposals beside an output anchor, {SNAPS[1]} moved onto a slot")
        if "--png" in sys.argv:  # a 300 x 300 corner of the output, exemplar scale
            from s64c_deciles import render
            from strew import Region
            c = (out.x < 300) & (out.y < 300)
            render(type(out)(out.shapes, np.asarray(out.kind)[c], out.x[c], out.y[c], scale=np.asarray(out.scale)[c], region=Region.rectangle(300, 300)),
                   f"{sys.argv[sys.argv.index('--png') + 1]}_s{seed}.png")
        print(f"  final: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {' '.join(fails)}  {shape(np.c_[out.x, out.y], np.asarray(out.kind))}", flush=True)


if __name__ == "__main__":
    main()

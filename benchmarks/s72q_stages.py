"""Helper s72q: synth --varied row (fidelity-suite exemplar, ``p`` label) stage by stage for kind K
(default 1 = medium): count and nn[K>K] deciles (border-corrected as the judge) after each pass, the
judge's value per seed, and the exemplar's generator drawn at the output's size (counts x area) for
comparison (svar13i_oracle.big_params).

    PYTHONPATH=src:benchmarks python benchmarks/s72q_stages.py three_sizes:p4s46:1,2 [--kind 1] [--oracle 1,2]
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from svar13i_oracle import big_params

import strew._fidelity as F
import strew.synth._displace as DP
import strew.synth._farmix as FM
import strew.synth._grow as G
import strew.synth._pebbles as PB
import strew.synth._shell as SH
import strew.synth._swap as SW
import strew.synth._thin as TH
from strew import Region
from strew.synth import synthesize

K = int(sys.argv[sys.argv.index("--kind") + 1]) if "--kind" in sys.argv else 1
ORACLE = [int(s) for s in sys.argv[sys.argv.index("--oracle") + 1].split(",")] if "--oracle" in sys.argv else []
LOG = []
PREV = {}


def kpos(state):
    prep = state.prep
    vis = np.flatnonzero(~prep.void[state.src])
    k = prep.skind[state.src[vis]]
    return vis[k == K], state.pos[vis[k == K]]


def deciles(p, geom):
    if len(p) < 3:
        return None, None
    d = cKDTree(p).query(p, k=2)[0][:, 1]
    edge = shapely.distance(geom.boundary, shapely.points(p))
    return np.quantile(d[d <= edge], np.arange(1, 10) / 10), d


def snap(state, label):
    ids, p = kpos(state)
    q, d = deciles(p, state.region.geometry)
    prev = PREV.get("ids", np.zeros(0, int))
    new = np.setdiff1d(ids, prev)
    nd = d[np.isin(ids, new)] if d is not None else np.zeros(0)
    PREV["ids"] = ids
    LOG.append((label, len(ids), len(new), q, nd))


def wrap(mod, name):
    f = getattr(mod, name)

    def g(state, *a, **k):
        if name == "_complete_anchor_rings":
            PREV.clear()
            snap(state, "growth")
        r = f(state, *a, **k)
        snap(state, name)
        return r

    setattr(mod, name, g)


for mod, name in [(G, "_complete_anchor_rings"), (DP, "fill_displaced"), (SH, "fill_beside_largest"), (FM, "trade_far_small"),
                  (SH, "fill_beside_far_small"), (G, "fill_room"), (PB, "fill_partners"), (SW, "fill_swapped"), (G, "fill_holes"), (TH, "thin_small")]:
    wrap(mod, name)

mk = fidelity_suite()


def counts_inside(arr, pad):
    x0, y0, x1, y1 = arr.region.bounds
    xy = np.asarray(arr.xy)
    ins = (xy[:, 0] > x0 + pad) & (xy[:, 0] < x1 - pad) & (xy[:, 1] > y0 + pad) & (xy[:, 1] < y1 - pad)
    a = (x1 - x0 - 2 * pad) * (y1 - y0 - 2 * pad)
    return [round(1e4 * np.sum(ins & (arr.kind == k)) / a, 2) for k in range(len(arr.kinds))]


for spec in [a for a in sys.argv[1:] if a.count(":") == 2]:
    cls, label, seeds = spec.split(":")
    i, _, v = label[1:].partition("s")
    kw = (_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)]
    ex = mk.make_exemplar(cls, rng=int(v), **kw)
    x0, y0, x1, y1 = ex.region.bounds
    pad = 2 * max(sh.radius for sh in ex.shapes.values()) if hasattr(ex, "shapes") else 20.0
    xy = np.asarray(ex.xy)[ex.kind == K]
    eq, _ = deciles(xy, ex.region.geometry)
    print(f"== {spec} kind {ex.kinds[K]} exemplar n_total={len(ex)} per-class counts {np.bincount(ex.kind)} per 1e4 inside(pad {pad:.1f}) {counts_inside(ex, pad)}", flush=True)
    print(f"   exemplar nn deciles {np.round(eq, 2)}", flush=True)
    for seed in [int(s) for s in seeds.split(",")]:
        LOG.clear()
        out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
        rep = F.fidelity(ex, out, eq5=False, local=False)
        m = rep.metrics[f"nn[{ex.kinds[K]}>{ex.kinds[K]}]"]
        print(f" seed {seed} n={len(out)} counts {np.bincount(out.kind)} per 1e4 inside {counts_inside(out, pad)} faithful={rep.faithful} nn {m.value:.3f}/{m.tolerance:.3f}", flush=True)
        for lab, n, nnew, q, nd in LOG:
            med = np.median(nd) if len(nd) else float("nan")
            print(f"   {lab:22s} n={n:4d} +{nnew:4d} new nn med {med:6.2f} deciles {np.round(q, 1) if q is not None else None}", flush=True)
    for d in ORACLE:
        big = mk.make_exemplar(cls, rng=int(v) + 1000 * d, **big_params(cls, dict(kw), 3.5))
        rep = F.fidelity(ex, big, eq5=False, local=False)
        m = rep.metrics[f"nn[{ex.kinds[K]}>{ex.kinds[K]}]"]
        q, _ = deciles(np.asarray(big.xy)[big.kind == K], big.region.geometry)
        print(f" oracle draw {d} n={len(big)} counts {np.bincount(big.kind)} per 1e4 inside {counts_inside(big, pad)} faithful={rep.faithful} nn {m.value:.3f}/{m.tolerance:.3f}", flush=True)
        print(f"   deciles {np.round(q, 1)}", flush=True)

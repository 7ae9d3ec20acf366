"""Helper s70t: per stage of grow() on a --harder row, for a kind K (default 1 = medium): count inside the
frame less 2 largest rc, and nn[K>K] deciles of all K elements (border-corrected as the judge: nn <= distance to
the region's edge), plus, per stage, how many K elements it added and their own nn to another K (median, share > 1.4x
the exemplar's 90 % decile).

    PYTHONPATH=src:benchmarks python benchmarks/s70t_stages.py three_sizes:11:44:1,2,3 [--kind 1]
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from synth_variants import _harder

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
LOG = []
PREV = {}


def kpos(state):
    prep = state.prep
    vis = np.flatnonzero(~prep.void[state.src])
    k = prep.skind[state.src[vis]]
    return vis[k == K], state.pos[vis[k == K]]


def nnstat(state, ids, p):
    geom = state.region.geometry
    if len(p) < 3:
        return None, None
    d = cKDTree(p).query(p, k=2)[0][:, 1]
    edge = shapely.distance(geom.boundary, shapely.points(p))
    dd = d[d <= edge]
    return np.quantile(dd, np.arange(1, 10) / 10), d


def snap(state, label):
    ids, p = kpos(state)
    q, d = nnstat(state, ids, p)
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

mk = _harder_suite()
for spec in [a for a in sys.argv[1:] if ":" in a]:
    cls, h, v, seeds = spec.split(":")
    ex = mk.make_exemplar(cls, rng=int(v), **_harder()[cls][int(h)])
    x0, y0, x1, y1 = ex.region.bounds
    xy = np.asarray(ex.xy)[ex.kind == K]
    de = cKDTree(xy).query(xy, k=2)[0][:, 1]
    ee = shapely.distance(ex.region.geometry.boundary, shapely.points(xy))
    eq = np.quantile(de[de <= ee], np.arange(1, 10) / 10)
    print(f"== {spec} kind {ex.kinds[K]} exemplar n={len(xy)} nn deciles {np.round(eq, 2)}", flush=True)
    for seed in [int(s) for s in seeds.split(",")]:
        LOG.clear()
        out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
        rep = F.fidelity(ex, out, eq5=False, local=False)
        m = rep.metrics[f"nn[{ex.kinds[K]}>{ex.kinds[K]}]"]
        print(f" seed {seed} n={len(out)} faithful={rep.faithful} nn {m.value:.3f}/{m.tolerance:.3f}")
        for lab, n, nnew, q, nd in LOG:
            far = np.mean(nd > 1.4 * eq[-1]) if len(nd) else float("nan")
            med = np.median(nd) if len(nd) else float("nan")
            print(f"   {lab:22s} n={n:4d} +{nnew:4d} new nn med {med:6.2f} far {far:.2f} deciles {np.round(q, 1) if q is not None else None}")

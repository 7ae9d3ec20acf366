"""Helper s42t (copy of syn15_stages.py; ratios also give, last, the share of inner largest-class elements whose nearest element of the next class stands nearer than the exemplar's closest approach of the two, min_dist / 0.95). Helper syn15: syn13a_stages.py (rows as ``CLASS:H:V:SEEDS`` or, helper s27k, as fresh17_rows.py labels ``CLASS:LABEL:SEEDS``, e.g. ``clusters:p2s20:1,2``) for any --harder set of synth (synth_variants._harder: stripes, rings, clusters ...), per kind and per stage of grow(), elements per area away from the edge over the exemplar's inner-frame density.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/syn15_stages.py CLASS:H:V:SEEDS [--set G.LARGER_IN_CLASS=99]
"""
"""(syn13a_stages.py's notes follow)
elements per area away from the region's edge against the exemplar's inner-frame density
(``_displace._inner_density``, margin two of the largest collision radii, as ``_room_cap`` counts), and
the fidelity metric's density ratio at the end; for growth's large stones, where in the exemplar the copied
element stood (distance to the frame in largest radii) against the exemplar's own large stones.

    python benchmarks/syn13a_stages.py SPEC [SPEC ...] [--scale 3.5]
    SPEC: three_sizes:H:V:SEEDS (H harder index or 'suite', V variant seed, SEEDS 1,2)
    --set G.NAME=VALUE sets a constant of strew.synth._grow first (e.g. G.SHARE_MARGIN=0)

With benchmarks/results/syn13a_count_nearer_seed.patch applied to d67a7c3 and SYN13A_COUNT=1 it also
prints how many of the largest class growth placed stood nearer another seed of their step than their own.

Figures (d67a7c3, seed 1; ratios small / medium / large right after growth; no later pass moves the large):
h4s7 1.177 / 0.832 / 1.243 (seed 2 1.182 / 0.782 / 1.335), h3s8 0.810 / 1.074 / 1.305, h0s7 0.905 / 1.093 / 1.444,
the suite's 0.956 / 1.031 / 0.947; nearer another seed: h4s7 130 of 274 (seed 2 152 of 290), h3s8 263 of 562,
h0s7 117 of 250, suite 183 of 391. SHARE_MARGIN=0 leaves h4s7 byte-identical and its large stones at 1.243;
LARGER_IN_CLASS acts on none of these (three size classes each, no bonus).
"""
import argparse
import sys
import time

import numpy as np
import shapely

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from synth_variants import _harder
HARDER = _harder()

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

LOG = []
ORIG = {}


def ratios(state):
    prep = state.prep
    margin = 2.0 * float(prep.rc.max())
    dens = DP._inner_density(prep, margin)
    inner = state.region.geometry.buffer(-margin)
    vis = np.flatnonzero(~prep.void[state.src])
    p = state.pos[vis]
    ins = shapely.contains_xy(inner, p[:, 0], p[:, 1])
    k = prep.skind[state.src[vis[ins]]]
    S = len(dens)
    r = np.bincount(k, minlength=S)[:S] / inner.area / dens
    from scipy.spatial import cKDTree
    ks = prep.skind[state.src[vis]]
    top, nxt = S - 1, S - 2
    pt, pn = p[ins & (ks == top)], p[ks == nxt]
    close = float(np.mean(cKDTree(pn).query(pt)[0] < prep.min_dist[top, nxt] / 0.95)) if len(pt) and len(pn) else np.nan
    return np.append(r, close)


def wrap(mod, name, label=None):
    f = getattr(mod, name)
    ORIG[(mod, name)] = f

    def g(state, *a, **k):
        if name == "_complete_anchor_rings":
            pr = state.prep
            S = int(pr.skind.max()) + 1
            cls = [int(pr.size_class[pr.skind == q][0]) for q in range(S)]
            bonus = [float(G._larger_in_class(pr)[pr.skind == q][0]) for q in range(S)]
            LOG.append((f"classes {cls} bonus {bonus}", np.zeros(0)))
            LOG.append(("growth", ratios(state)))
        r = f(state, *a, **k)
        LOG.append((label or name, ratios(state)))
        return r

    setattr(mod, name, g)


for mod, name in [(G, "_complete_anchor_rings"), (DP, "fill_displaced"), (SH, "fill_beside_largest"), (FM, "trade_far_small"),
                  (SH, "fill_beside_far_small"), (G, "fill_room"), (PB, "fill_partners"), (SW, "fill_swapped"), (G, "fill_holes"), (TH, "thin_small")]:
    wrap(mod, name)

# origin of growth's copies: wrap state.add during the loop
from strew.synth._state import SynthState

ADDS = []
_add = SynthState.add


def add(self, src, pos, *, horizon=True, fixed=False):
    idx = _add(self, src, pos, horizon=horizon, fixed=fixed)
    if horizon:
        ADDS.append(np.asarray(src).copy())
    return idx


SynthState.add = add

ap = argparse.ArgumentParser()
ap.add_argument("specs", nargs="+")
ap.add_argument("--scale", type=float, default=3.5)
ap.add_argument("--set", action="append", default=[], help="MODULE.NAME=VALUE (G: _grow)")
args = ap.parse_args()
for kv in args.set:
    name, val = kv.split("=")
    mod, attr = name.split(".")
    setattr({"G": G, "DP": DP, "SH": SH, "FM": FM}[mod], attr, eval(val))
    print("set", name, val)
mk = _harder_suite()
for spec in args.specs:
    parts = spec.split(":")
    if len(parts) == 3:  # a fresh17_rows.py label (``clusters:p2s20:SEEDS``, helper s27k)
        from fresh17_rows import exemplar as _fresh_exemplar

        cls, label, seeds = parts
        ex = _fresh_exemplar(mk, cls, label)
    else:
        cls, h, v, seeds = parts
        kw = {} if h == "suite" else HARDER[cls][int(h)]
        ex = mk.make_exemplar(cls, rng=int(v), **kw) if h != "suite" else mk.make_exemplar(cls)
    x0, y0, x1, y1 = ex.region.bounds
    print(f"== {spec} exemplar counts", {k: int(np.sum(ex.kind == i)) for i, k in enumerate(ex.kinds)}, "inner dens", DP._inner_density(__import__("strew.synth._prepare", fromlist=["x"]).prepare(ex) if False else None, 0) if False else "")
    from strew.synth._prepare import prepare as _pp  # noqa: F401
    for seed in [int(s) for s in seeds.split(",")]:
        LOG.clear(); ADDS.clear()
        t = time.process_time()
        out = synthesize(ex, Region.rectangle(args.scale * (x1 - x0), args.scale * (y1 - y0)), rng=seed, measure=False)
        t = time.process_time() - t
        rep = F.fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        dr = {k: round(rep.metrics[f"density[{k}]"].value, 3) for k in out.kinds if f"density[{k}]" in rep.metrics}
        print(f" seed {seed} n={len(out)} cpu={t:.1f}s faithful={rep.faithful} {fails} |dens-1| {dr}")
        if hasattr(G, "_SYN13A_C"):
            print("   largest class placed by growth, nearer another seed:", G._SYN13A_C); G._SYN13A_C[:] = [0, 0]
        for lab, r in LOG:
            print(f"   {lab:22s}", np.round(r, 3))

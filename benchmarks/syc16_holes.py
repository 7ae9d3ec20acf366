"""Helper syc16: what synth's fill_holes adds on clusters h3 (issue 13 point 1, fresh h3s9): per kind the number
added, the elements' inner density over the exemplar's after growth+earlier passes and after fill_holes, and the
dot-to-dot nearest distance of the dots fill_holes added against the others' (in exemplar dot-dot nn medians).

    PYTHONPATH=TREE/src:benchmarks python benchmarks/syc16_holes.py CLASS:H:V:SEEDS [--scale 3.5]
"""
import argparse
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from synth_variants import _harder

import strew._fidelity as F
import strew.synth._grow as G
from strew import Region
from strew.synth import synthesize
import shapely
import strew.synth._displace as DP


def ratios(state):
    """(as benchmarks/syn15_stages.py) elements per area inside the region shrunk by two largest collision radii
    over the exemplar's inner density (_displace._inner_density), per kind-in-exemplar."""
    prep = state.prep
    margin = 2.0 * float(prep.rc.max())
    dens = DP._inner_density(prep, margin)
    inner = state.region.geometry.buffer(-margin)
    vis = np.flatnonzero(~prep.void[state.src])
    p = state.pos[vis]
    ins = shapely.contains_xy(inner, p[:, 0], p[:, 1])
    k = prep.skind[state.src[vis[ins]]]
    return np.bincount(k, minlength=len(dens))[:len(dens)] / inner.area / dens

HARDER = _harder()


def RING(arr):
    """histogram of dots per disc, each dot given to its nearest disc (clusters)."""
    di, do = arr.kinds.index("disc"), arr.kinds.index("dot")
    owner = cKDTree(arr.xy[arr.kind == di]).query(arr.xy[arr.kind == do])[1]
    c = np.bincount(owner, minlength=int(np.sum(arr.kind == di)))
    return np.bincount(c, minlength=8)[:8].tolist(), round(float(c.mean()), 3)
REC = {}
_fh = G.fill_holes


def fh(state, *a, **k):
    n0 = state.n
    REC["before"] = ratios(state)
    r = _fh(state, *a, **k)
    REC["after"] = ratios(state)
    REC["n0"] = n0
    REC["newpos"] = state.pos[n0:state.n].copy()
    return r


G.fill_holes = fh
ap = argparse.ArgumentParser()
ap.add_argument("spec")
ap.add_argument("--scale", type=float, default=3.5)
ap.add_argument("--no-holes", action="store_true")
a = ap.parse_args()
if a.no_holes:
    G.FILL_HOLES = False
cls, h, v, seeds = a.spec.split(":")
ex = _harder_suite().make_exemplar(cls, rng=int(v), **HARDER[cls][int(h)])
x0, y0, x1, y1 = ex.region.bounds
d = ex.kinds.index("dot") if "dot" in ex.kinds else 0
ep = ex.xy[ex.kind == d]
ed = cKDTree(ep).query(ep, 2)[0][:, 1]
print("exemplar dot nn median", round(float(np.median(ed)), 2), "deciles", np.round(np.quantile(ed, np.linspace(.1, .9, 9)), 2))
for seed in map(int, seeds.split(",")):
    out = synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=seed, measure=False)
    rep = F.fidelity(ex, out, eq5=False, local=False)
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    if a.no_holes:
        print("  dots per disc hist 0..7, exemplar", RING(ex), "output", RING(out))
        print(f"seed {seed} (no fill_holes) n={len(out)} fails {fails}", "nn[dot>dot]", round(rep.metrics["nn[dot>dot]"].value, 4), "empty_circle", round(rep.metrics["empty_circle"].value, 4))
        continue
    # output order: elements keep their add order? (synthesize may drop void); use counts only when lengths allow
    print(f"seed {seed} n={len(out)} fails {fails}")
    print("  density before fill_holes", np.round(REC["before"], 3), "after", np.round(REC["after"], 3))
    on = cKDTree(out.xy).query(REC["newpos"])[0] < 1e-6
    print("  added", len(REC["newpos"]), "kept in output", int(on.sum()))
    dp = out.xy[out.kind == d]
    idx = np.flatnonzero(out.kind == d)
    nd = cKDTree(dp).query(dp, 2)[0][:, 1] / np.median(ed)
    new = cKDTree(REC["newpos"]).query(dp)[0] < 1e-6 if len(REC["newpos"]) else np.zeros(len(dp), bool)
    print(f"  dot nn / exemplar median: holes' dots median {np.median(nd[new]):.3f} (n={new.sum()}), others {np.median(nd[~new]):.3f}")
    print("  holes' dots deciles", np.round(np.quantile(nd[new], np.linspace(.1, .9, 9)), 3))
    print("  others  deciles    ", np.round(np.quantile(nd[~new], np.linspace(.1, .9, 9)), 3))
    print("  nn[dot>dot] value", round(rep.metrics["nn[dot>dot]"].value, 4), "empty_circle", round(rep.metrics["empty_circle"].value, 4) if "empty_circle" in rep.metrics else None)
    print("  dots per disc (each dot to its nearest disc): histogram 0..7, exemplar", RING(ex), "output", RING(out))

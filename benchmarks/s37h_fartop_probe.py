"""Helper s37h: what trade_far_top (``_farmix``) does on a --harder three_sizes row.

    PYTHONPATH=src:benchmarks python benchmarks/s37h_fartop_probe.py CLASS:H:V SEEDS

Per seed: the exemplar's far distance (q90 large->medium), the output's large stones beyond it
(interior, nearer a medium than the frame) before and after trade_far_top and at the end, the
medium budget before/after, and how the trade's sites fared (no site / all blocked / traded).
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from scipy.spatial import cKDTree
from synth_variants import _harder

from strew import Region
from strew.synth import _displace, _farmix, fill, new_state

name, i, v = sys.argv[1].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
kn = np.asarray(ex.kind_names); xy = np.asarray(ex.xy)
far = float(np.quantile(cKDTree(xy[kn == "medium"]).query(xy[kn == "large"])[0], 0.9))
print("ex far q90", round(far, 2), "ex q50", round(float(np.quantile(cKDTree(xy[kn == "medium"]).query(xy[kn == "large"])[0], 0.5)), 2))
ST = {}


def farcount(state):
    p = state.prep
    vis = np.flatnonzero(~p.void[state.src[: state.n]])
    c = p.size_class[state.src[vis]]
    top, mid = c.max(), np.unique(c)[-2]
    big = state.pos[vis[c == top]]; md = state.pos[vis[c == mid]]
    d = cKDTree(md).query(big)[0]
    x0, y0, x1, y1 = state.region.geometry.bounds
    edge = np.minimum.reduce([big[:, 0] - x0, x1 - big[:, 0], big[:, 1] - y0, y1 - big[:, 1]])
    m = d <= edge
    return f"large {len(big)} medium {len(md)} far {int(np.sum(d[m] > far))}/{int(m.sum())} q(.5,.8,.9) {np.round(np.quantile(d[m], [.5, .8, .9]), 1)}"


orig_top = _farmix.trade_far_top
orig_at = _farmix._trade_at
stats = {}


def at(*a, **k):
    r = orig_at(*a, **k)
    stats["calls"] = stats.get("calls", 0) + 1
    stats["ok"] = stats.get("ok", 0) + (r >= 0)
    return r


def top(state, *a, **k):
    cand = _farmix._far_setup(state)[5]
    b0 = _displace._inner_deficit(state, state.prep.skind[cand])[2]
    print("   before far_top:", farcount(state), "budget", b0[b0 > 0], flush=True)
    r = orig_top(state, *a, **k)
    b1 = _displace._inner_deficit(state, state.prep.skind[cand])[2]
    print("   after  far_top:", farcount(state), "budget", b1[b1 > 0], "net", r, stats, flush=True)
    return r


_farmix.trade_far_top = top
_farmix._trade_at = at
import strew.synth._grow as G
if hasattr(G, "trade_far_top"):
    G.trade_far_top = top
x0, y0, x1, y1 = ex.region.bounds
for seed in [int(x) for x in sys.argv[2].split(",")]:
    stats.clear()
    st = new_state(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    print(f"seed {seed}")
    fill(st)
    print("   end:", farcount(st), flush=True)

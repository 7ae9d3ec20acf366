"""Helper c50 (issue 13 point 2): clusters at 50x, seed 3: the hole behind the failing window
(4,8) empty_circle (seam17_all50). Runs ``synthesize`` as ``seam17_all50.py`` does, with every
pass of ``_grow.grow`` after the growth loop hooked: the state's visible elements are kept
after each pass. The widest empty circle (Delaunay circumcircle of the output's centres)
centred in the window is found in the output, and for each pass the elements within
``R + 2 rc`` of its centre are listed (added / removed by the pass), with the widest circle
at the hole's centre after each pass and fill_holes' limit (the exemplar's largest empty
circle).

    PYTHONPATH=src python benchmarks/c50_hole.py [--seed 3] [--win 4,8] [--name clusters]
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
import shapely
from scipy.spatial import Delaunay

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import fidelity_suite

import strew.synth._grow as G
import strew.synth._thin as T
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

ap = argparse.ArgumentParser()
ap.add_argument("--seed", type=int, default=3)
ap.add_argument("--win", default="4,8")
ap.add_argument("--name", default="clusters")
ap.add_argument("--scale", type=float, default=7.07)
ap.add_argument("--list", action="store_true", help="list the elements each pass adds/removes near the circle")
a = ap.parse_args()

SNAP: list[tuple[str, np.ndarray, np.ndarray]] = []
INFO: dict = {}


def snap(name, state):
    vis = np.flatnonzero(~state.prep.void[state.src[: state.n]])
    SNAP.append((name, state.pos[vis].copy(), state.src[vis].copy()))


def hook(mod, fname):
    f = getattr(mod, fname)

    def w(state, *args, **kw):
        if fname == "_complete_anchor_rings":
            snap("growth loop", state)
            INFO["limit"] = float(np.nanmax(G.largest_empty_circles(state.prep)[state.prep.selected]))
        r = f(state, *args, **kw)
        snap(fname, state)
        return r

    setattr(mod, fname, w)


import strew.synth._displace as D
import strew.synth._farmix as FM
import strew.synth._pebbles as PB
import strew.synth._shell as SH
import strew.synth._swap as SW

for mod, fn in ((G, "_complete_anchor_rings"), (D, "fill_displaced"), (SH, "fill_beside_largest"), (FM, "trade_far_small"), (SH, "fill_beside_far_small"),
                (G, "fill_room"), (PB, "fill_partners"), (SW, "fill_swapped"), (G, "fill_holes"), (T, "thin_small"), (T, "thin_orphans")):
    hook(mod, fn)

mk = fidelity_suite()
ex = mk.make_exemplar(a.name)
x0, y0, x1, y1 = ex.region.bounds
region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
out = synthesize(ex, region, rng=a.seed, measure=False)
import strew._fidelity as F

WSTAT: dict = {}
_st, _wd = F._stats, F._window_discrepancies


def st_(sm, raw, K, s, window, **kw):
    r = _st(sm, raw, K, s, window, **kw)
    WSTAT["last"] = (tuple(np.round(window.bounds, 3)), r)
    return r


def wd_(st, ex_stats, kinds, s, flags):
    d = _wd(st, ex_stats, kinds, s, flags)
    b, r = WSTAT["last"]
    if r is st:
        WSTAT[b] = (st.lec, st.q95, ex_stats.lec, ex_stats.q95, d.get("empty_circle"))
    return d


F._stats, F._window_discrepancies = st_, wd_
rep = fidelity(ex, out, region, eq5=False)
F._stats, F._window_discrepancies = _st, _wd
loc = rep.local
i, j = map(int, a.win.split(","))
wx, wy = loc["x0"] + j * loc["step"], loc["y0"] + i * loc["step"]
win = shapely.box(wx, wy, wx + loc["window"], wy + loc["window"])
wl, wq, el, eq, dec = WSTAT[tuple(np.round(win.bounds, 3))]
wl_ex, wq_ex = el, eq
m = rep.metrics["empty_circle"]
print(f"window: largest empty circle {wl:.3f} (exemplar's {el:.3f}: {wl / el:.4f}), q95 {wq:.3f} (exemplar's {eq:.3f}: {wq / eq:.4f}); "
      f"discrepancy {dec:.4f}, global tolerance {m.tolerance:.4f}; window tolerance {dec / loc['score'][i, j]:.4f}")
fin = loc["score"][np.isfinite(loc["score"])]
lecs = sorted((v[0] for k, v in WSTAT.items() if k != "last"), reverse=True)
print("largest empty circle per window, widest 6:", np.round(lecs[:6], 3).tolist())
print(f"n={len(out)} window ({i},{j}) score {loc['score'][i, j]:.4f} {loc['worst_metric'][i, j]} box {np.round(win.bounds, 1).tolist()}")
print("fill_holes limit (exemplar's largest empty circle):", round(INFO["limit"], 3))


def circles(p):
    t = Delaunay(p).simplices
    A, B, C = p[t[:, 0]], p[t[:, 1]], p[t[:, 2]]
    d = 2 * (A[:, 0] * (B[:, 1] - C[:, 1]) + B[:, 0] * (C[:, 1] - A[:, 1]) + C[:, 0] * (A[:, 1] - B[:, 1]))
    ux = ((A**2).sum(1) * (B[:, 1] - C[:, 1]) + (B**2).sum(1) * (C[:, 1] - A[:, 1]) + (C**2).sum(1) * (A[:, 1] - B[:, 1])) / d
    uy = ((A**2).sum(1) * (C[:, 0] - B[:, 0]) + (B**2).sum(1) * (A[:, 0] - C[:, 0]) + (C**2).sum(1) * (B[:, 0] - A[:, 0])) / d
    cen = np.c_[ux, uy]
    return cen, np.hypot(*(cen - A).T), t


vis = out.xy[~np.isin(out.kind, [k for k, n in enumerate(out.kinds) if n.startswith("void")])] if len(out) else out.xy
cen, rad, _ = circles(vis)
# the window's circles: centre in the window, wholly inside the region (fidelity's _raw)
inside = shapely.contains_xy(win, cen[:, 0], cen[:, 1]) & (shapely.distance(region.geometry.boundary, shapely.points(cen)) >= rad)
k = np.flatnonzero(inside)[np.argmax(rad[inside])]
c, R = cen[k], rad[k]
print(f"widest empty circle in the window: centre {np.round(c, 2).tolist()} r {R:.3f} = {R / INFO['limit']:.3f} x the limit")
others = np.sort(rad[inside])[::-1][:5]
print("  next widest in the window:", np.round(others, 3).tolist())
prep = None
reach = R + 12.0
prev = None
kinds = ex.kinds
for name, pos, src in SNAP:
    d = np.hypot(*(pos - c).T)
    near = d < reach
    key = {tuple(np.round(p, 6)) for p in pos[near]}
    lo = float(d.min()) if len(d) else np.nan
    cc, rr, _ = circles(pos)
    cw = shapely.contains_xy(win, cc[:, 0], cc[:, 1]) & (shapely.distance(region.geometry.boundary, shapely.points(cc)) >= rr)
    inw = shapely.contains_xy(win, pos[:, 0], pos[:, 1])
    line = (f"{name:22s} n={len(pos):6d} window: elements {int(inw.sum()):4d} q95 {np.quantile(rr[cw], 0.95) / wq_ex:.4f} "
            f"largest {rr[cw].max() / wl_ex:.4f} (of the exemplar's); nearest to the circle's centre {lo:7.3f}")
    if prev is not None and a.list:
        add = key - prev
        rem = prev - key
        if add or rem:
            line += f"  +{len(add)} -{len(rem)}"
            for p in sorted(rem):
                line += f"\n     removed {np.round(p, 2).tolist()} d {np.hypot(p[0] - c[0], p[1] - c[1]):.2f}"
            for p in sorted(add):
                line += f"\n     added   {np.round(p, 2).tolist()} d {np.hypot(p[0] - c[0], p[1] - c[1]):.2f}"
    print(line)
    prev = key
q = np.quantile(rad[inside], 0.95)
print(f"output, by this script's circles: q95 {q / wq_ex:.4f} largest {rad[inside].max() / wl_ex:.4f}")
print("output's elements within", round(reach, 1), "of the centre:")
d = np.hypot(*(out.xy - c).T)
for q in np.argsort(d)[: int((d < reach).sum())]:
    print(f"   {np.round(out.xy[q], 2).tolist()} {out.kinds[out.kind[q]]} d {d[q]:.2f}")

# the window's make-up against the exemplar's (same area): elements per kind, and the
# dots per disc (each dot given to its nearest disc), and against every other window
from scipy.spatial import cKDTree


def makeup(arr, geom):
    m = shapely.contains_xy(geom, arr.xy[:, 0], arr.xy[:, 1])
    cnt = {k: int(np.sum(m & (arr.kind == arr.kinds.index(k)))) for k in arr.kinds}
    if "disc" in arr.kinds and "dot" in arr.kinds:
        di, do = arr.kinds.index("disc"), arr.kinds.index("dot")
        discs = arr.xy[arr.kind == di]
        dd, owner = cKDTree(discs).query(arr.xy[(arr.kind == do) & m])
        cnt["dot->disc median"] = round(float(np.median(dd)), 2)
        cnt["dot->disc q90"] = round(float(np.quantile(dd, 0.9)), 2)
    return cnt


print("exemplar:", makeup(ex, ex.region.geometry), "area", round(ex.region.geometry.area))
print(f"window ({i},{j}):", makeup(out, win), "area", round(win.area))
S = np.asarray(loc["score"], float)
rows = []
for (r_, c_), v in np.ndenumerate(S):
    if not np.isfinite(v):
        continue
    bx = shapely.box(loc["x0"] + c_ * loc["step"], loc["y0"] + r_ * loc["step"], loc["x0"] + c_ * loc["step"] + loc["window"], loc["y0"] + r_ * loc["step"] + loc["window"])
    st = WSTAT.get(tuple(np.round(bx.bounds, 3)))
    mu = makeup(out, bx)
    rows.append((r_, c_, st[1] / wq_ex if st else np.nan, mu.get("disc", 0), mu.get("dot", 0)))
R_ = np.array(rows, float)
me = R_[(R_[:, 0] == i) & (R_[:, 1] == j)][0]
print(f"over {len(R_)} windows: q95 ratio mean {np.nanmean(R_[:, 2]):.3f} sd {np.nanstd(R_[:, 2]):.3f}, this window {me[2]:.3f} (rank {int(np.sum(R_[:, 2] < me[2])) + 1} lowest); "
      f"discs mean {R_[:, 3].mean():.1f} sd {R_[:, 3].std():.1f} this {me[3]:.0f}; dots mean {R_[:, 4].mean():.1f} sd {R_[:, 4].std():.1f} this {me[4]:.0f}")
print("corr(q95 ratio, discs) %.2f, corr(q95 ratio, dots) %.2f" % (np.corrcoef(R_[:, 2], R_[:, 3])[0, 1], np.corrcoef(R_[:, 2], R_[:, 4])[0, 1]))

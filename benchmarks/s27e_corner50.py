"""Helper s27e: rings at 50x (seam17_all50 synth_row, seed 5): the local map's failing corner windows
against others: ring tiles per hub, tile orientation against its hub, and the ring phase (angle of a
hub's ring tiles modulo the tile step) differences to the 6 nearest hubs (the generator draws
phases uniformly: mean 0.25 tile step).

    PYTHONPATH=src python benchmarks/s27e_corner50.py
"""
import sys
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from _runner import fidelity_suite
from scipy.spatial import cKDTree
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize
mk = fidelity_suite()
ex = mk.make_exemplar("rings")
x0, y0, x1, y1 = ex.region.bounds
region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
out = synthesize(ex, region, rng=5, measure=False)
rep = fidelity(ex, out, region, eq5=False)
L = rep.local
print("map", L["x0"], L["y0"], L["step"], L["window"], np.asarray(L["score"]).shape, region.geometry.bounds)
kn = np.asarray(out.kind_names); pos = np.asarray(out.xy)
hub, tile = pos[kn == "hub"], pos[kn != "hub"]
rad = float(ex.meta["params"]["radius"])
d, j = cKDTree(hub).query(tile)
off = np.abs(d - rad) > 2
rot = np.asarray(out.rotation)[kn != "hub"]
# a tile's orientation against its hub: local +y points out of the ring (rot = t - pi/2)
ang = np.arctan2(tile[:, 1] - hub[j, 1], tile[:, 0] - hub[j, 0])
dev = np.angle(np.exp(1j * (rot - (ang - np.pi / 2))))
S = np.asarray(L["score"])
for (r, c) in [(9, 11), (9, 12), (10, 11), (10, 12), (5, 5), (3, 8)]:
    bx0, by0 = L["x0"] + c * L["step"], L["y0"] + r * L["step"]
    m = (tile[:, 0] >= bx0) & (tile[:, 0] < bx0 + L["window"]) & (tile[:, 1] >= by0) & (tile[:, 1] < by0 + L["window"])
    mh = (hub[:, 0] >= bx0) & (hub[:, 0] < bx0 + L["window"]) & (hub[:, 1] >= by0) & (hub[:, 1] < by0 + L["window"])
    k = np.bincount(j[m & ~off], minlength=len(hub))[mh]
    print(f"win ({r},{c}) score {S[r, c]:.3f} box x {bx0:.0f}-{bx0 + L['window']:.0f} y {by0:.0f}-{by0 + L['window']:.0f}: tiles {m.sum()} off-ring {(m & off).sum()} hubs {mh.sum()} ring counts {np.bincount(k).tolist()} |orient dev|>0.2: {(np.abs(dev[m]) > 0.2).sum()} (q90 {np.quantile(np.abs(dev[m]), 0.9):.3f})")
# ring phase per hub: the angle of its ring tiles modulo 2 pi / tiles
nt = int(ex.meta["params"]["tiles"])
ph = np.full(len(hub), np.nan)
for h in range(len(hub)):
    a = ang[(j == h) & ~off]
    if len(a) >= 3:
        z = np.exp(1j * nt * a).mean()
        ph[h] = np.angle(z) / nt
hd, hj = cKDTree(hub).query(hub, k=7)
step = 2 * np.pi / nt
def dphase(h):
    p = ph[hj[h, 1:]] - ph[h]
    p = np.abs(np.angle(np.exp(1j * nt * p))) / nt
    return p[np.isfinite(p)]
exh = np.asarray(ex.xy)[np.asarray(ex.kind_names) == "hub"]
print("exemplar hubs", len(exh))
for (r, c) in [(9, 11), (10, 11), (10, 12), (5, 5), (3, 8), (2, 2)]:
    bx0, by0 = L["x0"] + c * L["step"], L["y0"] + r * L["step"]
    mh = np.flatnonzero((hub[:, 0] >= bx0) & (hub[:, 0] < bx0 + L["window"]) & (hub[:, 1] >= by0) & (hub[:, 1] < by0 + L["window"]))
    dp = np.concatenate([dphase(h) for h in mh])
    print(f"win ({r},{c}) neighbour ring phase differences (units of the tile step {step:.3f}): hist {np.histogram(dp / step, bins=5, range=(0, 0.5))[0].tolist()} mean {np.mean(dp / step):.3f}")
allp = np.concatenate([dphase(h) for h in range(len(hub))])
print(f"all hubs: hist {np.histogram(allp / step, bins=5, range=(0, 0.5))[0].tolist()} mean {np.mean(allp / step):.3f}")

"""Helper g37r: where the widest empty circles of a grown rings row lie.

    PYTHONPATH=src:benchmarks python benchmarks/g37r_probe.py rings:v27 1[,2,3]

For each seed: the output's and the exemplar's empty-circle q95 (Delaunay circumcircles
wholly inside the frame, as ``strew.metrics.fidelity``), then the circles above the
exemplar's q95 classed by where they are: distance to the frame, the hubs within
reach (a missing hub: a hub-sized hole among the hubs), the nearest hub's satellites.
"""
import sys
from types import SimpleNamespace

import _variants  # noqa: F401
import numpy as np
import shapely
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run
from scipy.spatial import Delaunay, cKDTree

from strew.metrics import fidelity


def circles(arr):
    xy = arr.xy
    tri = Delaunay(xy)
    p = xy[tri.simplices]
    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    d = 2 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    ok = np.abs(d) > 1e-12
    ux = ((a ** 2).sum(1) * (b[:, 1] - c[:, 1]) + (b ** 2).sum(1) * (c[:, 1] - a[:, 1]) + (c ** 2).sum(1) * (a[:, 1] - b[:, 1])) / np.where(ok, d, 1)
    uy = ((a ** 2).sum(1) * (c[:, 0] - b[:, 0]) + (b ** 2).sum(1) * (a[:, 0] - c[:, 0]) + (c ** 2).sum(1) * (b[:, 0] - a[:, 0])) / np.where(ok, d, 1)
    cen = np.c_[ux, uy][ok]
    r = np.hypot(cen[:, 0] - a[ok, 0], cen[:, 1] - a[ok, 1])
    reg = arr.region.geometry
    inside = shapely.contains_xy(reg, cen[:, 0], cen[:, 1]) & (shapely.distance(reg.boundary, shapely.points(cen)) >= r)
    return cen[inside], r[inside], tri.simplices[ok][inside]


def main():
    spec, seeds = sys.argv[1], [int(s) for s in sys.argv[2].split(",")]
    cls, label = spec.split(":")
    mk = fidelity_suite()
    ex = exemplar(mk, cls, label)
    ec, er, _ = circles(ex)
    eq = float(np.quantile(er, 0.95))
    hub = ex.kinds.index("hub")
    eh = ex.xy[ex.kind == hub]
    ehd = cKDTree(eh).query(eh, k=2)[0][:, 1]
    print(f"exemplar n={len(ex)} q95={eq:.2f} max={er.max():.2f} hub nn median {np.median(ehd):.2f} min {ehd.min():.2f}")
    for seed in seeds:
        out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
        rep = fidelity(ex, out, eq5=False, local=False)
        oc, orr, simp = circles(out)
        oq = float(np.quantile(orr, 0.95))
        hx = out.xy[out.kind == hub]
        hd = cKDTree(hx).query(hx, k=2)[0][:, 1]
        reg = out.region.geometry
        big = orr > eq * 1.0
        print(f"seed {seed}: n={len(out)} hubs={len(hx)} q95={oq:.2f} ({oq / eq - 1:+.3f}) max={orr.max():.2f} circles {len(orr)} above ex q95: {big.sum()} ({big.mean():.3f}, exemplar 0.05)"
              f" hub nn median {np.median(hd):.2f} min {hd.min():.2f} max {hd.max():.2f} faithful={rep.faithful}")
        # satellites per hub
        ht = cKDTree(hx)
        sat = out.xy[out.kind != hub]
        _, q = ht.query(sat)
        per = np.bincount(q, minlength=len(hx))
        hedge = shapely.distance(reg.boundary, shapely.points(hx))
        print(f"   sats per hub: {np.bincount(per)} ; hubs with < full ring: interior(>30 from frame) {np.count_nonzero((per < per.max()) & (hedge > 30))}")
        # classify big circles
        edge = shapely.distance(reg.boundary, shapely.points(oc[big]))
        dh, _ = ht.query(oc[big])
        kinds_in = out.kind[simp[big]]
        nh = (kinds_in == hub).sum(1)
        print(f"   big circles: centre-to-frame <= 2r {np.count_nonzero(edge <= 2 * orr[big])}, nearest hub dist median {np.median(dh):.1f}; vertices that are hubs: {np.bincount(nh, minlength=4)}")
        # by nearest-hub-distance bins, compare to exemplar's big circles
        ebig = er > eq
        edh, _ = cKDTree(eh).query(ec[ebig])
        print(f"   nearest hub dist of big circles: out pct10/50/90 {np.percentile(dh, [10, 50, 90]).round(1)}, ex {np.percentile(edh, [10, 50, 90]).round(1)}")
        # hub holes: largest empty circles among hubs alone
        top = np.argsort(-orr)[:8]
        for t in top:
            print(f"     r={orr[t]:.2f} at ({oc[t, 0]:.0f},{oc[t, 1]:.0f}) to frame {shapely.distance(reg.boundary, shapely.Point(*oc[t])):.0f} nearest hub {ht.query(oc[t])[0]:.1f} verts kinds {out.kind[simp[t]].tolist()}")


if __name__ == "__main__":
    main()

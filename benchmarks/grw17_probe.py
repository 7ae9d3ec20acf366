"""grw17 probe: per-kind shares of --harder rows against the exemplar's whole-frame and
interior shares (elements at least one largest radius in from the frame), interior
densities, and where the widest empty circles sit (kinds of their Delaunay corners).

    PYTHONPATH=TREE/src python benchmarks/grw17_probe.py two_sizes:3:10,two_sizes:11:7 1-4 [scale]
"""
import sys
import time

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite
from scipy.spatial import Delaunay

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def stats(arr, R):
    xy = np.asarray(arr.xy, float)
    kind = np.asarray(arr.kind)
    K = len(arr.kinds)
    x0, y0, x1, y1 = arr.region.bounds
    to_edge = np.minimum.reduce([xy[:, 0] - x0, x1 - xy[:, 0], xy[:, 1] - y0, y1 - xy[:, 1]])
    inner = to_edge >= R
    area_in = (x1 - x0 - 2 * R) * (y1 - y0 - 2 * R)
    whole = np.bincount(kind, minlength=K) / len(kind)
    cin = np.bincount(kind[inner], minlength=K)
    share_in = cin / max(1, cin.sum())
    dens_in = cin / area_in
    tri = Delaunay(xy)
    p = xy[tri.simplices]
    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    d = 2 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    ux = ((a ** 2).sum(1) * (b[:, 1] - c[:, 1]) + (b ** 2).sum(1) * (c[:, 1] - a[:, 1]) + (c ** 2).sum(1) * (a[:, 1] - b[:, 1])) / d
    uy = ((a ** 2).sum(1) * (c[:, 0] - b[:, 0]) + (b ** 2).sum(1) * (a[:, 0] - c[:, 0]) + (c ** 2).sum(1) * (b[:, 0] - a[:, 0])) / d
    r = np.hypot(ux - a[:, 0], uy - a[:, 1])
    e = np.minimum.reduce([ux - x0, x1 - ux, uy - y0, y1 - uy])
    ok = e >= r
    r, simp = r[ok], tri.simplices[ok]
    q95 = float(np.quantile(r, 0.95))
    top = r >= q95
    # corners of the widest circles: how many of the three are the largest kind (kind 0)
    nbig = (kind[simp[top]] == 0).sum(1)
    mix = np.bincount(nbig, minlength=4) / max(1, top.sum())
    dens_w = np.bincount(kind, minlength=K) / ((x1 - x0) * (y1 - y0))
    return whole, share_in, dens_in, q95, mix, dens_w


mk = _harder_suite()
a, _, b = sys.argv[2].partition("-")
seeds = range(int(a), int(b or a) + 1)
scale = float(sys.argv[3]) if len(sys.argv) > 3 else 3.5
for spec in sys.argv[1].split(","):
    c, i, v = spec.split(":")
    ex = mk.make_exemplar(c, rng=int(v), **HARDER[c][int(i)])
    R = float(np.max(np.asarray(ex.radii)))
    ew, ei, ed, eq, emix, edw = stats(ex, R)
    print(f"{spec} ex n {len(ex)} counts {np.bincount(np.asarray(ex.kind))} R {R:.2f} whole {np.round(ew,3)} inner {np.round(ei,3)} q95 {eq:.2f} top-circle #big corners 0..3 {np.round(emix,2)} dens_in/dens_whole {np.round(ed/edw,3)}", flush=True)
    x0, y0, x1, y1 = ex.region.bounds
    for seed in seeds:
        t = time.process_time()
        out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=seed)
        dt = time.process_time() - t
        ow, oi, od, oq, omix, odw = stats(out, R)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        print(f"  s{seed} n {len(out)} whole/exwhole {np.round(ow/ew,3)} inner/exinner {np.round(oi/ei,3)} dens_in/ex {np.round(od/ed,3)} dens_whole/ex {np.round(odw/edw,3)} "
              f"q95 {oq/eq:.3f} mix {np.round(omix,2)} ec {rep.metrics['empty_circle'].value:.3f} {fails} {dt:.1f}s", flush=True)

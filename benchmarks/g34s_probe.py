"""Helper g34s: the share of wide apple holes (whole Delaunay circumcircles of the visible elements) in the
exemplar, in grow's result with the void-hole pass off, and in the class's generator at the output's size.

    PYTHONPATH=src python benchmarks/g34s_probe.py CLASS:LABEL[,CLASS:LABEL...] [SEED]

For thresholds t = the exemplar's whole-circle radius quantiles 0.5/0.75/0.9 and its least visible distance,
prints the share of whole circles wider than t (exemplar / grow off / oracle), and density x.
"""
import math
import os
import sys

import numpy as np
from scipy.spatial import Delaunay, cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402
from g33s_probe import sparse_oracle  # noqa: E402

import strew.grow._void_holes as vh  # noqa: E402
from strew import Region  # noqa: E402
from strew._kernels.geometry import circumcircles  # noqa: E402
from strew.grow import grow  # noqa: E402
from strew.metrics import fidelity  # noqa: E402


def radii(a):
    h = np.asarray(a.columns["void"], bool) if "void" in a.columns else np.zeros(len(a), bool)
    p = a.xy[~h]
    t = Delaunay(p)
    cen, r, _ = circumcircles(*(p[t.simplices[:, q]] for q in range(3)))
    inner = a.region.contains(cen) & (a.region.distance_to_boundary(cen) >= r)
    dmin = float(cKDTree(p).query(p, 2)[0][:, 1].min())
    return r[inner], dmin, len(p)


def main():
    specs = sys.argv[1].split(",")
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    vh.reference_visible_gap = lambda g: 0.0
    for spec in specs:
        cls, label = spec.split(":")
        ex = exemplar(fidelity_suite(), cls, label)
        re, dmin, ne = radii(ex)
        ts = [float(np.quantile(re, q)) for q in (0.5, 0.75, 0.9)] + [dmin]
        x0, y0, x1, y1 = ex.region.bounds
        sc = 3.5
        for _ in range(2):
            out = grow(ex, region=Region.rectangle(sc * (x1 - x0), sc * (y1 - y0)), mode="fixed", rng=seed)
            if len(out) >= 10 * len(ex):
                break
            sc *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
        ro, _, no = radii(out)
        v = int(label.split("s")[-1]) if "s" in label else int(label[1:])
        orc = sparse_oracle(ex.meta["params"], sc * (x1 - x0), v + 1000)
        rc, _, nc = radii(orc)
        dx = lambda a: (lambda m: m.result / m.exemplar)(fidelity(ex, a, eq5=False, local=False).metrics[f"density[{ex.kinds[0]}]"])
        print(f"{spec}: exemplar {ne} apples {len(re)} whole circles dmin {dmin:.2f}; off: {no} apples {len(ro)} circles dens {dx(out):.3f}x; oracle {nc} apples dens {dx(orc):.3f}x")
        for name, t in zip(("q50", "q75", "q90", "dmin"), ts):
            print(f"   t {name}={t:6.2f}: ex {np.mean(re > t):.3f} ({int((re > t).sum())})  off {np.mean(ro > t):.3f} ({int((ro > t).sum())})  oracle {np.mean(rc > t):.3f} ({int((rc > t).sum())})   excess-off {int((ro > t).sum() - np.mean(re > t) * len(ro))}", flush=True)


if __name__ == "__main__":
    main()

"""Helper fr: grow on a rings --varied-variants row with GrowParams probes (not changes):
hub pairs closer than 0.9 of the exemplar's least hub distance, rings short of tiles, and
the row's verdict, per probe and seed.

    PYTHONPATH=src python benchmarks/fr_rings_probe.py rings:p3s12,rings:p3s11 1-3 [PROBE ...]

PROBE is ``base`` or ``name=value`` of a GrowParams field (Python literal).
"""
import ast
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
import numpy as np
from _runner import fidelity_suite
from fresh17_rows import exemplar
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def defects(a, hub_min):
    kn = np.asarray(a.kind_names)
    xy = np.c_[a.x, a.y]
    h, t = xy[kn == "hub"], xy[kn == "tile"]
    d, _ = cKDTree(h).query(h, k=2)
    dt, it = cKDTree(h).query(t)
    per = np.bincount(it[dt < 0.5 * hub_min], minlength=len(h))
    return int((d[:, 1] < 0.9 * hub_min).sum()), int((per < per.max()).sum()), len(h)


def main():
    specs, seeds = sys.argv[1].split(","), _variants.ints(sys.argv[2])
    probes = sys.argv[3:] or ["base"]
    mk = fidelity_suite()
    for spec in specs:
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        kn = np.asarray(ex.kind_names)
        h = np.c_[ex.x, ex.y][kn == "hub"]
        hub_min = float(cKDTree(h).query(h, k=2)[0][:, 1].min())
        x0, y0, x1, y1 = ex.region.bounds
        for pr in probes:
            kw = {} if pr == "base" else {pr.split("=")[0]: ast.literal_eval(pr.split("=", 1)[1])}
            res = []
            for seed in seeds:
                out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, **kw)
                rep = fidelity(ex, out, eq5=False, local=False)
                c, short, nh = defects(out, hub_min)
                g = rep.metrics["g[hub,hub]"]
                res.append(rep.faithful)
                print(f"  {spec} {pr} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} hubs {nh} close {c} short rings {short} g[hub,hub] {g.value:.3f}/{g.tolerance:.3f} {' '.join(rep.failures)}", flush=True)
            print(f"{spec} {pr}: {sum(res)}/{len(res)}", flush=True)


if __name__ == "__main__":
    main()

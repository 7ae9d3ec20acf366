"""Helper g42s: stones p2 (sparse small stones) rows: the whole empty circles quantiles
(q50, q75, q90, q95) of the exemplar, of the class generator at 3.5 x (the oracle) and of
grow, and empty_circle against the exemplar.

    PYTHONPATH=src:benchmarks python benchmarks/g42s_probe.py p2s23,p2s29 1,2
"""
import sys, numpy as np
sys.path.insert(0, "benchmarks")
import _variants
from fresh17_rows import exemplar
from _runner import fidelity_suite
from grow_variants import run
from types import SimpleNamespace
from scipy.spatial import Delaunay
from strew._kernels.geometry import circumcircles
mk = fidelity_suite()
def circles(arr):
    pts = arr.xy
    tri = Delaunay(pts); a,b,c = (pts[tri.simplices[:,q]] for q in range(3))
    cen, rr, _ = circumcircles(a,b,c)
    inner = arr.region.contains(cen) & (arr.region.distance_to_boundary(cen) >= rr)
    return rr[inner]
Q=[.5,.75,.9,.95]
seeds=[int(s) for s in sys.argv[2].split(",")]
for lab in sys.argv[1].split(","):
    ex = exemplar(mk, "stones", lab)
    re = circles(ex)
    v = int(lab.split("s")[1]); kw = dict(_variants.EDGE["stones"][1]); kw.update(size=700.0, count=int(round(60*3.5*3.5)))
    orc = mk.make_exemplar("stones", rng=v+1000, **kw)
    ro = circles(orc)
    line = f"{lab} ex n{len(ex)} {np.quantile(re,Q).round(1)} | oracle n{len(orc)} {np.quantile(ro,Q).round(1)} ec {abs(np.quantile(ro,.95)/np.quantile(re,.95)-1):.3f}"
    for seed in seeds:
        out,_ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
        rg = circles(out)
        line += f" | grow{seed} n{len(out)} {np.quantile(rg,Q).round(1)} ec {abs(np.quantile(rg,.95)/np.quantile(re,.95)-1):.3f}"
    print(line, flush=True)

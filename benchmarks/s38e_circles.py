"""Helper s38e: where an output's widest empty circles lie (issue 13 point 1, stones h4s27).

    PYTHONPATH=src:benchmarks python benchmarks/s38e_circles.py CLASS:H:V SEEDS

Prints the empty_circle metric (result / exemplar q95 of the Delaunay circumradii), the
exemplar's and the output's radius quantiles, and for the output's circles above the
exemplar's q95: their depth from the region's edge (in exemplar largest empty circle
radii, lec) and the kinds/sources of their corners' birth order (a seam shows corners
from copies born far apart).
"""
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from synth_variants import _harder, run

from strew.metrics import fidelity
from strew.synth._grow import circumcircles


def circles(arr):
    xy = np.asarray(arr.xy)
    cen, rad, tri = circumcircles(xy)
    g = arr.region.geometry
    ins = shapely.contains_xy(g, cen[:, 0], cen[:, 1])
    ins[ins] = shapely.distance(g.boundary, shapely.points(cen[ins])) >= rad[ins]
    return cen[ins], rad[ins], tri[ins]


name, i, v = sys.argv[1].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
_, er, _ = circles(ex)
q = [0.5, 0.75, 0.9, 0.95, 0.99, 1.0]
print("exemplar n", len(ex), "circ q", np.round(np.quantile(er, q), 2))
for seed in [int(x) for x in sys.argv[2].split(",")]:
    t0 = time.process_time()
    out, _ = run(ex, 3.5, seed, None)
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["empty_circle"]
    cen, rad, tri = circles(out)
    print(f"seed {seed} n={len(out)} empty_circle {m.value:.3f}/{m.tolerance:.3f} res {m.result} ex {m.exemplar} cpu {time.process_time()-t0:.1f}")
    print("  out circ q", np.round(np.quantile(rad, q), 2))
    eq95 = np.quantile(er, 0.95)
    big = rad > eq95
    depth = shapely.distance(out.region.geometry.boundary, shapely.points(cen[big]))
    print(f"  circles > ex q95 ({eq95:.2f}): {big.sum()} of {len(rad)} ({big.mean():.3f}; ex {np.mean(er > eq95):.3f}); depth quantiles / ex lec {np.round(np.quantile(depth, [0.1, 0.5, 0.9]) / er.max(), 2)}")
    born = np.arange(len(out))  # output order = birth order
    spread = np.ptp(born[tri[big]], axis=1)
    print(f"  corner birth spread median {np.median(spread):.0f} (all circles {np.median(np.ptp(born[tri], axis=1)):.0f})")

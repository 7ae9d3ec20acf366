"""Helper s60c: clusters' disc spacing and room for one more cluster (a disc >= the exemplar's least disc-disc distance from every disc), exemplar vs synth output.

    PYTHONPATH=src:benchmarks python benchmarks/s60c_rooms.py LABEL SEEDS
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run


def stats(name, arr, dmin, margin):
    k = np.asarray(arr.kind)
    p = np.c_[arr.x, arr.y]
    x0, y0, x1, y1 = arr.region.bounds
    d = p[k == 0]
    inner = (d[:, 0] > x0 + margin) & (d[:, 0] < x1 - margin) & (d[:, 1] > y0 + margin) & (d[:, 1] < y1 - margin)
    nn = cKDTree(d).query(d, 2)[0][:, 1]
    # room: grid points inside the inner frame farther than dmin from every disc, greedily dmin apart
    g = np.mgrid[x0 + margin:x1 - margin:1.0, y0 + margin:y1 - margin:1.0].reshape(2, -1).T
    gd = cKDTree(d).query(g)[0]
    cand = g[gd >= dmin]
    rooms = 0
    if len(cand):
        order = np.argsort(-gd[gd >= dmin])
        taken = []
        for i in order[:20000]:
            if all(np.hypot(*(cand[i] - t)) >= dmin for t in taken):
                taken.append(cand[i])
        rooms = len(taken)
    area = (x1 - x0 - 2 * margin) * (y1 - y0 - 2 * margin)
    nd = inner.sum()
    print(f"{name:12s} discs/1e4 area {1e4 * nd / area:.3f} dots/disc {(k == 1).sum() / (k == 0).sum():.2f} disc nn deciles(inner) {np.round(np.percentile(nn[inner], [10, 30, 50, 70, 90]), 1)} rooms/1e4 {1e4 * rooms / area:.3f} ({rooms})", flush=True)


mk = fidelity_suite()
ex = exemplar(mk, "clusters", sys.argv[1])
k = np.asarray(ex.kind)
d = np.c_[ex.x, ex.y][k == 0]
dmin = float(cKDTree(d).query(d, 2)[0][:, 1].min())
print("least disc-disc distance in the exemplar", round(dmin, 2))
stats("exemplar", ex, dmin, 20.0)
for s in [int(x) for x in sys.argv[2].split(",")]:
    out, _ = run(ex, 3.5, s, None)
    stats(f"synth s{s}", out, dmin, 20.0)

"""Helper s37k: where a --varied row's output is too dense, per kind: by distance from the region's edge.

    PYTHONPATH=src python benchmarks/s37k_where.py stripes:v20 1-2

Per row and seed: elements per 1e4 area of each kind in bands of distance to the region's
boundary (0-1 s, 1-2 s, 2-4 s, 4-8 s, > 8 s, s the exemplar's median nn), against the
exemplar's own interior (> 1 s from its frame), and nn[k>k] deciles / s, exemplar and output.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
import shapely
from scipy.spatial import cKDTree

import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from strew.metrics import fidelity


def per_band(arr, s, edges):
    g = arr.region.geometry
    xy = np.asarray(arr.xy, float)
    kn = np.asarray(arr.kind_names)
    d = shapely.distance(g.boundary, shapely.points(xy))
    out = {}
    for k in sorted(set(kn)):
        row = []
        for lo, hi in zip(edges[:-1], edges[1:]):
            inner = g.buffer(-lo * s)
            ring = inner.difference(g.buffer(-hi * s)) if np.isfinite(hi) else inner
            n = np.sum((kn == k) & (d >= lo * s) & (d < hi * s))
            row.append(n / max(ring.area, 1e-9) * 1e4)
        out[k] = np.round(row, 2)
    return out


def nnq(arr, k, s):
    xy = np.asarray(arr.xy, float); kn = np.asarray(arr.kind_names)
    p = xy[kn == k]
    d = cKDTree(p).query(p, 2)[0][:, 1]
    edge = shapely.distance(arr.region.geometry.boundary, shapely.points(p))
    d = d[d <= edge]
    return np.round(np.quantile(d, np.arange(1, 10) / 10) / s, 3)


mk = fidelity_suite()
from synth_variants import run  # noqa: E402

for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    for seed in _variants.ints(sys.argv[2]):
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        s = rep.s
        pe = per_band(ex, s, [1, np.inf])
        po = per_band(out, s, [0, 1, 2, 4, 8, np.inf])
        print(f"{spec} seed {seed} n={len(out)} s={s:.2f}", flush=True)
        for k in pe:
            print(f"  {k}: ex interior {pe[k]}  out by edge distance 0-1,1-2,2-4,4-8,>8 s {po[k]}")
            print(f"     nn deciles/s ex {nnq(ex, k, s)}\n                  out {nnq(out, k, s)}", flush=True)

"""Helper s30t: shape-measured neighbour counts, exemplar against synth's output.

    PYTHONPATH=src python benchmarks/s30t_counts.py CLASS:LABEL[,...] SEEDS [off]

For each element away from the edge (its shape's reach neighbourhood wholly inside the
box shrunk by the reach), the number of other shapes within ``reach`` (the shape's
bounding radius) of its shape; prints mean and quantiles (10/50/90 %) in the exemplar
and in the output, and the output's density ratio. ``off`` runs with
``_grow.SHAPE_CROWD`` off (the tree's growth without shape limits).
"""
import os
import sys

import numpy as np
import shapely

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from fresh17_rows import exemplar
from _runner import fidelity_suite


def counts(arr):
    g = np.array([arr.shapes[arr.kinds[k]].geometry for k in arr.kind], dtype=object)
    rad = np.array([shapely.minimum_bounding_radius(x) for x in g])
    th, sc = np.asarray(arr.rotation, float), np.asarray(arr.scale, float)
    geo = np.array([shapely.affinity.translate(shapely.affinity.rotate(shapely.affinity.scale(gi, s, s, origin=(0, 0)), t, use_radians=True, origin=(0, 0)), *p) for gi, t, s, p in zip(g, th, sc, arr.xy)], dtype=object)
    reach = rad * sc
    tree = shapely.STRtree(geo)
    a, b = tree.query(geo, predicate="dwithin", distance=float(reach.max()))
    keep = a != b
    a, b = a[keep], b[keep]
    close = shapely.dwithin(geo[a], geo[b], reach[a])
    cnt = np.bincount(a[close], minlength=len(geo))
    xy = np.asarray(arr.xy, float)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    m = 3 * reach.max()
    inner = np.all((xy > lo + m) & (xy < hi - m), axis=1)
    return cnt[inner], len(xy) / np.prod(hi - lo)


def main():
    if len(sys.argv) > 3 and sys.argv[3] == "off":
        from strew.synth import _grow
        _grow.SHAPE_CROWD = False
    from synth_variants import run

    mk = fidelity_suite()
    q = lambda v: f"mean {v.mean():.2f} q {' '.join(f'{x:.0f}' for x in np.quantile(v, [0.1, 0.5, 0.9]))}"
    for spec in sys.argv[1].split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        ce, de = counts(ex)
        for seed in _variants.ints(sys.argv[2]):
            out, _ = run(ex, 3.5, seed, None)
            co, do = counts(out)
            print(f"{spec} seed {seed}: exemplar {q(ce)} (n {len(ce)}) | output {q(co)} (n {len(co)}) | rough density ratio {do / de:.3f}", flush=True)


if __name__ == "__main__":
    main()

"""Helper s29s: nearest shape-to-shape gap per element, exemplar against synth's output.

    PYTHONPATH=src python benchmarks/s29s_gaps.py CLASS:LABEL[,...] SEEDS

Prints the clearance synth's shape test keeps (``_shapes.clearance`` times 0.95), the
exemplar's and the output's smallest gap and gap quantiles (10, 25, 50 %), and the
output's share of elements whose nearest gap is below the exemplar's smallest.
"""
import os
import sys

import numpy as np
import shapely

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from fresh17_rows import exemplar
from _runner import fidelity_suite


def gaps(arr):
    g = np.array([arr.shapes[arr.kinds[k]].geometry for k in arr.kind], dtype=object)
    th, sc = np.asarray(arr.rotation, float), np.asarray(arr.scale, float)
    geo = np.array([shapely.affinity.translate(shapely.affinity.rotate(shapely.affinity.scale(gi, s, s, origin=(0, 0)), t, use_radians=True, origin=(0, 0)), *p) for gi, t, s, p in zip(g, th, sc, arr.xy)], dtype=object)
    tree = shapely.STRtree(geo)
    a, b = tree.query(geo, predicate="dwithin", distance=6.0)
    keep = a != b
    a, b = a[keep], b[keep]
    d = shapely.distance(geo[a], geo[b])
    out = np.full(len(geo), np.inf)
    np.minimum.at(out, a, d)
    return out[np.isfinite(out)]


def main():
    from strew.synth import _prepare, _shapes
    from synth_variants import run

    mk = fidelity_suite()
    for spec in sys.argv[1].split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        ge = gaps(ex)
        for seed in _variants.ints(sys.argv[2]):
            out, _ = run(ex, 3.5, seed, None)
            go = gaps(out)
            q = lambda v: " ".join(f"{x:.2f}" for x in np.quantile(v, [0.1, 0.25, 0.5]))
            print(f"{spec} seed {seed}: exemplar min {ge.min():.3f} q {q(ge)} | output min {go.min():.3f} q {q(go)} below ex min {np.mean(go < ge.min()):.3f}", flush=True)


if __name__ == "__main__":
    main()

"""s67c: ring sizes (dots whose nearest disc lies within 1.25 ring radii, as the s65c test
counts them) of synth's output on --varied clusters p4s38 (exemplar largest ring 9), with
nn[dot>dot], at the frame multiple and synth seeds given.

    PYTHONPATH=src:benchmarks python benchmarks/s67c_rings_out.py 3.0 1-3
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

P4 = {"large": 12.0, "small": 2.0, "ring_gap": 0.5, "ring_min": 7, "ring_max": 9, "cluster_spacing": 70.0}


def rings(arr, radius=None):
    k = np.asarray(arr.kind_names)
    disc, dot = arr.xy[k == "disc"], arr.xy[k == "dot"]
    d, j = cKDTree(disc).query(dot)
    radius = float(np.median(d)) if radius is None else radius
    return np.bincount(j[d <= 1.25 * radius], minlength=len(disc)), radius


ex = fidelity_suite().make_exemplar("clusters", rng=38, **P4)
ec, rad = rings(ex)
print(f"exemplar rings {np.bincount(ec).tolist()} largest {ec.max()} radius {rad:.2f}")
x0, y0, x1, y1 = ex.region.bounds
f = float(sys.argv[1])
for seed in _variants.ints(sys.argv[2]):
    out = synthesize(ex, Region.rectangle(f * (x1 - x0), f * (y1 - y0)), rng=seed, measure=False)
    c, _ = rings(out, rad)
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["nn[dot>dot]"]
    print(f"{f}x seed {seed}: n {len(out)} discs {len(c)} hist {np.bincount(c).tolist()} over9 {int((c > 9).sum())} ({(c > 9).mean():.3f}) "
          f"over10 {int((c > 10).sum())} max {c.max()} nn[dot>dot] {m.value:.3f}/{m.tolerance:.3f}", flush=True)

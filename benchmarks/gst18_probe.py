"""Helper gst18: grow stripes p2s10 per-kind census (exemplar, size levels, priorities, output).

    PYTHONPATH=src python benchmarks/gst18_probe.py [VARIANT=10] [SEEDS=1]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from types import SimpleNamespace

from strew.grow._analysis import size_priority, default_priority, analyze
from grow_variants import run
from strew.metrics import fidelity


def inner_density(arr, margin):
    x0, y0, x1, y1 = arr.region.bounds
    m = (arr.x > x0 + margin) & (arr.x < x1 - margin) & (arr.y > y0 + margin) & (arr.y < y1 - margin)
    area = (x1 - x0 - 2 * margin) * (y1 - y0 - 2 * margin)
    return {k: 1e4 * np.count_nonzero(m & (arr.kind == i)) / area for i, k in enumerate(arr.kinds)}


mk = fidelity_suite()
v = int(sys.argv[1]) if len(sys.argv) > 1 else 10
seeds = [int(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "1").split(",")]
ex = mk.make_exemplar("stripes", rng=v, **(_variants.VARIED.get("stripes", []) + _variants.EDGE.get("stripes", []))[2])
for i, k in enumerate(ex.kinds):
    sh = ex.shapes[k]
    sel = ex.kind == i
    print(k, "n", sel.sum(), "radius", round(float(sh.radius), 2), "area", round(float(getattr(sh, 'area', float('nan'))), 2), "scale", np.median(np.abs(ex.scale[sel])))
print("size_priority", size_priority(ex))
ref = analyze(ex)
print("default_priority", default_priority(ref))
print("exemplar density", inner_density(ex, 0))
for s in seeds:
    out, sc = run(ex, 3.5, s, SimpleNamespace(mode="fixed", times=10.0))
    rep = fidelity(ex, out, eq5=False, local=False)
    print("seed", s, "n", len(out), "density", {k: round(d, 2) for k, d in inner_density(out, 0).items()},
          "fails", [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed])

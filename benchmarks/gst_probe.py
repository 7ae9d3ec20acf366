"""Helper gst: grow stripes EDGE p2 census at a variant seed: per-kind densities, dot nn quantiles.

    PYTHONPATH=src python benchmarks/gst_probe.py [VARIANT=13] [SEEDS=1] [GROW_KW, e.g. relax=False]
"""
import os
import sys
from types import SimpleNamespace

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from grow_variants import run

from strew.grow._analysis import size_priority
from strew import _fidelity
from strew.metrics import fidelity

_calls = []
_disc = _fidelity._discrepancies


def _spy(a, b, kinds, s, **kw):
    _calls.append((a, b, kinds, s))
    return _disc(a, b, kinds, s, **kw)


_fidelity._discrepancies = _spy


def deciles(kind):
    """The judge's nn[kind>kind] deciles (result, exemplar), in units of s, first call."""
    a, b, kinds, s = _calls[0]
    i = kinds.index(kind)
    return np.round(a.nn[i, i] / s, 3), np.round(b.nn[i, i] / s, 3)


def inner_density(arr, margin):
    x0, y0, x1, y1 = arr.region.bounds
    m = (arr.x > x0 + margin) & (arr.x < x1 - margin) & (arr.y > y0 + margin) & (arr.y < y1 - margin)
    area = (x1 - x0 - 2 * margin) * (y1 - y0 - 2 * margin)
    return {k: round(1e4 * np.count_nonzero(m & (arr.kind == i)) / area, 2) for i, k in enumerate(arr.kinds)}


def nn_q(arr, kind):
    i = arr.kinds.index(kind)
    p = np.c_[arr.x, arr.y][arr.kind == i]
    d, _ = cKDTree(p).query(p, 2)
    return np.round(np.quantile(d[:, 1], [0.1, 0.25, 0.5, 0.75, 0.9, 0.97]), 2)


mk = fidelity_suite()
v = int(sys.argv[1]) if len(sys.argv) > 1 else 13
seeds = [int(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "1").split(",")]
ex = mk.make_exemplar("stripes", rng=v, **(_variants.VARIED.get("stripes", []) + _variants.EDGE.get("stripes", []))[2])
for i, k in enumerate(ex.kinds):
    print(k, "n", int((ex.kind == i).sum()), "radius", round(float(ex.shapes[k].radius), 2))
print("size_priority", size_priority(ex))
print("exemplar density", inner_density(ex, 0), "dot nn q", nn_q(ex, "dot"), "bar nn q", nn_q(ex, "bar"))
for s in seeds:
    kw = {k: eval(v) for k, v in (a.split("=") for a in sys.argv[3:])}
    if kw:
        import grow_variants
        from strew.grow import grow as _grow
        grow_variants.grow = lambda *a, **k: _grow(*a, **{**k, **kw})
    out, sc = run(ex, 3.5, s, SimpleNamespace(mode="fixed", times=10.0))
    _calls.clear()
    rep = fidelity(ex, out, eq5=False, local=False)
    r, e = deciles("dot")
    print("   dot>dot deciles/s result", r, "\n                     exemplar", e, "diff", np.round(r - e, 3))
    print("seed", s, "n", len(out), "density", inner_density(out, 0), "dot nn q", nn_q(out, "dot"), "bar nn q", nn_q(out, "bar"))
    print("   fails", [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed])

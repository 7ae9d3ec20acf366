"""Helper g31r: grow's own rows on the fresh draw, measured (issue 14 point 1).

    PYTHONPATH=src python benchmarks/g31r_probe.py CLASS:LABEL SEED [--save F.pkl] [--load F.pkl]

Grows the ``--varied`` row as ``grow_variants.py`` does (3.5x, fixed mode), then prints
the failing metrics and every density, g and nn metric (value/tolerance; the result's
and exemplar's statistic where the judge has one) and, for one-kind rows, the quantiles
of each element's least shape-to-shape gap in the exemplar and the output.
"""
import os
import pickle
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from types import SimpleNamespace

import numpy as np
import shapely
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run

from strew.metrics import fidelity


def shape_stats(arr):
    geo = np.asarray(arr.geometry)
    tree = shapely.STRtree(geo)
    r = np.sqrt(np.max([shapely.area(g) for g in geo[:5]]))
    a, b = tree.query(geo, predicate="dwithin", distance=3 * r)
    keep = a < b
    a, b = a[keep], b[keep]
    d = shapely.distance(geo[a], geo[b])
    gap = np.full(len(geo), np.inf)
    np.minimum.at(gap, a, d)
    np.minimum.at(gap, b, d)
    return gap


def main():
    spec, seed = sys.argv[1], int(sys.argv[2])
    cls, label = spec.split(":")
    ex = exemplar(fidelity_suite(), cls, label)
    if "--load" in sys.argv:
        with open(sys.argv[sys.argv.index("--load") + 1], "rb") as f:
            out = pickle.load(f)
    else:
        out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
    if "--save" in sys.argv:
        with open(sys.argv[sys.argv.index("--save") + 1], "wb") as f:
            pickle.dump(out, f)
    rep = fidelity(ex, out, eq5=False, local=False)
    print(f"{spec} seed {seed}: n={len(out)} ex n={len(ex)} faithful={rep.faithful}")
    for k, m in rep.metrics.items():
        if not m.applicable:
            continue
        if (not m.passed) or k.startswith(("g[", "density", "nn[")):
            print(f"  {k}: {m.value:.4g}/{m.tolerance:.4g} res={np.asarray(m.result, float) if m.result is not None else None} ex={np.asarray(m.exemplar, float) if m.exemplar is not None else None}")
    if len(set(np.asarray(ex.kind))) == 1:
        for name, a in (("ex", ex), ("out", out)):
            gap = shape_stats(a)
            gap = gap[np.isfinite(gap)]
            print(f"  {name} least shape gap q0/5/10/50: {np.round(np.quantile(gap, [0, .05, .1, .5]), 3)}")


if __name__ == "__main__":
    main()

"""Helper g33s: Delaunay edge lengths (units s) of the exemplar's interior and grow's result, and grow's meta.

    PYTHONPATH=src python benchmarks/g33s_edges.py CLASS:LABEL SEED

Edges with both ends farther from the frame than 2 s; quantiles and the shares beyond
1.5 s and 2 s (the exemplar's long edges span its empty spaces); then the keys of the
result's ``meta`` that count seeds and refusals.
"""
import os
import sys
from types import SimpleNamespace

import numpy as np
from scipy.spatial import Delaunay, cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402
from grow_variants import run  # noqa: E402


def edges(a, s):
    h = np.asarray(a.columns["void"], bool) if "void" in a.columns else np.zeros(len(a), bool)
    p = a.xy[~h]
    x0, y0, x1, y1 = a.region.bounds
    db = np.minimum.reduce([p[:, 0] - x0, x1 - p[:, 0], p[:, 1] - y0, y1 - p[:, 1]])
    t = Delaunay(p)
    e = np.r_[t.simplices[:, [0, 1]], t.simplices[:, [1, 2]], t.simplices[:, [0, 2]]]
    e = np.unique(np.sort(e, 1), axis=0)
    e = e[(db[e[:, 0]] > 2 * s) & (db[e[:, 1]] > 2 * s)]
    L = np.hypot(*(p[e[:, 0]] - p[e[:, 1]]).T) / s
    return L


def main():
    spec, seed = sys.argv[1], int(sys.argv[2])
    cls, label = spec.split(":")
    ex = exemplar(fidelity_suite(), cls, label)
    h = np.asarray(ex.columns["void"], bool) if "void" in ex.columns else np.zeros(len(ex), bool)
    s = float(np.median(cKDTree(ex.xy[~h]).query(ex.xy[~h], 2)[0][:, 1]))
    out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
    for name, a in (("exemplar", ex), (f"grow seed {seed}", out)):
        L = edges(a, s)
        print(f"  {spec} {name}: {len(L)} interior edges; quantiles .1 .5 .9 .99 {np.round(np.quantile(L, [.1, .5, .9, .99]), 3)}; > 1.5 s {np.mean(L > 1.5):.3f}; > 2 s {np.mean(L > 2):.3f}")
    st = {k: v for k, v in (out.meta or {}).items() if k not in ("params",)}
    print("  meta:", {k: (v if not isinstance(v, (list, dict)) or len(str(v)) < 300 else str(v)[:300]) for k, v in st.items()})


if __name__ == "__main__":
    main()

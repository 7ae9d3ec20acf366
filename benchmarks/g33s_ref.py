"""Helper g33s: grow's reference (§4) of an exemplar: interior elements, and their 1-ring edges (units s).

    PYTHONPATH=src python benchmarks/g33s_ref.py CLASS:LABEL

How many exemplar elements are references (interior of the connectivity), per kind, how many
of them lie within spacing/2 of the frame (sparse_voids: the apple-free band), and the
quantiles of the references' 1-ring edge lengths (all kinds, and visible-visible) against
the exemplar's interior Delaunay edges (g33s_edges.py).
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402

from strew.grow._analysis import analyze  # noqa: E402


def main():
    spec = sys.argv[1]
    cls, label = spec.split(":")
    ex = exemplar(fidelity_suite(), cls, label)
    h = np.asarray(ex.columns["void"], bool) if "void" in ex.columns else np.zeros(len(ex), bool)
    s = float(np.median(cKDTree(ex.xy[~h]).query(ex.xy[~h], 2)[0][:, 1]))
    ref = analyze(ex)
    inter = np.flatnonzero(ref.interior) if ref.interior.dtype == bool else np.asarray(ref.interior)
    x0, y0, x1, y1 = ex.region.bounds
    db = np.minimum.reduce([ex.xy[:, 0] - x0, x1 - ex.xy[:, 0], ex.xy[:, 1] - y0, y1 - ex.xy[:, 1]])
    band = float(db[~h].min()) if h.any() else 0.0
    print(f"{spec}: {len(ex)} elements, {len(inter)} references; visible refs {int((~h[inter]).sum())}, hidden refs {int(h[inter].sum())}")
    if h.any():
        hb = h[inter] & (db[inter] < band)
        print(f"  hidden refs inside the apple-free band (< {band:.1f} from frame): {int(hb.sum())}")
        # 1-rings of hidden refs: share with no visible neighbour
        nov = [int(i) for i in inter if h[i] and not (~h[np.asarray(ref.rings[i])]).any()]
        print(f"  hidden refs whose 1-ring has no visible element: {len(nov)} ({len(nov) / max(int(h[inter].sum()), 1):.0%}); of them in the band {sum(db[i] < band for i in nov)}")
    L, Lv = [], []
    for i in inter:
        for j in np.asarray(ref.rings[i]):
            d = np.hypot(*(ex.xy[i] - ex.xy[j])) / s
            L.append(d)
            if not h[i] and not h[j]:
                Lv.append(d)
    L = np.asarray(L)
    print(f"  reference 1-ring edges: {len(L)}; quantiles .1 .5 .9 .99 {np.round(np.quantile(L, [.1, .5, .9, .99]), 3)}; > 1.5 s {np.mean(L > 1.5):.3f}; > 2 s {np.mean(L > 2):.3f}")


if __name__ == "__main__":
    main()

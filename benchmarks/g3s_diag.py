"""Helper g3s: where a --harder three_sizes row fails: per-kind nn deciles and density, exemplar vs grown.

    PYTHONPATH=src python benchmarks/g3s_diag.py three_sizes:0:12 1 [--save DIR]

Prints, for each ordered kind pair, the deciles (10..90 %) of the distance from each
element of kind a to its nearest of kind b (in units of the exemplar's median nn
distance s; interior elements only), for exemplar (E) and output (O), and the fidelity
failures. ``--save DIR`` pickles exemplar and output.
"""
import os
import pickle
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def deciles(arr, names, s, box):
    xy = np.c_[arr.x, arr.y]

    names_arr = np.asarray(arr.kind_names)
    x0, y0, x1, y1 = box
    edge = np.minimum.reduce([xy[:, 0] - x0, x1 - xy[:, 0], xy[:, 1] - y0, y1 - xy[:, 1]])
    out = {}
    for a in names:
        ia = np.flatnonzero(names_arr == a)
        for b in names:
            ib = np.flatnonzero(names_arr == b)
            if len(ib) < 2 or len(ia) < 2:
                continue
            t = cKDTree(xy[ib])
            d, j = t.query(xy[ia], k=2)
            dd = np.where(ib[j[:, 0]] == ia, d[:, 1], d[:, 0])
            ok = dd <= edge[ia]
            out[(a, b)] = np.quantile(dd[ok], np.linspace(0.1, 0.9, 9)) / s
    return out


def main():
    cls, i, v = sys.argv[1].split(":")
    seed = int(sys.argv[2])
    mk = _harder_suite()
    ex = mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    rep = fidelity(ex, out, eq5=False, local=False)
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    print(sys.argv[1], seed, "n", len(out), "FAIL" if fails else "pass", fails)
    names = ["small", "medium", "large"]
    exy = np.c_[ex.x, ex.y]
    s = np.median(cKDTree(exy).query(exy, k=2)[0][:, 1])
    de = deciles(ex, names, s, ex.region.bounds)
    do = deciles(out, names, s, out.region.bounds if out.region is not None else (0, 0, 3.5 * (x1 - x0), 3.5 * (y1 - y0)))
    for key in de:
        print(f"  {key[0]:>6}>{key[1]:<6} E " + " ".join(f"{x:5.2f}" for x in de[key]))
        print(f"  {'':>13} O " + " ".join(f"{x:5.2f}" for x in do[key]) + f"   mean|d|={np.mean(np.abs(de[key]-do[key])):.3f}")
    for k, m in rep.metrics.items():
        if k.startswith(("density", "fraction")) and m.applicable:
            print(f"  {k}: ex {m.exemplar} out {m.result} val {m.value:.3g}/{m.tolerance:.3g}")
    if "--save" in sys.argv:
        d = sys.argv[sys.argv.index("--save") + 1]
        with open(os.path.join(d, f"{cls}_{i}_{v}_{seed}.pkl"), "wb") as f:
            pickle.dump((ex, out), f)


if __name__ == "__main__":
    main()

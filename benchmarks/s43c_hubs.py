"""Helper s43c: far-hub (disc) spacing in exemplar and synth output, --varied clusters set 2.

    PYTHONPATH=src:benchmarks python benchmarks/s43c_hubs.py p2s27,p2s29 1

Prints disc count, area per disc, and the medians of the 1st-4th nearest disc distances
over discs deeper than 120 from the frame (output) / all discs (exemplar, few), the number
of discs within 100 of each disc, and dots a disc; then fidelity failures.
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, "benchmarks")
from fresh17_rows import exemplar
from _runner import fidelity_suite
from synth_variants import run
from strew.metrics import fidelity


def stats(arr, tag, deep):
    xy = arr.xy
    big = np.asarray(arr.kind_names) == "disc"
    d = xy[big]
    x0, y0, x1, y1 = arr.region.bounds
    dep = np.minimum.reduce([d[:, 0] - x0, x1 - d[:, 0], d[:, 1] - y0, y1 - d[:, 1]])
    t = cKDTree(d)
    k = min(5, len(d))
    nn, _ = t.query(d, k=k)
    sel = dep >= deep if (dep >= deep).sum() >= 3 else np.ones(len(d), bool)
    within = t.query_ball_point(d, 100.0, return_length=True) - 1
    dots = cKDTree(d).query(xy[~big])[1]
    per = np.bincount(dots, minlength=len(d))
    area = (x1 - x0) * (y1 - y0)
    print(f"  {tag}: discs {len(d)} area/disc {area / len(d):.0f}  nn1-4 median (deep {sel.sum()}) "
          + " ".join(f"{np.median(nn[sel, j]):.1f}" for j in range(1, k))
          + f"  within100 mean {within[sel].mean():.2f} max {within[sel].max()}  dots/disc {per[sel].mean():.2f}")


def main():
    labels, seeds = sys.argv[1].split(","), [int(s) for s in sys.argv[2].split(",")]
    mk = fidelity_suite()
    for lab in labels:
        ex = exemplar(mk, "clusters", lab)
        print(lab)
        stats(ex, "exemplar", 0.0)
        for s in seeds:
            out, _ = run(ex, 3.5, s, None)
            stats(out, f"seed {s}", 120.0)
            rep = fidelity(ex, out, eq5=False, local=False)
            print("   ", "pass" if rep.faithful else "FAIL", " ".join(f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed))


main()

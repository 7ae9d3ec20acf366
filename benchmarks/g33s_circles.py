"""Helper g33s: how many apple holes wider than grow's fill limit the class's own generator leaves.

    PYTHONPATH=src python benchmarks/g33s_circles.py CLASS:LABEL SIZE LIM [DRAWS]

Counts whole Delaunay circumcircles of the apples (centre inside the frame, circle inside it)
with radius > LIM in the generator drawn at SIZE x SIZE (``g33s_probe.sparse_oracle``,
dart counts scaled by the area), per 1000 apples, and the apples' density (judge) there.
"""
import os
import sys

import numpy as np
from scipy.spatial import Delaunay

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402
from g33s_probe import sparse_oracle  # noqa: E402

from strew._kernels.geometry import circumcircles  # noqa: E402
from strew.metrics import fidelity  # noqa: E402


def wide(a, lim):
    h = np.asarray(a.columns["void"], bool)
    p = a.xy[~h]
    t = Delaunay(p)
    cen, r, _ = circumcircles(*(p[t.simplices[:, q]] for q in range(3)))
    inner = a.region.contains(cen) & (a.region.distance_to_boundary(cen) >= r)
    return int((inner & (r > lim)).sum()), int(inner.sum()), len(p)


def main():
    spec, size, lim = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    draws = int(sys.argv[4]) if len(sys.argv) > 4 else 2
    cls, label = spec.split(":")
    ex = exemplar(fidelity_suite(), cls, label)
    print(f"{spec} exemplar: wide/whole/apples {wide(ex, lim)}")
    v = int(label.split("s")[-1]) if "s" in label else int(label[1:])
    for d in range(draws):
        o = sparse_oracle(ex.meta["params"], size, v + 1000 * (d + 1))
        w, n, k = wide(o, lim)
        m = fidelity(ex, o, eq5=False, local=False).metrics["density[apple]"]
        print(f"  oracle draw {d} size {size:.0f}: whole circles > {lim:.2f}: {w} of {n} ({1000 * w / k:.0f} per 1000 apples), apples {k}, density {m.result / m.exemplar:.3f}x")


if __name__ == "__main__":
    main()

"""Helper g33s: stones p2s23's generator at the output's size (svar13i_oracle.big_params), judged.

    PYTHONPATH=src python benchmarks/g33s_stones_oracle.py CLASS:LABEL [DRAWS]

Prints per draw the verdict, n, density and empty_circle (result/exemplar) and the
nearest-neighbour deciles in exemplar units s, to set against grow's (g33s_ab.py, g33s_probe.py).
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402
from svar13i_oracle import big_params  # noqa: E402

from strew.metrics import fidelity  # noqa: E402


def main():
    spec = sys.argv[1]
    draws = int(sys.argv[2]) if len(sys.argv) > 2 else 2
    cls, label = spec.split(":")
    mk = fidelity_suite()
    ex = exemplar(mk, cls, label)
    kw = dict(ex.meta["params"])
    v = int(label.split("s")[-1]) if "s" in label else int(label[1:])
    s = float(np.median(cKDTree(ex.xy).query(ex.xy, 2)[0][:, 1]))
    big = big_params(cls, kw, 3.5)
    print(f"{spec}: exemplar n={len(ex)}; oracle params {big}")
    for d in range(draws):
        o = mk.make_exemplar(cls, rng=v + 1000 * d, **big)
        rep = fidelity(ex, o, eq5=False, local=False)
        m, e = rep.metrics[f"density[{ex.kinds[0]}]"], rep.metrics["empty_circle"]
        nn = cKDTree(o.xy).query(o.xy, 2)[0][:, 1]
        fails = [f"{k}={x.value:.3g}/{x.tolerance:.3g}" for k, x in rep.metrics.items() if x.applicable and not x.passed]
        print(f"  draw {d}: {'pass' if rep.faithful else 'FAIL'} n={len(o)} density {m.result / m.exemplar:.3f}x empty_circle {e.value:.3f} ({e.result:.1f} vs {e.exemplar:.1f}) nn deciles/s {np.round(np.quantile(nn, np.linspace(.1, .9, 9)) / s, 3)} {' '.join(fails)}")


if __name__ == "__main__":
    main()

"""Helper s32t: where synth's nearest-neighbour distances depart from the exemplar's on
chosen rows (the fidelity judge's ``nn[a>b]`` deciles, in units of ``s``).

    PYTHONPATH=src python benchmarks/s32t_nn.py sticks:p1s19,sticks:p1s20 1

Prints per row and seed the exemplar's and the output's nn deciles (10 ... 90 %) over
``s`` as the judge measures them (border-corrected), their signed difference
(output - exemplar) and the metric (mean absolute difference).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants  # noqa: E402
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402
from synth_variants import run  # noqa: E402

from strew import _fidelity  # noqa: E402
from strew.metrics import fidelity  # noqa: E402

GOT: list = []
_disc = _fidelity._discrepancies


def _keep(a, b, *args, **kw):
    GOT.append((a, b, args[1]))
    return _disc(a, b, *args, **kw)


_fidelity._discrepancies = _keep
mk = fidelity_suite()
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    for seed in _variants.ints(sys.argv[2]):
        GOT.clear()
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, out.region)
        a, b, s = GOT[0]
        ra, rb = np.asarray(a.nn[0, 0]) / s, np.asarray(b.nn[0, 0]) / s
        f = lambda v: " ".join(f"{x:6.3f}" for x in v)
        print(f"{spec} seed {seed} n={len(out)} s={s:.3f} verdict {'pass' if rep.faithful else 'FAIL'}\n  exemplar {f(rb)}\n  output   {f(ra)}\n  out-ex   {f(ra - rb)}  metric {np.mean(np.abs(ra - rb)):.4f}", flush=True)

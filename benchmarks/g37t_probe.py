"""Helper g37t: the hole pass's second round (``toward``) on one row, with it and without.

    ROW=three_sizes:7:23 SEEDS=1 PYTHONPATH=src python benchmarks/g37t_probe.py

Grows the row as ``grw14y_rows.py`` twice (second round off: ``fill_void_holes(toward=True)``
returns 0; on) and prints the fills of each round, the judge's density / nn / empty_circle
figures of the smallest kind (result and exemplar), and the second round's budget
(``small_budget``, where the tree has it) before each of its calls.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

import strew.grow._growth as gr
import strew.grow._void_holes as vh
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

orig = vh.fill_void_holes
log = []
OFF = [False]


def wrapped(g, lim=None, bare=False, toward=False):
    if toward and OFF[0]:
        return 0
    pre = vh.small_budget(g) if toward and hasattr(vh, "small_budget") else None
    n = orig(g, lim, bare, toward)
    log.append((toward, n, pre))
    return n


gr.fill_void_holes = wrapped
cls, i, v = os.environ.get("ROW", "three_sizes:7:23").split(":")
a, _, b = os.environ.get("SEEDS", "1").partition("-")
ex = _harder_suite().make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
x0, y0, x1, y1 = ex.region.bounds
for seed in range(int(a), int(b or a) + 1):
    for off in (True, False):
        OFF[0] = off
        log.clear()
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        rep = fidelity(ex, out, eq5=False, local=False)
        m = rep.metrics
        print(f"seed {seed} second round {'off' if off else 'on '}: fills {[(int(t), n) for t, n, _ in log]} budgets {[p for _, _, p in log if p is not None]}")
        for k, x in m.items():
            if x.applicable and ("small" in k or "pebble" in k or k == "empty_circle" or not x.passed):
                r = "" if x.result is None else f" res {x.result:.4g} ex {x.exemplar:.4g}"
                print(f"   {k:24s} {x.value:.4f}/{x.tolerance:.4f} {'ok' if x.passed else 'FAIL'}{r}")
        print(f"   faithful {rep.faithful}", flush=True)

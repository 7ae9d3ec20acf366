"""Helper g43m: per-kind density (the judge's) of a grow row after each pass.

    ROW=three_sizes:7:30 SEEDS=1-6 PYTHONPATH=src:benchmarks python benchmarks/g43m_probe.py

Wraps ``_Grower._rounds`` / ``advance`` and after growth and each pass takes the result so
far and prints the judge's density ratio per kind (result / exemplar) and the counts.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

import strew.grow._growth as gr
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

cls, i, v = os.environ.get("ROW", "three_sizes:7:30").split(":")
a, _, b = os.environ.get("SEEDS", "1").partition("-")
ex = _harder_suite().make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
x0, y0, x1, y1 = ex.region.bounds
names = [s.name if hasattr(s, "name") else str(k) for k, s in enumerate(ex.shapes)]
snap = []
orig_rounds, orig_run = gr._Grower._rounds, gr._Grower.run


def take(g, label):
    out = g.result({})
    rep = fidelity(ex, out, eq5=False, local=False)
    d = {k: (m.result, m.exemplar, m.value, m.passed) for k, m in rep.metrics.items() if k.startswith("density") and m.applicable}
    cnt = np.bincount(out.kind, minlength=len(ex.shapes))
    snap.append((label, cnt, d, [k for k, m in rep.metrics.items() if m.applicable and not m.passed]))


def rounds(self, one_pass, rep, target):
    orig_rounds(self, one_pass, rep, target)
    name = getattr(one_pass, "__name__", "?")
    try:
        import inspect
        src = inspect.getsource(one_pass).strip() if name == "<lambda>" else name
    except Exception:
        src = name
    take(self, src[-40:])


def run(self, start, rep):
    adv = self.advance
    first = [True]

    def advance(rep_, target, pause=None):
        r = adv(rep_, target, pause)
        if first[0]:
            first[0] = False
            take(self, "growth")
        return r
    self.advance = advance
    orig_run(self, start, rep)
    take(self, "settled")


gr._Grower._rounds = rounds
gr._Grower.run = run
for seed in range(int(a), int(b or a) + 1):
    snap.clear()
    grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    print(f"seed {seed}: exemplar counts {np.bincount(ex.kind, minlength=len(ex.shapes))}")
    for label, cnt, d, fails in snap:
        ds = " ".join(f"{k[8:-1]}={r / e:.3f}" for k, (r, e, val, ok) in d.items())
        print(f"  {label:42s} n={cnt} {ds} fails={fails}")
    sys.stdout.flush()

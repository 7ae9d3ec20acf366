"""Helper g44r: chosen ``--varied`` grow rows at chosen seeds, every applicable metric
within 0.01 of its tolerance (or failing) printed, and the least margin; run it on two
trees (PYTHONPATH) to see whether a change moved a row near its tolerance.

    PYTHONPATH=src:benchmarks python benchmarks/g44r_margins.py CLASS:LABEL[,...] SEEDS

LABEL as ``--varied`` (v29, p2s29) or ``--harder`` (h2s29) labels it.
"""
import os
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import HARDER, _harder_suite, run

import strew
from strew.metrics import fidelity

mk = fidelity_suite()
hk = _harder_suite()
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    if label.startswith("h"):  # a --harder set: h<i>s<variant>
        i, _, v = label[1:].partition("s")
        ex = hk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    else:
        ex = exemplar(mk, cls, label)
    for seed in _variants.ints(sys.argv[2]):
        out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
        rep = fidelity(ex, out, eq5=False, local=False)
        app = {k: m for k, m in rep.metrics.items() if m.applicable}
        worst = min(app, key=lambda k: app[k].tolerance - app[k].value)
        near = " ".join(f"{k}={m.value:.4f}/{m.tolerance:.4g}" for k, m in app.items() if m.value > m.tolerance - 0.01)
        print(f"{spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} least margin {app[worst].tolerance - app[worst].value:+.4f} ({worst}) near: {near}", flush=True)
print(strew.__file__)

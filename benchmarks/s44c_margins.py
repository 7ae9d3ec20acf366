"""Helper s44c: the three metrics nearest their tolerance for chosen --varied synth rows.

    PYTHONPATH=src:benchmarks python benchmarks/s44c_margins.py clusters:p2s25,clusters:p2s26 1

A label ``hIsV`` is a --harder row (set I, variant seed V).
"""
import sys

sys.path.insert(0, "benchmarks")
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run

import strew
from strew.metrics import fidelity

mk = fidelity_suite()
print(strew.__file__)
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    if label.startswith("h"):
        from grow_variants import _harder_suite
        from synth_variants import _harder

        i, _, v = label[1:].partition("s")
        ex = _harder_suite().make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    else:
        ex = exemplar(mk, cls, label)
    for seed in [int(s) for s in sys.argv[2].split(",")]:
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        ms = sorted(((m.tolerance - m.value, k, m.value, m.tolerance) for k, m in rep.metrics.items() if m.applicable), key=lambda t: t[0])[:3]
        print(f"{spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} " + "  ".join(f"{k}={v:.3g}/{t:.3g} ({mg:+.3f})" for mg, k, v, t in ms), flush=True)

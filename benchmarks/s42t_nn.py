"""Helper s42t: a --varied row's nn[a>b] signed decile errors (output - exemplar, in s) and
failing metrics, with constants of strew.synth._grow set first.

    PYTHONPATH=src:benchmarks python benchmarks/s42t_nn.py three_sizes:p4s27 1,2 large medium [G.OWN_COVER=0.27 ...]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from fresh17_rows import exemplar
from _runner import fidelity_suite
from syn13z_rows import nnq
from synth_variants import run

import strew.synth._grow as G
from strew.metrics import fidelity

spec, seeds, a, b = sys.argv[1:5]
for kv in sys.argv[5:]:
    k, v = kv.split("=")
    setattr(G, k.split(".")[1], eval(v))
cls, label = spec.split(":")
ex = exemplar(fidelity_suite(), cls, label)
for seed in [int(s) for s in seeds.split(",")]:
    out, _ = run(ex, 3.5, seed, None)
    rep = fidelity(ex, out, eq5=False, local=False)
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    print(f"{spec} seed {seed} {'pass' if rep.faithful else 'FAIL'} {' '.join(fails)} nn[{a}>{b}] dec(out-ex)/s {np.round((nnq(out, a, b) - nnq(ex, a, b)) / rep.s, 2)}", flush=True)

"""Helper s70p: nn[pebble>pebble] deciles (units of s) of the exemplar, synth's output and
the exemplar's own generator at the output's size, on --varied two_sizes rows; optional
--skip PASS (a synth pass replaced by a no-op, to see what it contributes).

    PYTHONPATH=src:benchmarks python benchmarks/s70p_probe.py two_sizes:p4s43 1-6 [--skip fill_holes] [--oracle]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from svar13i_oracle import big_params
from synth_variants import run

import strew._fidelity as F
import strew.synth._grow as G
from strew.metrics import fidelity

CAP = {}
_disc = F._discrepancies


def disc(a, b, *args, **kw):
    CAP.setdefault("ab", []).append((a, b))
    return _disc(a, b, *args, **kw)


F._discrepancies = disc
args = sys.argv[1:]
if "--skip" in args:
    name = args[args.index("--skip") + 1]
    setattr(G, name, lambda state, *a, **k: None)
np.set_printoptions(precision=3, suppress=True, linewidth=220)


def show(tag, ex, out):
    CAP.clear()
    rep = fidelity(ex, out, eq5=False, local=False)
    a, b = CAP["ab"][0]
    ks = ex.kinds
    s = rep.metrics["nn[" + ks[0] + ">" + ks[0] + "]"]
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    sc = float(rep.metrics["empty_circle"].exemplar) if False else None
    line = f" {tag}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} counts {dict(zip(ks, a.counts))} dens " + \
        " ".join(f"{k} {a.density[i] / b.density[i] - 1:+.3f}" for i, k in enumerate(ks)) + " " + " ".join(fails)
    print(line)
    for i, ki in enumerate(ks):
        for j, kj in enumerate(ks):
            m = rep.metrics[f"nn[{ki}>{kj}]"]
            print(f"    nn[{ki}>{kj}] {m.value:.3f}/{m.tolerance:.3f} out {a.nn[i, j]} ex {b.nn[i, j]}")
    return rep


mk = fidelity_suite()
for spec in args[0].split(","):
    cls, label = spec.split(":")
    i, _, v = label[1:].partition("s")
    kw = (_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)]
    ex = mk.make_exemplar(cls, rng=int(v), **kw)
    print(f"== {spec} {kw} exemplar n={len(ex)}", flush=True)
    if "--oracle" in args:
        for d in range(2):
            show(f"oracle {d}", ex, mk.make_exemplar(cls, rng=int(v) + 1000 * d, **big_params(cls, kw, 3.5)))
    for seed in _variants.ints(args[1]):
        out, _ = run(ex, 3.5, seed, None)
        show(f"seed {seed}", ex, out)
        sys.stdout.flush()

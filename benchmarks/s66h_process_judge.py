"""Helper s66h: judge fresh samples of the exemplar's own generator at the output's size (3.5 x 300 = 1050)
against a --harder clusters exemplar: what a perfectly faithful synth would score (empty_circle, verdict).

    PYTHONPATH=src:benchmarks python benchmarks/s66h_process_judge.py LABEL RNGS

LABEL: h4s9 (--harder clusters set 4, variant seed 9) or p2s21 (--varied/EDGE set, as fresh17_rows.py);
variant seeds <= 38 only. RNGS: generator seeds of the samples (e.g. 1-8; the sample's own seed, not a
variant seed of any suite).
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.metrics import fidelity

label = sys.argv[1]
idx, _, v = label[1:].partition("s")
idx, v = int(idx), int(v)
assert v <= 38, "held-out variant seeds"
mk = _harder_suite()
sets = _harder()["clusters"] if label[0] == "h" else _variants.VARIED.get("clusters", []) + _variants.EDGE.get("clusters", [])
p = dict(sets[idx])
ex = mk.make_exemplar("clusters", rng=v, **p)
print(f"== clusters {label} {p} exemplar n={len(ex)}")
for r in _variants.ints(sys.argv[2]):
    out = mk.make_exemplar("clusters", rng=r, size=1050.0, **p)
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["empty_circle"]
    fails = [f"{k}={x.value:.3g}/{x.tolerance:.3g}" for k, x in rep.metrics.items() if x.applicable and not x.passed]
    k = np.asarray(out.kind)
    print(f" generator sample rng {r} (1050x1050): {'pass' if rep.faithful else 'FAIL'} n={len(out)} discs {np.sum(k == 0)} "
          f"dots/disc {np.sum(k == 1) / np.sum(k == 0):.2f} empty_circle {m.value:.3f}/{m.tolerance:.3f} {' '.join(fails)}", flush=True)

"""Helper s72q counterfactual (probe only, src untouched): s70t_counter.py for --varied ``p`` rows: right after
growth remove a share F of the largest class's visible stones at random (own Generator, seed 7) so the later
passes refill the room; then judge (eq5, local off). F=0 is main.

    PYTHONPATH=src:benchmarks python benchmarks/s72q_counter.py F three_sizes:p4s46:1,2,3 [...]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from synth_variants import run

import strew.synth._grow as G
from strew.metrics import fidelity

F = float(sys.argv[1])
_car = G._complete_anchor_rings


def car(state, *a, **k):
    if F > 0:
        prep = state.prep
        vis = ~prep.void[state.src[: state.n]]
        top = int(prep.skind.max())
        lg = vis & (prep.skind[state.src[: state.n]] == top)
        pick = np.flatnonzero(lg)
        g = np.random.default_rng(7)
        drop = g.choice(pick, int(round(F * len(pick))), replace=False)
        mask = np.zeros(state.n, bool)
        mask[drop] = True
        state.remove(mask)
    return _car(state, *a, **k)


G._complete_anchor_rings = car
mk = fidelity_suite()
for spec in sys.argv[2:]:
    cls, label, seeds = spec.split(":")
    i, _, v = label[1:].partition("s")
    ex = mk.make_exemplar(cls, rng=int(v), **(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)])
    for s in [int(x) for x in seeds.split(",")]:
        out, _ = run(ex, 3.5, s, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        m = rep.metrics["nn[medium>medium]"]
        print(f"F={F} {cls} {label} seed {s}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} counts {np.bincount(out.kind)} nn[m>m] {m.value:.3f}/{m.tolerance:.3f} {' '.join(fails)}", flush=True)

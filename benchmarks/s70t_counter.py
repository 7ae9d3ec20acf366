"""Helper s70t counterfactual (probe only, src untouched): right after growth (before _complete_anchor_rings),
remove a share F of the largest class's visible stones at random (own Generator, seed 7), so the later passes
(fill_displaced ... fill_holes) refill the room; then judge. F=0 is main.

    PYTHONPATH=src:benchmarks python benchmarks/s70t_counter.py F three_sizes:11:44:1,2,3 [...]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from syn13z_rows import counts, nnq
from synth_variants import _harder, run

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
mk = _harder_suite()
for spec in sys.argv[2:]:
    cls, h, v, seeds = spec.split(":")
    ex = mk.make_exemplar(cls, rng=int(v), **_harder()[cls][int(h)])
    for s in [int(x) for x in seeds.split(",")]:
        out, _ = run(ex, 3.5, s, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        m = rep.metrics["nn[medium>medium]"]
        print(f"F={F} {cls} h{h}s{v} seed {s}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} nn[m>m] {m.value:.3f}/{m.tolerance:.3f} {' '.join(fails)}"
              f" inner20 {counts(out, 20)} nn[m>m] dec {np.round(nnq(out, 'medium', 'medium'), 1)}", flush=True)

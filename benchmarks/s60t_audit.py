"""Helper s60t: the three_sizes audit rows (--varied v, p0-p4 and --harder h0-h13) at the given
variant seeds, seed 1, but only where ``_grow._own_setup`` keeps the exemplar (elsewhere
``_top_ahead`` is never evaluated and the output is main's byte for byte: printed as
``not kept``). Per run: verdict, failing metrics, n, growth calls where the closed area was
measured and how many owned the class (acted=0: main's output too).

    PYTHONPATH=src:benchmarks python benchmarks/s60t_audit.py 25-34 [SEED]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import s60t_ahead_probe as P
from synth_variants import _harder, run

import strew.synth._grow as G
from strew.metrics import fidelity
from strew.synth._api import new_state

nv = len(_variants.VARIED.get("three_sizes", []) + _variants.EDGE.get("three_sizes", []))
nh = len(_harder()["three_sizes"])
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
G._top_ahead = P._logged
for v in _variants.ints(sys.argv[1]):
    for label in [f"v{v}"] + [f"p{i}s{v}" for i in range(nv)] + [f"h{i}s{v}" for i in range(nh)]:
        ex = P.exemplar(label)
        top, *_ = G._own_setup(new_state(ex).prep)
        if not top.any():
            print(f"{label}: not kept", flush=True)
            continue
        P.LOG.clear()
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        acts = sum(a for *_x, a in P.LOG)
        print(f"{label} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} calls={len(P.LOG)} acted={acts} {' '.join(fails)}", flush=True)

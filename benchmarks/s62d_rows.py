"""Helper s62d: --harder rows (labels hIsV, synth_variants._harder) of synth at several seeds, with
the nn[A>B] metric's signed deciles (output minus exemplar) printed for the failing kinds.

    PYTHONPATH=src:benchmarks python benchmarks/s62d_rows.py two_sizes:h8s36,two_sizes:h9s36 1-6
"""
import sys
import numpy as np
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder, run
from strew.metrics import fidelity

mk = _harder_suite()
H = _harder()
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    i, _, v = label[1:].partition("s")
    ex = mk.make_exemplar(cls, rng=int(v), **H[cls][int(i)])
    if "REACH" in globals():  # (s62d_counter.py MODE=window: the metric's wall reach of the exemplar)
        _cap = []
        F._wall_reach = lambda *a: (_cap.append(_wr(*a)), _cap[-1])[1]
        fidelity(ex, ex, eq5=False, local=False)
        F._wall_reach = _wr
        REACH["v"] = _cap[0]
        print(f"  {spec} exemplar wall reach {_cap[0]:.2f}", flush=True)
    kinds = sorted(set(e.kind for e in ex.elements)) if hasattr(ex, "elements") else None
    res = []
    for seed in _variants.ints(sys.argv[2]):
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        show = ("nn[stone>pebble]", "density[pebble]", "density[stone]", "nn[pebble>stone]", "nn[pebble>pebble]", "nn[stone>stone]")
        s = " ".join(f"{k}={m.value:.3g}/{m.tolerance:.3g}{'' if m.passed else '!'}" for k, m in rep.metrics.items() if m.applicable and (k in show or not m.passed))
        res.append(int(rep.faithful))
        print(f"  synth {spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {s}", flush=True)
    print(f"synth {spec} {sum(res)}/{len(res)}", flush=True)

"""Helper s62d: signed nn deciles (output minus exemplar, in units of s) and density ratios for --harder
rows of synth (labels hIsV), to tell too near / too far and too many / too few.

    PYTHONPATH=src:benchmarks python benchmarks/s62d_deciles.py two_sizes:h8s36 1,2
"""
import sys
import numpy as np
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import strew._fidelity as F
from grow_variants import _harder_suite
from synth_variants import _harder, run
from strew.metrics import fidelity

CAP = []
_orig = F._discrepancies


def _wrap(a, b, kinds, s, **kw):
    CAP.append((a, b, kinds, s))
    return _orig(a, b, kinds, s, **kw)


F._discrepancies = _wrap
mk = _harder_suite()
H = _harder()
np.set_printoptions(precision=2, suppress=True, linewidth=200)
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    i, _, v = label[1:].partition("s")
    ex = mk.make_exemplar(cls, rng=int(v), **H[cls][int(i)])
    print(f"== {spec} params {H[cls][int(i)]} exemplar counts", {k: int(np.sum(ex.kind == j)) for j, k in enumerate(ex.kinds)}, flush=True)
    for seed in _variants.ints(sys.argv[2]):
        CAP.clear()
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        a, b, kinds, s = CAP[0]
        print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} s={s:.2f} counts", {k: int(np.sum(out.kind == j)) for j, k in enumerate(out.kinds)})
        for k, name in enumerate(kinds):
            print(f"   density[{name}] out/ex = {a.density[k] / b.density[k]:.3f}")
        for p in range(len(kinds)):
            for q in range(len(kinds)):
                m = rep.metrics[f"nn[{kinds[p]}>{kinds[q]}]"]
                print(f"   nn[{kinds[p]}>{kinds[q]}] {m.value:.3f}/{m.tolerance:.3f}  ex deciles/s {b.nn[p, q] / s}  out-ex {(a.nn[p, q] - b.nn[p, q]) / s}", flush=True)

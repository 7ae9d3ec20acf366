"""Helper s70t: every judge metric of a --harder row's synth outputs (and the generator drawn 3.5x, 2 draws)
whose value is over half its tolerance, plus nn deciles (syn13z_rows.nnq) for the pairs given.

    PYTHONPATH=src:benchmarks python benchmarks/s70t_metrics.py three_sizes:h11s44 1,2,3 medium:medium large:large medium:large
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from syn13z_rows import nnq
from synth_variants import _harder, run

from strew.metrics import fidelity


def show(tag, ex, arr, pairs):
    rep = fidelity(ex, arr, eq5=False, local=False)
    big = {k: f"{m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and m.value > 0.5 * m.tolerance}
    print(f"  {tag:12s} {'pass' if rep.faithful else 'FAIL'} n={len(arr)} over half tol: {big}")
    for a, b in pairs:
        print(f"      nn[{a}>{b}] deciles {np.round(nnq(arr, a, b), 1)}")


cls, label = sys.argv[1].split(":")
i, _, v = label[1:].partition("s")
mk = _harder_suite()
kw = _harder()[cls][int(i)]
ex = mk.make_exemplar(cls, rng=int(v), **kw)
pairs = [tuple(p.split(":")) for p in sys.argv[3:]]
print(f"== {sys.argv[1]} exemplar n={len(ex)}")
for a, b in pairs:
    print(f"      nn[{a}>{b}] exemplar deciles {np.round(nnq(ex, a, b), 1)}")
bp = big_params(cls, kw, 3.5)
for d in range(2):
    show(f"oracle d{d}", ex, mk.make_exemplar(cls, rng=int(v) + 1000 * d, **bp), pairs)
for s in [int(x) for x in sys.argv[2].split(",")]:
    out, _ = run(ex, 3.5, s, None)
    show(f"synth {s}", ex, out, pairs)

"""Helper s27e: the class generator drawn at the output size (svar13i_oracle.big_params, 3.5x side),
at the variant seed + 1000 d for d < D, judged against the exemplar as synth is: verdict, failing
metrics and g[tile,hub] (rings).

    PYTHONPATH=src python benchmarks/s27e_oracle.py CLASS:LABEL D
"""
import sys
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from svar13i_oracle import big_params
from strew.metrics import fidelity
mk = fidelity_suite()
cls, label = sys.argv[1].split(":")
ex = exemplar(mk, cls, label)
i, _, v = label[1:].partition("s")
kw = (_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)]
for d in range(int(sys.argv[2])):
    orc = mk.make_exemplar(cls, rng=int(v) + 1000 * d, **big_params(cls, kw, 3.5))
    ro = fidelity(ex, orc, eq5=False, local=False)
    print(d, ro.faithful, {k: f"{m.value:.3f}/{m.tolerance:.3f}" for k, m in ro.metrics.items() if not m.passed or k.startswith("g[tile,hub")})

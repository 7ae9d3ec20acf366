"""Helper fr: g(r) of one kind pair on a --varied-variants row: exemplar, method output, oracle.

The oracle is the exemplar's own generator drawn 3.5x larger (``svar13i_oracle.big_params``).
Prints the bin centres (in s), g of each, and the method's and oracle's discrepancies per bin.

    PYTHONPATH=src python benchmarks/fr_rings_g.py METHOD CLASS:LABEL A,B [SEED]

METHOD is grow, grow-rotate or synth (as ``fresh17_rows.py``).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
import numpy as np
from fresh17_rows import exemplar
from _runner import fidelity_suite
from svar13i_oracle import big_params

from strew.metrics import fidelity


def main():
    method, spec, pair = sys.argv[1], sys.argv[2], sys.argv[3]
    seed = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    mk = fidelity_suite()
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    if method == "synth":
        from synth_variants import run
        args = None
    else:
        from types import SimpleNamespace

        from grow_variants import run
        args = SimpleNamespace(mode="rotate" if method == "grow-rotate" else "fixed", times=10.0)
    out, _ = run(ex, 3.5, seed, args)
    v = int(label.split("s")[-1]) if "s" in label else int(label[1:])
    kw = {}
    if not label.startswith("v"):
        kw = (_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(label[1:].partition("s")[0])]
    orc = mk.make_exemplar(cls, rng=v, **big_params(cls, kw, 3.5))
    rm = fidelity(ex, out, eq5=False, local=False)
    ro = fidelity(ex, orc, eq5=False, local=False)
    key = f"g[{pair}]"
    print(f"{method} {spec} seed {seed}: {key} method {rm.metrics[key].value:.3f} oracle {ro.metrics[key].value:.3f} tol {rm.metrics[key].tolerance:.3f}; n {len(out)} oracle n {len(orc)}")
    kn = lambda a: {k: int((np.asarray(a.kind_names) == k).sum()) for k in sorted(set(a.kind_names))}
    print("counts ex", kn(ex), "method", kn(out), "oracle", kn(orc))
    print(" r/s    ex    method  oracle   (m-ex)  (o-ex)")
    ge, gm, go = rm.g_exemplar[pair], rm.g_result[pair], ro.g_result[pair]
    for i, r in enumerate(rm.r):
        print(f"{r:5.2f} {ge[i]:6.2f} {gm[i]:7.2f} {go[i]:7.2f} {gm[i] - ge[i]:+7.2f} {go[i] - ge[i]:+7.2f}")


if __name__ == "__main__":
    main()

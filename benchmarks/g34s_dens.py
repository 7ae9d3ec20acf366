"""Helper g34s: density[apple] (result / exemplar, the judge's) of sparse_voids rows, as grow_variants runs them.

    PYTHONPATH=src:benchmarks python benchmarks/g34s_dens.py LABEL[,LABEL...] SEEDS

LABEL as the audits print it (v24, p0s23, p1s21, p2s9 ...); SEEDS e.g. 1 or 1-3. One line per label:
the ratios per seed and the verdicts.
"""
import sys
from types import SimpleNamespace

import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run

from strew.metrics import fidelity


def main():
    labels, seeds = sys.argv[1].split(","), _variants.ints(sys.argv[2])
    mk = fidelity_suite()
    args = SimpleNamespace(mode="fixed", times=10.0)
    for lab in labels:
        ex = exemplar(mk, "sparse_voids", lab)
        xs, vs = [], []
        for seed in seeds:
            out, _ = run(ex, 3.5, seed, args)
            rep = fidelity(ex, out, eq5=False, local=False)
            m = rep.metrics["density[apple]"]
            xs.append(f"{m.result / m.exemplar:.3f}" if m.applicable and m.exemplar else "n/a")
            vs.append("pass" if rep.faithful else "FAIL")
        print(f"  {lab}: density x {' '.join(xs)}  {' '.join(vs)}", flush=True)


if __name__ == "__main__":
    main()

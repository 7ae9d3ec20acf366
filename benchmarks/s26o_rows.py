"""Helper s26o (issue 13 point 1): synth on chosen stones rows, judged as the audits judge them.

ROW is ``h2s17`` (``--harder`` set 2 at variant seed 17, synth_variants._harder) or ``p1s17``
(set 1 of ``_variants.VARIED + EDGE`` at variant seed 17); prints the verdict, the failing
metrics, n and the size classes synth sees.

    PYTHONPATH=src python benchmarks/s26o_rows.py CLASS ROW[,ROW...] SEEDS
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
import numpy as np
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder, run

from strew.metrics import fidelity
from strew.synth._api import as_selection
from strew.synth._prepare import prepare


def exemplar(cls, label):
    i, _, v = label[1:].partition("s")
    if label.startswith("h"):
        return _harder_suite().make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    if label.startswith("v"):
        return fidelity_suite().make_exemplar(cls, rng=int(label[1:]))
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    return fidelity_suite().make_exemplar(cls, rng=int(v), **sets[int(i)])


def main():
    cls, labels, seeds = sys.argv[1], sys.argv[2].split(","), _variants.ints(sys.argv[3])
    passed = total = 0
    for label in labels:
        ex = exemplar(cls, label)
        sc = np.bincount(prepare(as_selection(ex)).size_class).tolist()
        for seed in seeds:
            out, _ = run(ex, 3.5, seed, None)
            rep = fidelity(ex, out, eq5=False, local=False)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            passed += rep.faithful
            total += 1
            print(f"{cls} {label} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} classes {sc} {' '.join(fails)}", flush=True)
    print(f"{cls}: {passed}/{total}")


if __name__ == "__main__":
    main()

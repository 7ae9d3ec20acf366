"""Helper s29m (issue 13 point 1, three_sizes h6): one --harder row's nearest-neighbour deciles between
size classes away from the edge (as syn13z_rows.nnq), exemplar and output, and each kind's count in the
inner frame (margin 2 rc.max, as ``_displace._inner_density``) per 1e4.

    PYTHONPATH=src:benchmarks python benchmarks/s29m_pairs.py CLASS:H:V:SEEDS
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from syn13z_rows import counts, nnq
from synth_variants import _harder, run

from strew.metrics import fidelity

name, i, v, seeds = sys.argv[1].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
print(f"{name} h{i}s{v} exemplar whole {counts(ex, 0)} inner(22) {counts(ex, 22)}")
for seed in [int(x) for x in seeds.split(",")]:
    out, _ = run(ex, 3.5, seed, None)
    rep = fidelity(ex, out, eq5=False, local=False)
    print(f" seed {seed} {'pass' if rep.faithful else 'FAIL'} out inner(22) {counts(out, 22)}")
    for a, b in [("large", "medium"), ("medium", "large"), ("medium", "small"), ("small", "medium"), ("medium", "medium")]:
        m = rep.metrics[f"nn[{a}>{b}]"]
        print(f"  nn[{a}>{b}] {m.value:.3f}/{m.tolerance:.3f} ex {np.round(nnq(ex, a, b), 1)} out {np.round(nnq(out, a, b), 1)}")

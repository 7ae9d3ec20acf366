"""Helper s29m (issue 13 point 1, three_sizes h6): the exemplar's generator drawn 3.5x larger on a side
(svar13i_oracle.big_params, same variant seed) against the exemplar: counts per 1e4 in the whole frame and
the inner frame (margin 22, as synth's ``_inner_density`` with 2 rc.max), and nn[large>medium] deciles.

    PYTHONPATH=src:benchmarks python benchmarks/s29m_oracle_counts.py CLASS:H:V
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from syn13z_rows import counts, nnq
from synth_variants import _harder

name, i, v = sys.argv[1].split(":")
kw = _harder()[name][int(i)]
mk = _harder_suite()
ex = mk.make_exemplar(name, rng=int(v), **kw)
big = mk.make_exemplar(name, rng=int(v), **big_params(name, kw, 3.5))
for lab, a in (("exemplar", ex), ("oracle", big)):
    print(f"{name} h{i}s{v} {lab}: whole {counts(a, 0)} inner(22) {counts(a, 22)} nn[large>medium] {np.round(nnq(a, 'large', 'medium'), 1)}")

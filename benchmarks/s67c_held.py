"""s67c: the ring guard's statistic (``_prepare.ring_groups``' ``held``: share of the parents
with a whole ring that hold two or more children of the group) on every group s65c's gates
pass, for the exemplars named by the CAP lines of s67c_ring_stats_*.txt; with ``capped``
(the guard's verdict, RING_CAP_HELD) and the group's children-per-parent mean.

    PYTHONPATH=src:benchmarks python benchmarks/s67c_held.py benchmarks/results/s67c_ring_stats_*.txt
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import new_state
from strew.synth._prepare import RING_CAP_HELD, ring_groups

todo = []
for fn in sys.argv[1:]:
    with open(fn) as f:
        for line in f:
            t = line.split()
            if len(t) > 4 and t[4] == "CAP" and (t[0], t[1], t[2]) not in todo:
                todo.append((t[0], t[1], t[2]))
for which, cls, lab in todo:
    v = int(lab.rsplit("s", 1)[1]) if not lab.startswith("v") else int(lab[1:])
    assert v <= 40, "held-out variant seeds"
    if which == "harder":
        i, _, vv = lab[1:].partition("s")
        ex = _harder_suite().make_exemplar(cls, rng=int(vv), **_harder()[cls][int(i)])
    else:
        ex = exemplar(fidelity_suite(), cls, lab)
    prep = new_state(ex, Region.rectangle(50, 50), rng=1).prep
    names = np.asarray(ex.kind_names)
    for g in ring_groups(prep):
        if not g["gated"]:
            continue
        c0 = g["members"][0]
        print(f"{which} {cls} {lab} {names[c0]}<{names[prep.parent[c0]]} members {len(g['members'])} parents {g['parents']} "
              f"mean {len(g['members']) / g['parents']:.2f} held {g['held']:.2f} capped {g['held'] >= RING_CAP_HELD}", flush=True)

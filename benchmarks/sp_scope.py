"""Helper sp: which exemplars the spread guard newly bounds (``_optimize.sized_scatter``: near-regular
scatters of several kinds, no lattice, anchor or ring children), over the fidelity suite (variants
1-5), the ``--harder`` sets (variant seeds 7-14) and the ``--varied`` / edge sets (seeds 7-10).

    PYTHONPATH=src:benchmarks python benchmarks/sp_scope.py
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _variants import EDGE, VARIED
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import _optimize as O
from strew.synth import new_state

mk = _harder_suite()


def flag(ex):
    p = new_state(ex, Region.rectangle(100, 100), rng=1).prep
    reg, sc = O.near_regular(p), O.sized_scatter(p)
    return "B" if (reg[0] and sc[0]) else ("r" if reg[0] else ".")


print("B: newly bounded; r: near-regular, not bounded; .: irregular (bounded before when several kinds)")
for name in mk.NAMES:
    row = []
    for v in range(1, 6):
        try:
            row.append(flag(mk.make_exemplar(name, rng=v)))
        except Exception as e:  # noqa: BLE001
            row.append("x")
    print(f"suite {name:14s}", "".join(row))
for name, sets in _harder().items():
    for i, kw in enumerate(sets):
        print(f"harder {name:12s} h{i:<3d}", "".join(flag(mk.make_exemplar(name, rng=v, **kw)) for v in range(7, 15)))
for lab, d in (("varied", VARIED), ("edge", EDGE)):
    for name, sets in d.items():
        for i, kw in enumerate(sets):
            try:
                print(f"{lab} {name:12s} {i:<3d}", "".join(flag(mk.make_exemplar(name, rng=v, **kw)) for v in range(7, 11)))
            except Exception as e:  # noqa: BLE001
                print(f"{lab} {name} {i} error {e}")

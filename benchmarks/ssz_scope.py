"""Helper ssz (issue 13 point 1): which three_sizes exemplars of the audits change size classes when
``_prepare._split_kinds`` steps at KIND_AREA_STEP (this tree) instead of AREA_STEP 1.5 (main).

Sets: the suite's default exemplar (seeds 0-5), --harder h0-h13 at variant seeds 7-14, VARIED and EDGE
at variant seeds 7-12.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/ssz_scope.py
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from _variants import EDGE, VARIED
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.synth import _prepare as P

mk = _harder_suite()


def classes(ex, step):
    r = np.array([ex.shapes[k].radius for k in ex.kinds])[np.asarray(ex.kind)] * np.abs(np.asarray(ex.scale, float))
    old = P.KIND_AREA_STEP
    P.KIND_AREA_STEP = step
    try:
        cls = P.size_classes(r, P.area_radii(ex.with_columns(radius=r)), ex.kind)
    finally:
        P.KIND_AREA_STEP = old
    return [int(cls[np.asarray(ex.kind) == k][0]) for k in range(len(ex.kinds))]


cases = [(f"default v{v}", v, {}) for v in range(6)]
cases += [(f"h{i}s{v}", v, kw) for i, kw in enumerate(_harder()["three_sizes"]) for v in range(7, 15)]
sets = VARIED["three_sizes"] + EDGE["three_sizes"]
cases += [(f"p{i}s{v}", v, kw) for i, kw in enumerate(sets) for v in range(7, 13)]
changed = 0
for label, v, kw in cases:
    ex = mk.make_exemplar("three_sizes", rng=v, **kw)
    a, b = classes(ex, 1.5), classes(ex, P.KIND_AREA_STEP)
    if a != b:
        changed += 1
        print(f"{label}: classes {a} -> {b}")
print(f"{changed} of {len(cases)} exemplars change (KIND_AREA_STEP {P.KIND_AREA_STEP})")

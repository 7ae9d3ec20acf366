"""Helper g3s: which audit exemplars get other default priorities in fixed mode from
``several_priority`` (kinds of three or more sizes ranked by SIZE_STEP_SEVERAL) than from
``size_priority``: only their grow rows can change.

    PYTHONPATH=src python benchmarks/g3s_changed.py
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from grow_variants import HARDER, _harder_suite

from strew.grow._analysis import several_priority, size_priority

mk = _harder_suite()
rows = []
for cls in ["three_sizes"]:  # the only class of the suite with three or more kinds
    for i, kw in enumerate(HARDER.get(cls, [])):
        rows += [(cls, f"h{i}s{v}", v, kw) for v in range(7, 15)]
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    rows += [(cls, f"p{i}s{v}", v, kw) for i, kw in enumerate(sets) for v in range(7, 11)]
    rows += [(cls, f"v{v}", v, {}) for v in range(0, 11)]
for cls, label, v, kw in rows:
    ex = mk.make_exemplar(cls, rng=v, **kw)
    a, b = size_priority(ex), several_priority(ex)
    if a != b:
        print(cls, label, a, "->", b, flush=True)

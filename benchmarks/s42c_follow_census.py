"""Helper s42c: which exemplars hold ring children (``Prepared.follow``), and which a kind
of which ``_grow.FREE_CHILDREN_SHARE`` follows its parent, the only ones
``_grow._free_children_discount`` can change (prepare only, no synthesis).

    PYTHONPATH=src:benchmarks python benchmarks/s42c_follow_census.py 23-28 [CLASSES]
"""
import sys

import _variants
import numpy as np
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import new_state
from strew.synth._grow import FREE_CHILDREN_SHARE

variants = _variants.ints(sys.argv[1]) if len(sys.argv) > 1 else list(range(23, 29))
only = sys.argv[2].split(",") if len(sys.argv) > 2 else None
mk, hk = fidelity_suite(), _harder_suite()
classes = [c for c in mk.NAMES if only is None or c in only]
for cls in classes:
    sets = [("v", mk, {})] + [(f"p{i}", mk, kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]
    sets += [(f"h{i}", hk, kw) for i, kw in enumerate(_harder().get(cls, []))]
    n = hit = gated = 0
    top = 0.0
    for lab, m, kw in sets:
        for v in variants:
            try:
                ex = m.make_exemplar(cls, rng=v, **kw)
            except Exception:  # noqa: BLE001 - a generator that refuses a set
                continue
            prep = new_state(ex, Region.rectangle(10, 10), rng=1).prep
            n += 1
            sh = [float(prep.follow[prep.kind == k].mean()) for k in np.unique(prep.kind)]
            if prep.follow.any():
                hit += 1
                top = max(top, max(sh))
                gated += max(sh) >= FREE_CHILDREN_SHARE
                print(f"  {cls} {lab}s{v}: follow share by kind {np.round(sh, 2).tolist()}", flush=True)
    print(f"{cls:14s} {hit} of {n} exemplars hold ring children; {gated} have a kind >= {FREE_CHILDREN_SHARE} (largest share {top:.2f})", flush=True)

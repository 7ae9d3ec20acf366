"""Helper s43c: which exemplars have far hubs (``_prepare._far_hubs``), the only ones
``_grow.hub_floors`` acts on, and their floors (prepare only, no synthesis).

    PYTHONPATH=src:benchmarks python benchmarks/s43c_hub_census.py 23-28 [CLASSES]
"""
import sys

import _variants
import numpy as np
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import new_state
from strew.synth._grow import hub_floors

variants = _variants.ints(sys.argv[1]) if len(sys.argv) > 1 else list(range(23, 29))
only = sys.argv[2].split(",") if len(sys.argv) > 2 else None
mk, hk = fidelity_suite(), _harder_suite()
classes = [c for c in mk.NAMES if only is None or c in only]
for cls in classes:
    sets = [("v", mk, {})] + [(f"p{i}", mk, kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]
    sets += [(f"h{i}", hk, kw) for i, kw in enumerate(_harder().get(cls, []))]
    n = hit = 0
    for lab, m, kw in sets:
        for v in variants:
            try:
                ex = m.make_exemplar(cls, rng=v, **kw)
            except Exception:  # noqa: BLE001 - a generator that refuses a set
                continue
            prep = new_state(ex, Region.rectangle(10, 10), rng=1).prep
            n += 1
            fl = hub_floors(prep)
            if (fl[:, 0] > 0).any():
                hit += 1
                print(f"  {cls} {lab}s{v}: {int((fl[:, 0] > 0).sum())} far hubs, floors {np.round(fl[fl[:, 0] > 0][0], 1).tolist()}", flush=True)
    print(f"{cls:14s} {hit} of {n} exemplars have far hubs", flush=True)

"""Helper s37k: which exemplars' min_dist the endpoint bound (``_prepare.approach_bound``) raises above 0.95 x1.

    PYTHONPATH=src python benchmarks/s37k_bounds.py 27 [CLASS,...]

Per --varied row at the variant seed (default set and every VARIED + EDGE set): the pairs
of classes whose bound exceeds 0.95 of the closest approach by over 1 %, as bound / x1.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np

import _variants
from _runner import fidelity_suite
from strew.synth import as_selection
from strew.synth._prepare import approach_bound, closest_approach

mk = fidelity_suite()
v = int(sys.argv[1])
names = sys.argv[2].split(",") if len(sys.argv) > 2 else list(mk.NAMES)
for cls in names:
    sets = [("v", {})] + [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]
    for lab, kw in sets:
        ex = mk.make_exemplar(cls, rng=v, **kw)
        kn = np.asarray(ex.kind_names)
        _, kind = np.unique(kn, return_inverse=True)
        x1, x2 = closest_approach(np.asarray(ex.xy, float), kind.ravel(), np.zeros(len(ex), np.int64), second=True)
        ok = np.isfinite(x1)
        ratio = np.where(ok, approach_bound(np.where(ok, x1, 1), x2) / np.where(ok, x1, 1), np.nan)
        up = [f"{a}>{b} {ratio[i, j]:.3f}" for i, a in enumerate(np.unique(kn)) for j, b in enumerate(np.unique(kn)) if j >= i and ratio[i, j] > 0.96]
        print(f"{cls:12s} {lab}s{v}: {' '.join(up) or '-'}", flush=True)

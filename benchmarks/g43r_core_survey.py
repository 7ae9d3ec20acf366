"""Helper g43r: the hard-core test of ``lattice_like`` over the audit's exemplars, the
floor (q10 / min - 1) beside the tail (q90 / q10) and their ratio, for the exemplars
under the cv test (``GAP_LATTICE_CV``), where the hard-core test decides.

    PYTHONPATH=src python benchmarks/g43r_core_survey.py [CLASSES=all] [SEEDS=1-28]
"""
import os
import sys
import warnings

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
warnings.filterwarnings("ignore")
import _variants
from grow_variants import HARDER, _harder_suite

from strew.grow._growth import GAP_LATTICE_CV, lattice_like

mk = _harder_suite()
only = sys.argv[1].split(",") if len(sys.argv) > 1 and sys.argv[1] != "all" else list(mk.EXEMPLARS)
vs = _variants.ints(sys.argv[2]) if len(sys.argv) > 2 else list(range(1, 29))
for cls in only:
    exs = [("suite", {}, None)] + [(f"v{v}", {}, v) for v in vs]
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    exs += [(f"p{i}s{s}", kw, s) for i, kw in enumerate(sets) for s in vs]
    exs += [(f"h{i}s{s}", kw, s) for i, kw in enumerate(HARDER.get(cls, [])) for s in vs]
    for label, kw, v in exs:
        ex = mk.make_exemplar(cls, rng=v, **kw) if v is not None else mk.make_exemplar(cls, **kw)
        nn = cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]
        cv = float(nn.std() / nn.mean())
        if cv >= GAP_LATTICE_CV:
            continue
        lo = float(nn.min())
        q10, q90 = np.quantile(nn, [0.1, 0.9])
        floor, tail = q10 / lo - 1, q90 / q10 - 1
        print(f"{cls:13s} {label:6s} n={len(ex):4d} cv={100 * cv:5.2f}% floor={100 * floor:6.3f}% tail={100 * tail:6.2f}% "
              f"floor/tail={floor / tail if tail > 0 else float('nan'):6.3f} lattice={int(lattice_like(nn))}", flush=True)

"""Helper gst: static survey of the exemplar-wide nearest-neighbour statistics that
grow's lattice test reads (``GAP_LATTICE_CV``: ``_Grower._irregular``, ``_pair_gaps``),
with the hard-core candidate (90th percentile over the 10th), over audit exemplars.

    PYTHONPATH=src python benchmarks/gst_cv_survey.py [CLASSES=all] [SEEDS=7-14]
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

mk = _harder_suite()
only = sys.argv[1].split(",") if len(sys.argv) > 1 and sys.argv[1] != "all" else list(mk.EXEMPLARS)
vs = _variants.ints(sys.argv[2]) if len(sys.argv) > 2 else list(range(7, 15))
for cls in only:
    exs = [("suite", {}, None)] + [(f"v{v}", {}, v) for v in range(1, 4)] + [(f"v{v}", {}, v) for v in vs]
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    exs += [(f"p{i}s{s}", kw, s) for i, kw in enumerate(sets) for s in vs]
    exs += [(f"h{i}s{s}", kw, s) for i, kw in enumerate(HARDER.get(cls, [])) for s in vs]
    for label, kw, v in exs:
        ex = mk.make_exemplar(cls, rng=v, **kw) if v is not None else mk.make_exemplar(cls, **kw)
        nn = cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]
        cv = float(nn.std() / nn.mean())
        q10, q50, q90 = np.quantile(nn, [0.1, 0.5, 0.9])
        print(f"{cls:13s} {label:6s} n={len(ex):4d} cv={100 * cv:5.1f}% q90/q10={q90 / q10:5.3f} q50/q10={q50 / q10:5.3f} "
              f"q90/min={q90 / nn.min():5.3f} irregular={int(cv >= 0.06)}", flush=True)

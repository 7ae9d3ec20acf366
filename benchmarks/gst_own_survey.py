"""Helper gst: static survey of grow's one-kind distance rule in fixed mode (``_Grower.pair_close``)
over audit exemplars: per kind, the reference's least own-kind distance ``lo``, its median,
the spread (med - lo) / med, lo / l, today's flag, and candidate statistics.

    PYTHONPATH=src python benchmarks/gst_own_survey.py [CLASSES=all] [SEEDS=7-14]
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

from strew.grow._analysis import analyze, size_levels

mk = _harder_suite()
only = sys.argv[1].split(",") if len(sys.argv) > 1 and sys.argv[1] != "all" else list(mk.EXEMPLARS)
vs = _variants.ints(sys.argv[2]) if len(sys.argv) > 2 else list(range(7, 15))
for cls in only:
    exs = [("suite", {}, None)] + [(f"v{v}", {}, v) for v in range(1, 4)] + [(f"v{v}", {}, v) for v in vs]
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    exs += [(f"p{i}s{s}", kw, s) for i, kw in enumerate(sets) for s in vs]
    exs += [(f"h{i}s{s}", kw, s) for i, kw in enumerate(HARDER.get(cls, [])) for s in vs[:2]]
    for label, kw, v in exs:
        ex = mk.make_exemplar(cls, rng=v, **kw) if v is not None else mk.make_exemplar(cls, **kw)
        if "void" in ex.columns:
            continue
        ref = analyze(ex, lattice_repairs=True)
        l = ref.mean_edge
        lv = size_levels(ex)
        allnn = cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]
        for k, name in enumerate(ex.kinds):
            sel = np.flatnonzero(ex.kind == k)
            if len(sel) < 4:
                continue
            d = cKDTree(ex.xy[sel]).query(ex.xy[sel], k=2)[0][:, 1]
            lo, med = float(d.min()), float(np.median(d))
            q = np.quantile(d, [0.1, 0.9])
            own = med - lo >= 0.05 * med or lo >= 1.2 * l
            cv_all = float(allnn.std() / allnn.mean())
            print(f"{cls:13s} {label:6s} {name:7s} n={len(sel):3d} lvl={lv.get(name, 0):.0f} spread={100 * (med - lo) / med:5.1f}% "
                  f"lo/l={lo / l:4.2f} q10/lo={q[0] / lo:5.3f} q90/lo={q[1] / lo:5.3f} cv_all={100 * cv_all:4.1f}% own={int(own)}", flush=True)

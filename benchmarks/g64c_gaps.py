"""Helper g64c: over clusters exemplars (labels v, p0-p4) at variant seeds SEEDS (never 37, 38 here), whether
``_clusters.hub_reference`` took its fallback (every Delaunay triangle) and the largest bearing gap in the
interior hubs' 1-rings, each and all together: a gap near 180 degrees leaves a half-plane the hubs' growth never proposes into.
Exemplars only, no growth.

    PYTHONPATH=src:benchmarks python benchmarks/g64c_gaps.py 7-36
"""
import math
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from strew._errors import InputError
from strew.grow._analysis import analyze
from strew.grow._clusters import hub_reference, satellite_structure

mk = fidelity_suite()
seeds = [v for v in _variants.ints(sys.argv[1]) if v not in (37, 38)]
labels = ["v"] + [f"p{i}" for i in range(len(_variants.VARIED["clusters"]) + len(_variants.EDGE["clusters"]))]
for lab in labels:
    for v in seeds:
        label = f"{lab}{v}" if lab == "v" else f"{lab}s{v}"
        ex = exemplar(mk, "clusters", label)
        sat = satellite_structure(ex)
        if sat is None:
            print(f"{label:7s} not clustered")
            continue
        hx = ex.select(ex.kind == sat.hub)
        try:
            analyze(hx)
            fb = False
        except InputError:
            fb = True
        ref = hub_reference(hx)
        if ref is None:
            print(f"{label:7s} hubs {len(hx)} no reference")
            continue
        worst = 0.0
        inter = np.flatnonzero(ref.interior)
        allb = []
        for i in inter:
            b = sorted(math.degrees(math.atan2(*(hx.xy[j] - hx.xy[i])[::-1])) % 360 for j in ref.rings[i])
            allb += b
            worst = max(worst, float(np.max(np.diff(b + [b[0] + 360]))))
        allb = sorted(allb)
        union = float(np.max(np.diff(allb + [allb[0] + 360])))  # widest gap of all interior rings' bearings together
        print(f"{label:7s} hubs {len(hx):3d} fallback {fb!s:5s} interior {len(inter):3d} widest ring gap {worst:5.0f} deg, of all interior rings together {union:5.0f} deg{'  <-- >= 150' if union >= 150 else ''}", flush=True)

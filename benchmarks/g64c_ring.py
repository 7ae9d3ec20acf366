"""Helper g64c: the hubs' reference of ``--varied`` clusters p2s37 (``_clusters.hub_reference``): hub
positions, the interior hub(s) and their 1-ring offsets and bearings (the only proposals the hubs' growth
copies), the Delaunay edges kept, and whether the fallback (every triangle kept) was taken.

    PYTHONPATH=src:benchmarks python benchmarks/g64c_ring.py clusters:p2s37
"""
import math
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar
from strew._errors import InputError
from strew.grow._analysis import analyze
from strew.grow._clusters import hub_reference, satellite_structure

mk = fidelity_suite()
cls, label = sys.argv[1].split(":")
ex = exemplar(mk, cls, label)
sat = satellite_structure(ex)
hx = ex.select(ex.kind == sat.hub)
np.set_printoptions(precision=1, suppress=True, linewidth=200)
print("hubs xy (frame", ex.region.bounds, ")\n", hx.xy)
try:
    analyze(hx)
    print("§4 analyze (skew triangles dropped): has an interior hub")
except InputError as e:
    print("§4 analyze (skew triangles dropped) refused:", e, "-> hub_reference falls back to every Delaunay triangle")
ref = hub_reference(hx)
print("interior", np.flatnonzero(ref.interior).tolist(), "edges", sorted(map(tuple, np.asarray(ref.edges).tolist())) if ref.edges is not None else None)
for i in np.flatnonzero(ref.interior):
    print(f"hub {i} ring: {ref.rings[i] if hasattr(ref, 'rings') else None}")
    ring = ref.rings[i]
    for j in ring:
        d = hx.xy[j] - hx.xy[i]
        print(f"   -> hub {j}: offset {d}, length {np.hypot(*d):.1f}, bearing {math.degrees(math.atan2(d[1], d[0])):.0f} deg")
    b = sorted(math.degrees(math.atan2(*(hx.xy[j] - hx.xy[i])[::-1])) % 360 for j in ring)
    gaps = np.diff(b + [b[0] + 360])
    print(f"   bearing gaps {np.round(gaps, 0)} (largest {gaps.max():.0f} deg)")

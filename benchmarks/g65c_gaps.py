"""Helper g65c: over clusters exemplars (labels v, p0-p4) at variant seeds SEEDS (held-out seeds 39 and above
refused), the widest bearing gap of the interior hubs' 1-rings taken together in §4's reference of the hubs
(``hub_reference`` before mirroring) and whether ``_clusters.mirror_hub_rings`` acts there (gap over
``HUB_MIRROR_GAP``): the virtual hubs it adds. Exemplars only, no growth.

    PYTHONPATH=src:benchmarks python benchmarks/g65c_gaps.py 7-38
"""
import math
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar

import strew.grow._clusters as C

seeds = _variants.ints(sys.argv[1])
if max(seeds) >= 39:
    sys.exit("variant seeds 39 and above are held out")
mk = fidelity_suite()
own = C.mirror_hub_rings
seen = []
C.mirror_hub_rings = lambda ref, limit=C.HUB_MIRROR_GAP: (seen.append(ref), own(ref, limit))[1]
labels = ["v"] + [f"p{i}" for i in range(len(_variants.VARIED["clusters"]) + len(_variants.EDGE["clusters"]))]
acts = []
for lab in labels:
    for v in seeds:
        label = f"{lab}{v}" if lab == "v" else f"{lab}s{v}"
        ex = exemplar(mk, "clusters", label)
        sat = C.satellite_structure(ex)
        if sat is None:
            print(f"{label:7s} not clustered")
            continue
        hx = ex.select(ex.kind == sat.hub)
        seen.clear()
        ref = C.hub_reference(hx)
        if ref is None:
            print(f"{label:7s} hubs {len(hx)} no reference")
            continue
        gap = math.degrees(C.ring_union_gap(seen[0]))
        m = len(ref.exemplar) - len(hx)
        if m:
            acts.append(label)
        print(f"{label:7s} hubs {len(hx):3d} interior {int(seen[0].interior.sum()):3d} union gap {gap:5.0f} deg  "
              f"{'MIRRORED: ' + str(m) + ' virtual hubs' if m else ''}", flush=True)
print(f"mirrored at: {' '.join(acts) or 'none'}")

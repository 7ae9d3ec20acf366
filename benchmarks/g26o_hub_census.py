"""Helper g26o: which audit exemplars the hubs' fallback reference reaches: every clustered
exemplar (``satellite_structure``) of the audit's sets (default, VARIED + EDGE, and --harder)
at the given variant seeds whose hubs keep no interior one under §4's skew rule
(``analyze`` raises). Only these rows' outputs change with ``_clusters.hub_reference``.

    PYTHONPATH=src python benchmarks/g26o_hub_census.py [VARIANTS=1-18] [CLASSES=clusters,rings]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from grow_variants import HARDER, _harder_suite

from strew import InputError
from strew.grow._analysis import analyze
from strew.grow._clusters import hub_reference, satellite_structure

variants = _variants.ints(sys.argv[1] if len(sys.argv) > 1 else "1-18")
classes = (sys.argv[2] if len(sys.argv) > 2 else "clusters,rings").split(",")
mk = _harder_suite()
reached = total = 0
for cls in classes:
    sets = [("v", {})] + [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]
    sets += [(f"h{i}", kw) for i, kw in enumerate(HARDER.get(cls, []))]
    for tag, kw in sets:
        for v in variants:
            ex = mk.make_exemplar(cls, rng=v, **kw)
            sat = satellite_structure(ex)
            if sat is None:
                continue
            total += 1
            hx = ex.select(ex.kind == sat.hub)
            try:
                analyze(hx)
            except InputError:
                reached += 1
                ok = hub_reference(hx) is not None
                print(f"  {cls} {tag}s{v}: {len(hx)} hubs, none interior under §4; whole Delaunay: {'interior hub' if ok else 'still none'}", flush=True)
print(f"{reached} of {total} clustered exemplars reached")

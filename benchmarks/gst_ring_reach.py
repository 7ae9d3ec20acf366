"""Helper gst: static reach of the ring phase rule (``strew.grow._clusters.ring_phases``):
which audit exemplars of the clustered classes (rings, clusters) it applies to.

    PYTHONPATH=src python benchmarks/gst_ring_reach.py [SEEDS=7-14]
"""
import os
import sys
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
warnings.filterwarnings("ignore")
import _variants
from grow_variants import HARDER, _harder_suite

from strew.grow._clusters import ring_phases, satellite_structure

mk = _harder_suite()
vs = _variants.ints(sys.argv[1]) if len(sys.argv) > 1 else list(range(7, 15))
for cls in mk.EXEMPLARS:
    exs = [("suite", {}, None)] + [(f"v{v}", {}, v) for v in [1, 2, 3] + vs]
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    exs += [(f"p{i}s{s}", kw, s) for i, kw in enumerate(sets) for s in vs]
    exs += [(f"h{i}s{s}", kw, s) for i, kw in enumerate(HARDER.get(cls, [])) for s in vs]
    on = []
    n = 0
    for label, kw, v in exs:
        ex = mk.make_exemplar(cls, rng=v, **kw) if v is not None else mk.make_exemplar(cls, **kw)
        sat = satellite_structure(ex)
        n += 1
        if sat is not None and ring_phases(ex, sat) is not None:
            on.append(label)
    print(f"{cls}: {len(on)} of {n}: {' '.join(on)}", flush=True)

"""Helper s47p: the audit rows where _grow._yields_below departs from the plain rule
(every class yields to every larger one), i.e. where the YIELD_STEP change can act.

    PYTHONPATH=src:benchmarks python benchmarks/s47p_where.py 25-34 [three_sizes,...] [-v: also the plain rows of three classes]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from synth_variants import _harder

import strew.synth._grow as G
from strew.synth._api import as_selection
from strew.synth._prepare import prepare

mk = fidelity_suite()
H = _harder()
vs = _variants.ints(sys.argv[1])
rows = []
only = sys.argv[2].split(",") if len(sys.argv) > 2 and not sys.argv[2].startswith("-") else None
for cls in sorted(set(_variants.VARIED) | set(_variants.EDGE)):
    if only and cls not in only:
        continue
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    for i, kw in enumerate(sets):
        rows += [(cls, f"p{i}s{v}", kw, v) for v in vs]
for cls, sets in H.items():
    if only and cls not in only:
        continue
    for i, kw in enumerate(sets):
        rows += [(cls, f"h{i}s{v}", kw, v) for v in vs]
acts = 0
for cls, label, kw, v in rows:
    try:
        ex = mk.make_exemplar(cls, rng=v, **kw)
    except Exception as e:  # noqa: BLE001
        print(cls, label, "skip", e)
        continue
    pr = prepare(as_selection(ex))
    yb = G._yields_below(pr)
    acts += int(np.any(yb != np.arange(len(yb))))
    ncls = len(yb)
    med = np.array([float(np.median(pr.r[pr.size_class == k])) for k in range(ncls)])
    area = np.array([float(np.median(pr._area_r[pr.size_class == k])) for k in range(ncls)])
    if np.any(yb != np.arange(len(yb))) or (ncls >= 3 and "-v" in sys.argv):
        print(f"{'acts' if np.any(yb != np.arange(len(yb))) else 'plain'} {cls}:{label} yields_below {yb.tolist()} bounding radii {np.round(med / med[0], 2).tolist()} area radii {np.round(area / area[0], 2).tolist()}", flush=True)
print(f"{acts} of {len(rows)} rows")

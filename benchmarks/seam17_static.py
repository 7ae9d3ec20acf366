"""Helper seam17: which audit exemplars (the suite, --harder sets at variant seeds 7-10,
VARIED and EDGE at 7-8) have ring children that ``_grow._complete_anchor_rings`` pairs
with slots (``_ring_kids``): the only exemplars whose synth output its second pairing
round (seam17) can change. Prints one line per exemplar with the children's kinds.

    PYTHONPATH=src python benchmarks/seam17_static.py > OUT.txt
"""
import sys

import numpy as np

sys.path.insert(0, "benchmarks")
from _variants import EDGE, VARIED
from grow_variants import _harder_suite
from synth_variants import _harder

import strew.synth._grow as G
from strew.synth._api import as_selection
from strew.synth._prepare import prepare

mk = _harder_suite()
cases = [(n, "suite", 0, {}) for n in mk.NAMES]
for n, L in _harder().items():
    cases += [(n, f"h{i}s{s}", s, kw) for i, kw in enumerate(L) for s in (7, 8, 9, 10)]
for src in (VARIED, EDGE):
    for n, L in src.items():
        cases += [(n, f"{'v' if src is VARIED else 'p'}{i}s{s}", s, kw) for i, kw in enumerate(L) for s in (7, 8)]
for n, lab, s, kw in cases:
    ex = mk.make_exemplar(n, rng=s, **kw) if lab != "suite" else mk.make_exemplar(n)
    prep = prepare(as_selection(ex, None))
    child, ptr, idx = G._ring_kids(prep) if G.RING_COMPLETE_LARGER else G.anchor_children(prep)
    kinds = sorted({ex.kinds[int(k)] for k in np.asarray(prep.kind)[idx]}) if len(idx) else []
    print(n, lab, "ring children:", kinds, flush=True)

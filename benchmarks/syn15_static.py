"""Helper syn15: which audit exemplars (the suite, --harder sets at variant seeds 7-10, VARIED and EDGE at 7-8) have a kind with synth's _larger_in_class order bonus; run on two trees and diff.

    PYTHONPATH=TREE/src python benchmarks/syn15_static.py > OUT.txt
"""
import sys, numpy as np
sys.path.insert(0, "benchmarks")
from grow_variants import _harder_suite
from synth_variants import _harder
from _variants import VARIED, EDGE
from strew.synth._api import as_selection
from strew.synth._prepare import prepare
import strew.synth._grow as G
mk = _harder_suite()
cases = [(n, "suite", 0, {}) for n in mk.NAMES]
for n, L in _harder().items():
    cases += [(n, f"h{i}s{s}", s, kw) for i, kw in enumerate(L) for s in (7, 8, 9, 10)]
for src in (VARIED, EDGE):
    for n, L in src.items():
        cases += [(n, f"{'v' if src is VARIED else 'p'}{i}s{s}", s, kw) for i, kw in enumerate(L) for s in (7, 8)]
for n, lab, s, kw in cases:
    if n == "sticks": continue
    ex = mk.make_exemplar(n, rng=s, **kw) if lab != "suite" else mk.make_exemplar(n)
    prep = prepare(as_selection(ex, None))
    b = G._larger_in_class(prep)
    kinds = sorted({ex.kinds[int(k)] for k in np.asarray(prep.kind)[b > 0]}) if b.any() else []
    print(n, lab, "bonus:", kinds, flush=True)

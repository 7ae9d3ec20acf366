"""Helper s34p (issue 13 point 1): which exemplars ``_prepare._free_scattered`` changes.

    PYTHONPATH=src python benchmarks/s34p_affected.py 19-26

For every class's default, VARIED, EDGE and HARDER (grow's and synth's) sets at the given
variant seeds, prints the exemplars whose closest approach of a kind to itself the change
drops (kind, its count, the class's common kind count, the dropped value against the
kind's collision bound 2 rc). Output: benchmarks/results/s34p_affected.txt.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.synth import _prepare, as_selection
from strew.synth._prepare import closest_approach

seeds = _variants.ints(sys.argv[1] if len(sys.argv) > 1 else "19-26")
mk = _harder_suite()
hits = total = 0
orig = _prepare.closest_approach
for name in mk.NAMES:
    sets = [("v", {})] + [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(name, []) + _variants.EDGE.get(name, []))]
    sets += [(f"h{i}", kw) for i, kw in enumerate(_harder().get(name, []))]
    for lab, kw in sets:
        for v in seeds:
            ex = mk.make_exemplar(name, rng=v, **kw)
            got = {}

            def ca(pos, cls, source):
                out = orig(pos, cls, source)
                got["raw"] = out.copy()
                return out

            _prepare.closest_approach = ca
            try:
                p = _prepare.prepare(as_selection(ex))
            finally:
                _prepare.closest_approach = orig
            raw = np.where(np.isfinite(got["raw"]), 0.95 * got["raw"], 0.0)
            total += 1
            diff = [a for a in range(len(raw)) if raw[a, a] != p.min_dist[a, a]]
            if diff:
                hits += 1
                cnt = np.bincount(p.skind[~p.void])
                print(name, f"{lab}s{v}" if lab != "v" else f"v{v}", [(a, int(cnt[a]), int(cnt.max()), round(float(raw[a, a]), 1), round(float(2 * np.median(p.rc[p.skind == a])), 1)) for a in diff], flush=True)
print(f"{hits} of {total} exemplars changed")

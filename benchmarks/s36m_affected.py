"""Helper s36m (issue 13 point 1): which exemplars ``_prepare.PARENTLESS_CUT = False`` changes.

    PYTHONPATH=src:benchmarks python benchmarks/s36m_affected.py 19-26 [NAME,...]

For every class's default, VARIED, EDGE and HARDER sets at the given variant seeds, prints the
exemplars whose ``Prepared.parent`` differs between the cut on and off (kind names of the elements
that lose their -3), then the count. Output: benchmarks/results/s36m_affected.txt.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.synth import _prepare, as_selection

seeds = _variants.ints(sys.argv[1] if len(sys.argv) > 1 else "19-26")
only = sys.argv[2].split(",") if len(sys.argv) > 2 else None
mk = _harder_suite()
hits = total = 0
orig = _prepare.parents
for name in mk.NAMES:
    if only and name not in only:
        continue
    sets = [("v", {})] + [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(name, []) + _variants.EDGE.get(name, []))]
    sets += [(f"h{i}", kw) for i, kw in enumerate(_harder().get(name, []))]
    for lab, kw in sets:
        for v in seeds:
            ex = mk.make_exemplar(name, rng=v, **kw)
            got = {}

            def par(*a, **k):
                _prepare.PARENTLESS_CUT = True
                on = orig(*a, **{**k, "follow": None})
                _prepare.PARENTLESS_CUT = False
                off = orig(*a, **k)
                got["d"] = np.flatnonzero(on != off)
                return off

            _prepare.parents = par
            try:
                p = _prepare.prepare(as_selection(ex))
            finally:
                _prepare.parents = orig
            total += 1
            if len(got["d"]):
                hits += 1
                kn = np.asarray(ex.kind_names)
                print(name, f"{lab}s{v}" if lab != "v" else f"v{v}", sorted(kn[got["d"]].tolist()), flush=True)
print(f"{hits} of {total} exemplars changed")

"""Helper sm: how many size classes (``Prepared.size_class``, visible selected elements)
each audited exemplar of a class has: the middle-class rule of ``_grow.owed_classes``
(MIDDLE_RARE) acts only on exemplars of three classes or more.

    PYTHONPATH=src:benchmarks python benchmarks/sm_class_counts.py two_sizes,stones,clusters,three_sizes
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.synth._api import new_state

H = _harder()
mk = _harder_suite()
for name in sys.argv[1].split(","):
    got = {}
    cases = [(f"suite", {}, None)] + [(f"h{i}s{v}", kw, v) for i, kw in enumerate(H.get(name, [])) for v in (7, 8, 9, 10, 11, 12, 13, 14)]
    vs = getattr(_variants, "VARIED", {}).get(name, []) + getattr(_variants, "EDGE", {}).get(name, [])
    cases += [(f"p{i}s{v}", kw, v) for i, kw in enumerate(vs) for v in (7, 8)]
    for lab, kw, v in cases:
        try:
            ex = mk.make_exemplar(name) if v is None else mk.make_exemplar(name, rng=v, **kw)
        except Exception as e:  # noqa: BLE001
            got[lab] = f"err {type(e).__name__}"
            continue
        prep = new_state(ex).prep
        sel = prep.selected_elements & ~prep.void
        got[lab] = len(np.unique(prep.size_class[sel]))
    three = [k for k, c in got.items() if c == 3 or (isinstance(c, int) and c > 3)]
    print(name, len(got), "exemplars; with >= 3 size classes:", len(three), three[:12], "..." if len(three) > 12 else "")

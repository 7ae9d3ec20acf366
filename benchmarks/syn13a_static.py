"""Helper syn13a: which audit exemplars have three size classes or more (``Prepared.size_class`` of visible
selected elements), and which of them the largest-class ownership rule acts on (``_grow._top_class``: three
classes or more and the largest covering less than ``OWN_COVER`` of the inner frame): only their outputs
can change.

    python benchmarks/syn13a_static.py
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import HARDER, _harder_suite

from strew.synth import _grow as G
from strew.synth._api import new_state

mk = _harder_suite()
hit = []
act = []
total = 0
for name in mk.EXEMPLARS:
    sets = [("fid", 0, {})] + [(f"v{v}", v, {}) for v in (1, 2, 3)]
    sets += [(lab, s, kw) for lab, tag, s, kw in _variants.cases(name, [], True)]
    sets += [(lab, s, kw) for lab, tag, s, kw in [(f"h{i}s{s}", "harder", s, kw) for i, kw in enumerate(HARDER.get(name, [])) for s in (7, 8)]]
    for lab, v, kw in sets:
        ex = mk.make_exemplar(name) if lab == "fid" else mk.make_exemplar(name, rng=v, **kw)
        st = new_state(ex)
        prep = st.prep
        vis = prep.selected_elements & ~prep.void
        n = len(np.unique(prep.size_class[vis]))
        total += 1
        if n >= 3:
            hit.append(f"{name}:{lab}")
        if G._top_class(prep).any():
            act.append(f"{name}:{lab}")
print(f"{total} exemplars; three size classes or more: {len(hit)}")
print(" ".join(hit))
print(f"the rule acts on {len(act)}:")
print(" ".join(act))

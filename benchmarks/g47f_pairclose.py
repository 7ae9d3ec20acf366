"""Helper g47f: which audit exemplars does OWN_TAIL_Q change at all? pair_close with the
rule and without (OWN_TAIL_Q = None), for every class with two visible kinds, --varied
labels (v, p sets) and --harder sets, at the given variant seeds. An exemplar whose
pair_close is the same grows the same bytes.

    PYTHONPATH=src:benchmarks python benchmarks/g47f_pairclose.py 25-34
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
import numpy as np
from _runner import fidelity_suite
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import _growth as G
from strew.grow import grow

CAP = {}
_init = G._Grower.__init__


def init(self, *a, **k):
    _init(self, *a, **k)
    CAP["pc"] = self.pair_close.copy()


G._Grower.__init__ = init


def pc(ex, q):
    G.OWN_TAIL_Q = q
    CAP.clear()
    try:
        grow(ex, region=Region.rectangle(8, 8), rng=1)
    except Exception as e:  # noqa: BLE001
        return repr(e)
    return CAP.get("pc")


vs = _variants.ints(sys.argv[1])
changed = same = 0
for suite_name, mk, sets in (("varied", fidelity_suite(), None), ("harder", _harder_suite(), HARDER)):
    for cls in sorted(_variants.VARIED if sets is None else HARDER):
        lst = ([("v", {})] + [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]) if sets is None else [(f"h{i}", kw) for i, kw in enumerate(HARDER[cls])]
        for lab, kw in lst:
            for v in vs:
                ex = mk.make_exemplar(cls, rng=v, **kw)
                vcol = ex.columns.get("void")
                vis = ~(np.asarray(vcol, dtype=bool) if vcol is not None else np.zeros(len(ex), dtype=bool))
                if len(np.unique(ex.kind[vis])) != 2:
                    continue
                a, b = pc(ex, None), pc(ex, 0.1)
                if isinstance(a, str) or isinstance(b, str) or a is None or b is None:
                    print(f"{suite_name} {cls} {lab}s{v}: ? {a if isinstance(a, str) else ''} {b if isinstance(b, str) else ''}", flush=True)
                    continue
                if np.array_equal(a, b):
                    same += 1
                    continue
                changed += 1
                i = np.unravel_index(np.argmax(np.abs(a - b)), a.shape)
                print(f"{suite_name} {cls} {lab}s{v}: pair_close{tuple(int(x) for x in i)} {a[i]:.2f} -> {b[i]:.2f}", flush=True)
print(f"changed {changed}, same {same}")

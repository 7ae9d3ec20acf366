"""Helper s71t: where LARGEST_WHOLE acts with the majority gate (LARGEST_WHOLE_MAJORITY) against
s70t's v2 (no majority gate), prepare only: --harder/--varied three_sizes at the variant seeds given,
the fidelity suite's exemplar, and the exemplars of the two existing tests the cap failed.

    PYTHONPATH=src:benchmarks:tests python benchmarks/s71t_scope.py 30-44
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from strew_testing import fidelity_suite
from synth_variants import _harder

import strew.synth._displace as DP
from strew.synth._api import new_state


def dens(ex):
    prep = new_state(ex).prep
    m = 2.0 * float(prep.rc.max())
    out = {}
    for lab, on, maj in (("off", False, False), ("v2", True, False), ("A", True, True)):
        DP.LARGEST_WHOLE, DP.LARGEST_WHOLE_MAJORITY = on, maj
        out[lab] = DP._inner_density(prep, m)
    DP.LARGEST_WHOLE, DP.LARGEST_WHOLE_MAJORITY = True, True
    return out


def show(lab, ex):
    d = dens(ex)
    v2 = not np.allclose(d["off"], d["v2"], equal_nan=True)
    a = not np.allclose(d["off"], d["A"], equal_nan=True)
    same = np.allclose(d["v2"], d["A"], equal_nan=True) if a else None
    n = np.bincount(np.asarray(ex.kind))
    print(f"  {lab}: counts {n.tolist()} v2 acts {v2} A acts {a}" + ("" if same is None else f" A==v2 {same}"), flush=True)
    return v2, a


a, b = sys.argv[1].split("-")
mk = _harder_suite()
sets = [(f"h{i}", kw) for i, kw in enumerate(_harder().get("three_sizes", []))]
sets += [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get("three_sizes", []) + _variants.EDGE.get("three_sizes", []))]
nv2 = na = 0
for lab, kw in sets:
    for v in range(int(a), int(b) + 1):
        ex = mk.make_exemplar("three_sizes", rng=v, **kw)
        d = dens(ex)
        v2 = not np.allclose(d["off"], d["v2"], equal_nan=True)
        if v2:
            x, y = show(f"{lab}s{v}", ex)
            nv2 += x
            na += y
print(f"three_sizes {a}-{b}: v2 acts on {nv2}, A on {na}")
fs = fidelity_suite()
show("fidelity suite three_sizes (default)", fs.make_exemplar("three_sizes", rng=None))
show("ladder variant 13 (80:80:30, 1:3:4.5)", fs.make_exemplar("three_sizes", rng=13, ratios=(1.0, 3.0, 4.5), counts=(80, 80, 30)))
show("tsz13m h4s7 (100:100:15, 1:2.5:4)", fs.make_exemplar("three_sizes", rng=7, ratios=(1.0, 2.5, 4.0), counts=(100, 100, 15)))

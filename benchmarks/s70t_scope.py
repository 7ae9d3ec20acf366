"""Helper s70t: where LARGEST_WHOLE acts (src/strew/synth/_displace.py): for every --harder and --varied
exemplar of the classes given at the variant seeds given, the largest class's _inner_density with the cap
against without it (prepare only, no synthesis). Prints the rows where it changes and a count per class.

    PYTHONPATH=src:benchmarks python benchmarks/s70t_scope.py 30-42 [classes]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder

import strew.synth._displace as DP
from strew.synth._api import new_state

a, b = sys.argv[1].split("-")
seeds = range(int(a), int(b) + 1)
classes = sys.argv[2].split(",") if len(sys.argv) > 2 else sorted(set(_harder()) | set(_variants.VARIED))
mk = _harder_suite()


def both(ex):
    prep = new_state(ex).prep
    m = 2.0 * float(prep.rc.max())
    DP.LARGEST_WHOLE = False
    d0 = DP._inner_density(prep, m)
    DP.LARGEST_WHOLE = True
    d1 = DP._inner_density(prep, m)
    return d0, d1


for cls in classes:
    sets = [(f"h{i}", kw) for i, kw in enumerate(_harder().get(cls, []))]
    sets += [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]
    acts = tot = 0
    for lab, kw in sets:
        for v in seeds:
            try:
                ex = mk.make_exemplar(cls, rng=v, **kw)
                d0, d1 = both(ex)
            except Exception as e:  # noqa: BLE001
                print(f"  {cls} {lab}s{v}: error {e}")
                continue
            tot += 1
            ch = ~np.isclose(d0, d1, equal_nan=True)
            if ch.any():
                acts += 1
                print(f"  {cls} {lab}s{v}: acts, largest {np.round(d0[ch] * 1e4, 2)} -> {np.round(d1[ch] * 1e4, 2)} per 1e4", flush=True)
    print(f"{cls}: acts on {acts} of {tot}", flush=True)

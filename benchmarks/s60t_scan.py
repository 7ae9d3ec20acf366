"""Helper s60t: prep scan, which three_sizes exemplars `_grow._own_setup` keeps (the only ones
where `_top_ahead` is evaluated at all; elsewhere output is main's byte for byte).

    PYTHONPATH=src:benchmarks python benchmarks/s60t_scan.py 7-34
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from s60t_ahead_probe import exemplar

import strew.synth._grow as G
from strew.synth._api import new_state

nv = len(_variants.VARIED.get("three_sizes", []) + _variants.EDGE.get("three_sizes", []))
from synth_variants import _harder

nh = len(_harder()["three_sizes"])
kept = tot = 0
for v in _variants.ints(sys.argv[1]):
    for label in [f"v{v}"] + [f"p{i}s{v}" for i in range(nv)] + [f"h{i}s{v}" for i in range(nh)]:
        prep = new_state(exemplar(label)).prep
        top, _a, cover, rate = G._own_setup(prep)
        tot += 1
        kept += bool(top.any())
        print(f"{label}: kept={int(top.any())} cover={cover.max():.3f} topcover={G._top_cover(prep).max():.3f}", flush=True)
print(f"kept {kept}/{tot}")

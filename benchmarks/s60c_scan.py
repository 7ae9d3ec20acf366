"""Helper s60c: which clusters exemplars (--varied sets and --harder sets, variant seeds) have a hub kind _grow._saturated_hub_kinds picks (fill_hub_rooms can act only there; elsewhere synth is main's, byte for byte).

    PYTHONPATH=src:benchmarks python benchmarks/s60c_scan.py 25-34
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from synth_variants import _harder

from strew import Region
from strew.synth import new_state
from strew.synth._grow import _saturated_hub_kinds

mk = fidelity_suite()
H = _harder()["clusters"]
sets = [("v", {})] + [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED["clusters"] + _variants.EDGE["clusters"])] + [(f"h{i}", kw) for i, kw in enumerate(H)]
for v in _variants.ints(sys.argv[1]):
    row = []
    for lab, kw in sets:
        ex = mk.make_exemplar("clusters", rng=v, **kw)
        got = _saturated_hub_kinds(new_state(ex, Region.rectangle(100, 100), rng=1).prep)
        row.append(f"{lab}{'*' if got else '-'}")
    print(v, " ".join(row), flush=True)

"""Helper gst18: static survey — which audit exemplars' grow size levels change when a kind
must also be larger by equal-area radius (SIZE_STEP_AREA, ASTEP here) to start a new size level.

    PYTHONPATH=src python benchmarks/gst18_survey.py [ASTEP=1.3]
"""
import os
import sys
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
warnings.filterwarnings("ignore")
import _variants
from grow_variants import HARDER, _harder_suite

from strew.grow import _analysis
from strew.grow._analysis import _levels

astep = sys.argv[1] if len(sys.argv) > 1 else "1.3"
mk = _harder_suite()
n = changed = 0
for cls in mk.EXEMPLARS:
    exs = [("suite", {}, None)] + [(f"v{v}", {}, v) for v in range(1, 11)]
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    exs += [(f"p{i}s{s}", kw, s) for i, kw in enumerate(sets) for s in range(7, 11)]
    exs += [(f"h{i}s{s}", kw, s) for i, kw in enumerate(HARDER.get(cls, [])) for s in range(7, 11)]
    for label, kw, v in exs:
        try:
            ex = mk.make_exemplar(cls, rng=v, **kw) if v is not None else mk.make_exemplar(cls, **kw)
        except Exception as e:  # noqa: BLE001
            print("skip", cls, label, e)
            continue
        a = _levels(ex, 0.0)
        b = _levels(ex, float(astep))
        n += 1
        if a != b:
            changed += 1
            print(cls, label, a, "->", b)
print(f"{changed} of {n} exemplars change size levels")

"""Helper g26s: fixed-mode grow on one row (scales p2s18 by default), GrowParams fields
optionally set (``KEY=VALUE``, for the rejected patches' fields): regularity and failing
metrics per seed, judged as the audit (eq5 and local off).

    PYTHONPATH=src python benchmarks/g26s_rows.py [CLASS:LABEL=scales:p2s18] [SEEDS=1,2,3] [KEY=VALUE ...]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite
from fresh17_rows import exemplar

from strew import Region
from strew.grow import _growth, grow
from strew.metrics import fidelity

spec = sys.argv[1] if len(sys.argv) > 1 else "scales:p2s18"
seeds = [int(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "1,2,3").split(",")]
kw = {k: eval(v) for k, v in (a.split("=") for a in sys.argv[3:])}
orig = _growth.GrowParams.__init__


def init(self, *a, **k):
    orig(self, *a, **k)
    for key, val in kw.items():
        object.__setattr__(self, key, val)


_growth.GrowParams.__init__ = init
cls, label = spec.split(":")
ex = exemplar(fidelity_suite(), cls, label)
for s in seeds:
    x0, y0, x1, y1 = ex.region.bounds
    scale = 3.5
    for _ in range(2):
        out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=s)
        if len(out) >= 10 * len(ex):
            break
        scale *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics.get("regularity")
    fails = [f"{k} {v.result:.4g}/{v.tolerance:.4g}" for k, v in rep.metrics.items() if v.applicable and not v.passed]
    print(f"{spec} seed {s} {kw}: n {len(out)} regularity {m.result if m else float('nan'):.4f} faithful {rep.faithful}; fails {fails}")

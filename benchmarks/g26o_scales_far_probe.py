"""Helper g26o: fixed-mode grow on a scales row with GrowParams.ring_target_far set (the rule
rotation mode has as rotate_target_far, g25o): regularity and failing metrics per seed.

    PYTHONPATH=src python benchmarks/g26o_scales_far_probe.py [CLASS:LABEL=scales:p2s18] [SEEDS=1,2,3] [FAR=0.5|none]
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
far = None if len(sys.argv) > 3 and sys.argv[3] == "none" else float(sys.argv[3]) if len(sys.argv) > 3 else 0.5
if far is not None:
    orig = _growth.GrowParams.__init__

    def init(self, *a, **k):
        orig(self, *a, **k)
        if self.ring_target_far is None:
            object.__setattr__(self, "ring_target_far", far)

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
    m = rep.metrics["regularity"]
    fails = [f"{k}={x.value:.3g}/{x.tolerance:.3g}" for k, x in rep.metrics.items() if x.applicable and not x.passed]
    print(f"{spec} far={far} seed {s} n={len(out)} regularity {m.value:.4f} fails {fails}", flush=True)

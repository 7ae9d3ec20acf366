"""Helper g64c: counterfactual for next step 2 of g64c_notes.md: grow (fixed) on ``--varied`` clusters p2s37 with
its start moved from the region's centroid to a point near a corner (``grow(start=...)``, a public option), so the
one-sided hub ring grows over the whole region; scale as ``grow_variants.run`` (3.5, retried larger).

    PYTHONPATH=src:benchmarks python benchmarks/g64c_start.py clusters:p2s37 1,2 [FX,FY]

FX, FY: the start as fractions of the frame (default 0.97,0.97, the upper-right corner).
"""
import math
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

mk = fidelity_suite()
cls, label = sys.argv[1].split(":")
ex = exemplar(mk, cls, label)
fx, fy = (float(v) for v in (sys.argv[3] if len(sys.argv) > 3 else "0.97,0.97").split(","))
x0, y0, x1, y1 = ex.region.bounds
for seed in _variants.ints(sys.argv[2]):
    scale = 3.5
    for _ in range(2):
        w, h = scale * (x1 - x0), scale * (y1 - y0)
        out = grow(ex, region=Region.rectangle(w, h), mode="fixed", rng=seed, start=(fx * w, fy * h))
        if len(out) >= 10 * len(ex):
            break
        scale *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
    rep = fidelity(ex, out, eq5=False, local=False)
    shown = [f"{k}={m.value:.3g}/{m.tolerance:.3g}{'' if m.passed else '!'}" for k, m in rep.metrics.items() if m.applicable and (k.startswith("g[") or k.startswith("density") or not m.passed)]
    xy = np.c_[out.x, out.y]
    print(f" seed {seed} start {fx:g},{fy:g}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} scale {scale:.2f} x+y {xy.sum(1).min():.0f}-{xy.sum(1).max():.0f} of 0-{w + h:.0f}  {' '.join(shown)}", flush=True)
    if seed == 1:
        from s64c_deciles import render
        render(out, f"benchmarks/results/g64c_p2s37_start{fx:g}_{fy:g}_s1.png")

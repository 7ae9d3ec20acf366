"""Helper g64c: counterfactual for the judge only: the fidelity of grow's output (``--varied`` clusters p2s37, fixed
mode) cropped to a square corner the hubs' growth did fill (x, y < SIDE), against the whole output. If the crop
passes, the failing g[disc,dot] is the empty half-plane (the normalisation by n / |W|), not the rings.

    PYTHONPATH=src:benchmarks python benchmarks/g64c_crop.py clusters:p2s37 1,2 [SIDE=700]
"""
import sys
from types import SimpleNamespace

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run
from strew import Region
from strew.metrics import fidelity

mk = fidelity_suite()
cls, label = sys.argv[1].split(":")
ex = exemplar(mk, cls, label)
side = float(sys.argv[3]) if len(sys.argv) > 3 else 700.0
for seed in _variants.ints(sys.argv[2]):
    out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
    c = (out.x < side) & (out.y < side)
    crop = type(out)(out.shapes, np.asarray(out.kind)[c], out.x[c], out.y[c], np.asarray(out.rotation)[c], np.asarray(out.scale)[c], region=Region.rectangle(side, side))
    for tag, arr in (("whole", out), (f"crop {side:g}", crop)):
        rep = fidelity(ex, arr, eq5=False, local=False)
        shown = [f"{k}={m.value:.3g}/{m.tolerance:.3g}{'' if m.passed else '!'}" for k, m in rep.metrics.items() if m.applicable and (k.startswith("g[") or k.startswith("density") or not m.passed)]
        print(f" seed {seed} {tag}: {'pass' if rep.faithful else 'FAIL'} n={len(arr)} {' '.join(shown)}", flush=True)

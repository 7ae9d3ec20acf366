"""Helper gst: grow rotate mode on the scales EDGE set p2 (wide flat scales, noisier):
regularity (result / exemplar share), rotation spread, with optional grow keywords.

    PYTHONPATH=src python benchmarks/gst_rotate_probe.py [VARIANT=13] [SEEDS=1] [KEY=VALUE ...]
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

mk = fidelity_suite()
v = int(sys.argv[1]) if len(sys.argv) > 1 else 13
seeds = [int(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "1").split(",")]
kw = {k: eval(val, {"math": math}) for k, val in (a.split("=") for a in sys.argv[3:])}
cls = kw.pop("cls", "scales")
# gp_NAME=VALUE: a GrowParams default changed (fields grow does not take)
import inspect

from strew.grow import _growth

for k in [k for k in kw if k.startswith("gp_")]:
    name, val = k[3:], kw.pop(k)
    sig = inspect.signature(_growth.GrowParams.__init__)
    names = [q for q in sig.parameters if q != "self"]
    d = list(_growth.GrowParams.__init__.__defaults__ or ())
    if _growth.GrowParams.__init__.__kwdefaults__ and name in _growth.GrowParams.__init__.__kwdefaults__:
        _growth.GrowParams.__init__.__kwdefaults__[name] = val
    else:
        off = len(names) - len(d)
        d[names.index(name) - off] = val
        _growth.GrowParams.__init__.__defaults__ = tuple(d)
setn = kw.pop("set", 2)
ex = mk.make_exemplar(cls, rng=v, **(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[setn]) if setn >= 0 else mk.make_exemplar(cls, rng=v)


def rot_sd(a):
    r = np.angle(np.exp(1j * (a.rotation - np.angle(np.mean(np.exp(1j * a.rotation))))))
    return float(np.std(r))


print(f"exemplar n={len(ex)} rotation sd {rot_sd(ex):.4f}")
for s in seeds:
    x0, y0, x1, y1 = ex.region.bounds
    scale = 3.5
    for _ in range(2):
        out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), mode="rotate", rng=s, **kw)
        if len(out) >= 10 * len(ex):
            break
        scale *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["regularity"]
    fails = [f"{k}={x.value:.3g}/{x.tolerance:.3g}" for k, x in rep.metrics.items() if x.applicable and not x.passed]
    print(f"seed {s} n={len(out)} regularity {m.result} vs {m.exemplar} (value {m.value:.4f}) rotation sd {rot_sd(out):.4f} fails {fails}", flush=True)

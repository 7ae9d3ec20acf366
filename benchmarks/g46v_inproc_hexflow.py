"""g46v: hexflow (hex lattice, flow field turning 90 degrees, 30 x 20 spacings, relax on), REPS growths in one warm process: min CPU s.
Run: PYTHONPATH=src python benchmarks/g46v_inproc_hexflow.py LABEL 3"""
import sys
import time

import numpy as np
from strew import Region
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar

ref = analyze(hex_exemplar())
sp = ref.mean_edge; w = 30 * sp
def field(p):
    a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
    return np.c_[np.cos(a), np.sin(a)]
kw = {"region": Region.rectangle(w, 20 * sp), "mode": "flow", "flow": field}
grow(ref, rng=1, relax=True, **kw)
ts = []
for _ in range(int(sys.argv[2])):
    c = time.process_time(); out = grow(ref, rng=1, relax=True, **kw); ts.append(time.process_time() - c)
print(sys.argv[1], "hexflow", len(out), f"min {min(ts):.4f} med {sorted(ts)[len(ts)//2]:.4f} el/cpu-s {len(out)/min(ts):.0f}", flush=True)

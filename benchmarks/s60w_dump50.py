"""Helper s60w (issue 13 point 2): synth one suite class at 50x (as seam17_all50.py) and
keep the output (npz: xy, kind, rotation, radius) with the local map, for window diagnosis.

    python benchmarks/s60w_dump50.py NAME SEED OUT.npz
"""
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import SKIPPED, fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

if "--quick" in sys.argv[1:] or len(sys.argv) < 4:
    print("s60w_dump50.py: skipped: 50x canvases (minutes); usage: NAME SEED OUT.npz")
    sys.exit(SKIPPED)
name, seed, path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
mk = fidelity_suite()
ex = mk.make_exemplar(name)
x0, y0, x1, y1 = ex.region.bounds
region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
t0 = time.perf_counter()
out = synthesize(ex, region, rng=seed, measure=False)
rep = fidelity(ex, out, region, eq5=False)
L = rep.local
S = np.asarray(L["score"], float)
W = np.asarray(L["worst_metric"], dtype=object)
print(name, seed, "n", len(out), "s", round(time.perf_counter() - t0, 1), "x0 y0 step window", L["x0"], L["y0"], L["step"], L["window"], "shape", S.shape)
for (i, j), v in np.ndenumerate(S):
    if np.isfinite(v) and v > 0.9:
        print(f"  ({i},{j}) {W[i, j]} {v:.4f}")
np.savez(path, xy=np.asarray(out.xy), kind=np.asarray(out.kind), rot=np.asarray(out.rotation), rad=np.asarray(out.radii), kinds=np.asarray(out.kinds),
         score=S, wm=W.astype(str), geom=np.array([L["x0"], L["y0"], L["step"], L["window"]]), bounds=np.array(region.bounds))

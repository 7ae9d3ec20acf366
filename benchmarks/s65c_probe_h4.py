import sys
import numpy as np
from scipy.spatial import cKDTree
sys.path.insert(0, "benchmarks")
from grow_variants import _harder_suite
from synth_variants import _harder, run
from strew.metrics import fidelity
ex = _harder_suite().make_exemplar("clusters", rng=int(sys.argv[1]), **_harder()["clusters"][4])
def rings(arr, rad=None):
    k = np.asarray(arr.kind_names); xy = arr.xy
    disc, dot = xy[k == "disc"], xy[k == "dot"]
    d, j = cKDTree(disc).query(dot)
    rad = np.median(d) if rad is None else rad
    return np.bincount(j[d <= 1.25 * rad], minlength=len(disc)), rad, len(disc), len(dot), (d > 1.25 * rad).sum()
c, rad, nd, nt, stray = rings(ex)
print("ex", np.bincount(c), "discs", nd, "dots", nt, "stray", stray, "rad", round(rad, 2))
out, _ = run(ex, 3.5, 1, None)
c, _, nd, nt, stray = rings(out, rad)
rep = fidelity(ex, out, eq5=False, local=False)
print("out", np.bincount(c), "discs", nd, "dots", nt, "stray", stray, {k: round(m.value, 3) for k, m in rep.metrics.items() if k.startswith(("density", "empty"))})

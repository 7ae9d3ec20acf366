"""Helper syc16: dots per disc (each dot to its nearest disc) of a clusters --harder exemplar -- all discs and the
discs at least 20 away from the frame -- against its generator drawn at 3.5x (rngs 101-103), with the metric's
nn[dot>dot] of those draws against the exemplar (issue 13 point 1, clusters h3s9).

    PYTHONPATH=TREE/src python benchmarks/syc16_rings.py 3 8,9
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, "benchmarks")
from grow_variants import _harder_suite
from synth_variants import _harder
from strew.metrics import fidelity


def ring(arr, margin=0.0):
    di, do = arr.kinds.index("disc"), arr.kinds.index("dot")
    dpos = arr.xy[arr.kind == di]
    owner = cKDTree(dpos).query(arr.xy[arr.kind == do])[1]
    c = np.bincount(owner, minlength=len(dpos))
    if margin > 0:
        inner = arr.region.geometry.buffer(-margin)
        c = c[shapely.contains_xy(inner, dpos[:, 0], dpos[:, 1])]
    h = np.bincount(c, minlength=8)[:8]
    return f"{h.tolist()} mean {c.mean():.3f} 5:4 {h[5] / max(h[4], 1):.2f}"


i = int(sys.argv[1])
mk = _harder_suite()
kw = dict(_harder()["clusters"][i])
for v in [int(x) for x in sys.argv[2].split(",")]:
    ex = mk.make_exemplar("clusters", rng=v, **kw)
    print(f"h{i}s{v} exemplar all {ring(ex)} | inner {ring(ex, 20.0)}")
    size = ex.meta["params"]["size"]
    for r in (101, 102, 103):
        kw2 = dict(kw); kw2["size"] = size * 3.5
        o = mk.EXEMPLARS["clusters"](r, **kw2)
        m = fidelity(ex, o, eq5=False, local=False).metrics["nn[dot>dot]"]
        print(f"   generator 3.5x rng {r}: {ring(o)} nn[dot>dot] {m.value:.4f}/{m.tolerance:.3f}", flush=True)

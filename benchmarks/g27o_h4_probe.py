"""g27o: kind counts of two_sizes h4s19 (--harder) grown at seeds 1-3 against the exemplar.

    PYTHONPATH=src python benchmarks/g27o_h4_probe.py [V] [1-3]
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import grow

v = int(sys.argv[1]) if len(sys.argv) > 1 else 19
a, _, b = (sys.argv[2] if len(sys.argv) > 2 else "1-3").partition("-")
mk = _harder_suite()
ex = mk.make_exemplar("two_sizes", rng=v, **HARDER["two_sizes"][4])
names = list(ex.shapes)
def frac(arr):
    k = np.asarray(arr.kind)
    return {names[i]: round(float(np.mean(k == i)), 3) for i in range(len(names))}
print("exemplar", len(ex), frac(ex))
from scipy.spatial import cKDTree

xy = np.c_[ex.x, ex.y]; d, _ = cKDTree(xy).query(xy, 2); print("exemplar nn median", np.median(d[:, 1]))
for s in range(int(a), int(b) + 1):
    x0, y0, x1, y1 = ex.region.bounds
    W, H = 3.5 * (x1 - x0), 3.5 * (y1 - y0)
    out = grow(ex, region=Region.rectangle(W, H), rng=s)
    xy = np.c_[out.x, out.y]; d, _ = cKDTree(xy).query(xy, 2)
    print("seed", s, len(out), frac(out), "nn median", np.median(d[:, 1]))

if "--ref" in sys.argv:
    from strew.grow._analysis import analyze, default_priority
    ref = analyze(ex)
    k = np.asarray(ex.kind)[ref.interior]
    print("interior", len(k), {names[i]: round(float(np.mean(k == i)), 3) for i in range(len(names))})
    print("priority", default_priority(ref))

if "--nolone" in sys.argv:
    # the same growth with the lone-kind passes (_lone_larger / _lone_smaller / _lone_kin) off
    import strew.grow._growth as G
    for name in ("swap_lone_larger", "move_lone_smaller", "reseed_lone_kin", "fill_void_holes"):
        if name in sys.argv:
            setattr(G, name, lambda st: False)
    x0, y0, x1, y1 = ex.region.bounds
    from strew.metrics import fidelity
    for s in range(1, 3):
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=s)
        rep = fidelity(ex, out, eq5=False, local=False)
        print("off", [n for n in sys.argv if n in ("swap_lone_larger", "move_lone_smaller", "reseed_lone_kin", "fill_void_holes")], "seed", s, len(out), frac(out),
              [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed])

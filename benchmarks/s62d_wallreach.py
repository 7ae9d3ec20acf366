import sys
sys.path.insert(0, "benchmarks")
import numpy as np
import strew._fidelity as F
import strew.synth._displace as DP
from grow_variants import _harder_suite
from synth_variants import _harder, run
W, M = [], []
_w = F._wall_reach
def w(*a):
    r = _w(*a); W.append(r); return r
F._wall_reach = w
_i = DP._inner_density
def i(prep, margin):
    M.append(margin); return _i(prep, margin)
DP._inner_density = i
from strew.metrics import fidelity
mk = _harder_suite(); H = _harder()
for h, v in [(8, 36), (9, 36), (10, 8), (3, 8)]:
    ex = mk.make_exemplar("two_sizes", rng=v, **H["two_sizes"][h])
    W.clear(); M.clear()
    out, _ = run(ex, 3.5, 1, None)
    fidelity(ex, out, eq5=False, local=False)
    print(f"h{h}s{v}: ratio {H['two_sizes'][h].get('ratio')} synth margin {M[0]:.2f}; metric wall reach calls {[round(x, 2) for x in W[:3]]}")

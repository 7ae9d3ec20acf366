"""Helper s61c: clusters p2s36 probe: discs per area in the output against the exemplar, what _far_hub_room allows, and the metric's density factors.

    PYTHONPATH=src:benchmarks python benchmarks/s61c_probe.py LABEL SEEDS
"""
import sys
import numpy as np
sys.path.insert(0, __file__.rsplit("/", 1)[0])
from fresh17_rows import exemplar
from _runner import fidelity_suite
from synth_variants import run
import strew._fidelity as F
import strew.synth._grow as G
from strew.metrics import fidelity

label, seeds = sys.argv[1], [int(s) for s in sys.argv[2].split(",")]
ex = exemplar(fidelity_suite(), "clusters", label)
kinds = list(ex.kinds) if hasattr(ex, "kinds") else None
orig = G._far_hub_room
def spy(state):
    out = orig(state)
    prep = state.prep
    far = getattr(prep, "_far_hubs", None)
    print("  far_hub_room:", None if out is None else out[out < 10**9], "far hubs", None if far is None else int(far.sum()), "n", state.n, flush=True)
    return out
G._far_hub_room = spy
_rec = []
_od = F._discrepancies
def _dspy(a, b, *args, **kw):
    _rec.append((a, b))
    return _od(a, b, *args, **kw)
F._discrepancies = _dspy
exa = ex.region.geometry.area
kx = np.asarray(ex.kind) if hasattr(ex, "kind") else None
print("exemplar area", exa, "n", len(ex), flush=True)
for seed in seeds:
    out, _ = run(ex, 3.5, seed, None)
    _rec.clear()
    rep = fidelity(ex, out, eq5=False, local=False)
    a, b = _rec[0]
    print(f"   metric: out density {a.density} counts {a.counts} area {a.area:.0f}; ex density {b.density} counts {b.counts} area {b.area:.0f}", flush=True)
    print(f"seed {seed} n={len(out)} faithful={rep.faithful} dens[disc]={rep.metrics['density[disc]'].value:.3f} dens[dot]={rep.metrics['density[dot]'].value:.3f}", flush=True)
    for a, nm in ((ex, "ex"), (out, "out")):
        ks = np.asarray(a.kind)
        print(f"   {nm}: area {a.region.geometry.area:.0f} counts {np.bincount(ks)} per 1e4 {np.bincount(ks)/a.region.geometry.area*1e4}", flush=True)

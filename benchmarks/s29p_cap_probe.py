"""Helper s29p: with benchmarks/results/s29p_rejected_step_share_cap.patch applied, per size class of
three_sizes h3s20 (seed 1): proposals placed in growth's first placing pass, cut by the cap, and generated;
then the output's counts per kind.

    PYTHONPATH=src:benchmarks python benchmarks/s29p_cap_probe.py
"""
import sys
sys.path.insert(0, "benchmarks")
import numpy as np
from grow_variants import _harder_suite
from synth_variants import _harder, run
import strew.synth._grow as G
import strew.synth._kernels as K
ex = _harder_suite().make_exemplar("three_sizes", rng=20, **_harder()["three_sizes"][3])
T = {"p1": np.zeros(3, int), "cut": np.zeros(3, int), "p2": np.zeros(3, int), "gen": np.zeros(3, int)}
_o = G._over_share
_pl = K.place_proposals
LAST = {}
def over(prep, placed, gen_ok, exv, *a):
    c = _o(prep, placed, gen_ok, exv, *a)
    cls = prep.size_class[exv]
    T["p1"] += np.bincount(cls[placed], minlength=3)[:3]
    T["cut"] += np.bincount(cls[c], minlength=3)[:3]
    T["gen"] += np.bincount(cls[gen_ok], minlength=3)[:3]
    T["steps"] = T.get("steps", 0) + 1
    return c
G._over_share = over
out, _ = run(ex, 3.5, 1, None)
for k, v in T.items(): print(k, v, np.round(v / np.sum(v), 3))
kn = np.asarray(out.kind_names); print({k: int((kn == k).sum()) for k in set(kn)})

"""Helper s27k (with benchmarks/results/s27k_rejected_copyable.patch applied): which classes ``_grow.COPYABLE_ONLY`` changes: each fidelity-suite class (default
exemplar, or a fresh17 label) synthesized at SCALE times the frame's side with the flag on and off,
same rng; prints identical / changed with both counts and both verdicts.

    PYTHONPATH=src:benchmarks python benchmarks/s27k_identical.py [--scale 2] [--seed 1] [--only a,b] [--label v19]
"""
import argparse
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar

import strew.synth._grow as G
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

ap = argparse.ArgumentParser()
ap.add_argument("--scale", type=float, default=2.0)
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--only", default=None)
ap.add_argument("--label", default=None)
a = ap.parse_args()
mk = fidelity_suite()
names = a.only.split(",") if a.only else list(mk.NAMES)
for name in names:
    ex = exemplar(mk, name, a.label) if a.label else mk.make_exemplar(name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
    res = []
    for flag in (False, True):
        G.COPYABLE_ONLY = flag
        out = synthesize(ex, region, rng=a.seed, measure=False)
        rep = fidelity(ex, out, region, eq5=False, local=False)
        res.append((out, rep.faithful))
    same = len(res[0][0]) == len(res[1][0]) and np.array_equal(res[0][0].xy, res[1][0].xy)
    print(f"{name:16s} {'identical' if same else 'CHANGED'} n {len(res[0][0])} -> {len(res[1][0])} faithful {res[0][1]} -> {res[1][1]}", flush=True)

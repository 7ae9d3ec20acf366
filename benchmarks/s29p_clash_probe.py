"""Helper s29p: per size class of one --harder synth row, proposals ``K.place_proposals`` places in growth
against those ``shape_clashes`` then refuses (the exact-shape test after the disc placing) and those
``state.add`` receives.

    PYTHONPATH=src:benchmarks python benchmarks/s29p_clash_probe.py CLASS:H:V:SEED
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._grow as G
import strew.synth._kernels as K

name, i, v, seed = sys.argv[1].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
S = len(ex.kinds)
T = {k: np.zeros(S, int) for k in ("placed", "shape clash", "added")}
_pl, _sc = K.place_proposals, G.shape_clashes
LAST = {}


def place(costs, slack, out_ptr, count, ppos, pr, skind, *a):
    placed, s_ok = _pl(costs, slack, out_ptr, count, ppos, pr, skind, *a)
    T["placed"] += np.bincount(skind[placed], minlength=S)[:S]
    return placed, s_ok


def clash(state, ex_idx, pos):
    c = _sc(state, ex_idx, pos)
    T["shape clash"] += np.bincount(state.prep.skind[ex_idx[c]], minlength=S)[:S]
    return c


K.place_proposals, G.shape_clashes = place, clash
out, _ = run(ex, 3.5, int(seed), None)
kn = np.asarray(out.kind_names)
for k, a in T.items():
    print(f"{k:12s} {a}")
print("output", {k: int((kn == k).sum()) for k in ex.kinds})

"""Helper s28h (issue 13 point 1): where a size class is lost in synth's growth loop (§5.1), per kind, summed
over growth's iterations of one --harder row: proposals generated (every k-coherence candidate of every seed,
``generate_proposals``), refused by O (``_split_conflicts``: intersecting elements that do not yield), left
eligible when ``place_proposals`` chooses, and placed. Shares of each stage's total, next to the exemplar's
count share.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s28h_funnel.py CLASS:H:V:SEEDS [NAME=VALUE ...]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._grow as G
import strew.synth._kernels as K

for kv in sys.argv[2:]:  # --set-like NAME=VALUE of strew.synth._grow (helper s28h)
    nm, val = kv.split("=")
    setattr(G, nm, eval(val))
    print("set", nm, val)
name, i, v, seeds = sys.argv[1].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
S = len(ex.kinds)
ST = {}
PREP = [None]
_gen, _place, _split = K.generate_proposals, K.place_proposals, G._split_conflicts


def tally(key, kinds):
    ST[key] = ST.get(key, np.zeros(S, int)) + np.bincount(kinds, minlength=S)[:S]


def gen(*a):
    r = _gen(*a)
    if PREP[0] is not None:
        exv = r[1]
        tally("generated", PREP[0].skind[exv[exv >= 0]])
    return r


def split(state, pts, src, visible_only):
    PREP[0] = state.prep
    hard = _split(state, pts, src, visible_only)
    tally("offered to O", state.prep.skind[src])
    tally("refused by O", state.prep.skind[src[hard]])
    return hard


def place(costs, slack, out_ptr, count, ppos, pr, skind, md, okp, *a):
    placed, s_ok = _place(costs, slack, out_ptr, count, ppos, pr, skind, md, okp, *a)
    tally("eligible", skind[okp])
    tally("placed", skind[placed])
    return placed, s_ok


K.generate_proposals, K.place_proposals, G._split_conflicts = gen, place, split
exn = np.bincount(np.asarray(ex.kind), minlength=S)
print(f"{name} h{i}s{v} kinds {list(ex.kinds)} exemplar share {np.round(exn / exn.sum(), 3)}")
for seed in [int(x) for x in seeds.split(",")]:
    ST.clear()
    PREP[0] = None
    out, _ = run(ex, 3.5, seed, None)
    for k, a in ST.items():
        print(f"  seed {seed} {k:13s} {a} share {np.round(a / max(a.sum(), 1), 3)}")
    print(f"  seed {seed} refused/offered {np.round(ST['refused by O'] / np.maximum(ST['offered to O'], 1), 3)} placed/eligible {np.round(ST['placed'] / np.maximum(ST['eligible'], 1), 3)}")

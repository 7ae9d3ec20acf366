"""Helper s66h: in synth's growth on --harder clusters h4 (until _complete_anchor_rings), how many disc and
dot proposals pass the hard tests (collision, crowding, ring cap) and how many are placed, ring cap on or off;
and how many proposals the ring cap refuses.

    PYTHONPATH=src:benchmarks python benchmarks/s66h_disc_proposals.py VARIANT SEEDS --cap 0|1
"""
import functools
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._grow as G

CAP = int(sys.argv[sys.argv.index("--cap") + 1]) if "--cap" in sys.argv else 1
G.RING_CAP = bool(CAP)
C = {}
GROWING = [True]


def count_place(f):
    @functools.wraps(f)
    def w(costs, slack, out_ptr, count, ppos, pr, skind, min_dist, okp, *a):
        placed, s_ok = f(costs, slack, out_ptr, count, ppos, pr, skind, min_dist, okp, *a)
        if GROWING[0]:
            kind = PREP[0].kind[EXV[0]] if EXV[0] is not None and len(EXV[0]) == len(okp) else None
            if kind is not None:
                for k, nm in ((0, "disc"), (1, "dot")):
                    C[f"{nm} ok"] = C.get(f"{nm} ok", 0) + int(np.sum(okp & (kind == k)))
                    C[f"{nm} placed"] = C.get(f"{nm} placed", 0) + int(np.sum(placed & (kind == k)))
        return placed, s_ok
    return w


PREP, EXV = [None], [None]
orig_split = G._split_conflicts


def split(state, pts, src, **kw):
    PREP[0] = state.prep
    return orig_split(state, pts, src, **kw)


orig_full = G._ring_full


def full(state, pts, src, caps):
    out = orig_full(state, pts, src, caps)
    if GROWING[0]:
        C["cap refused"] = C.get("cap refused", 0) + int(out.sum())
    return out




def car(f):
    @functools.wraps(f)
    def w(state, *a, **k):
        GROWING[0] = False
        return f(state, *a, **k)
    return w


G.K.place_proposals = count_place(G.K.place_proposals)
G._split_conflicts = split
G._ring_full = full
G._complete_anchor_rings = car(G._complete_anchor_rings)
# the kinds of the proposals place_proposals sees: exv is prep-indexed; recover it from skind's caller via a
# wrapper of generate_proposals (ex) -- exv = max(ex, 0)
orig_gen = G.K.generate_proposals


def gen(*a):
    r = orig_gen(*a)
    EXV[0] = np.maximum(r[1], 0)
    return r


G.K.generate_proposals = gen
v = int(sys.argv[1])
assert v <= 38
ex = _harder_suite().make_exemplar("clusters", rng=v, **_harder()["clusters"][4])
for seed in _variants.ints(sys.argv[2]):
    C.clear()
    GROWING[0] = True
    out, _ = run(ex, 3.5, seed, None)
    print(f"h4s{v} cap={CAP} seed {seed}: n={len(out)} growth: " + " ".join(f"{k} {v}" for k, v in sorted(C.items())), flush=True)

"""s30h: trace trade_far_top on a --harder row (budget, far owners, sites tried, trades, smalls removed).

PYTHONPATH=src:benchmarks python benchmarks/s30h_trace.py three_sizes:6:19:1,2,3
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._farmix as F

log = []
_orig_at = F._trade_at
_orig_top = F.trade_far_top


def at(*a, **k):
    g = _orig_at(*a, **k)
    if a[0] is not None and _in_top[0]:
        log.append(g)
    return g


_in_top = [False]


def top(state, room=None, since=0):
    _in_top[0] = True
    log.clear()
    n0 = state.n
    r = _orig_top(state, room, since)
    _in_top[0] = False
    print(f"  trade_far_top net {r} n {n0}->{state.n} tries {len(log)} trades {sum(g >= 0 for g in log)} removed {sum(g for g in log if g > 0)}", flush=True)
    return r


F._trade_at = at
F.trade_far_top = top
for spec in sys.argv[1:]:
    name, i, v, seeds = spec.split(":")
    ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
    for seed in [int(x) for x in seeds.split(",")]:
        print(spec, seed, flush=True)
        run(ex, 3.5, seed, None)

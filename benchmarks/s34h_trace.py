"""s34h (issue 13 point 1): large/medium/small stone counts of the output after each of grow's
closing fills, three sizes h3s20 (the s31l test's exemplar) at 2x, or the suite's three sizes
(``suite``). Needs benchmarks/results/s34h_rejected_refill_vacated.patch applied (runs on main too).

    PYTHONPATH=src:tests python benchmarks/s34h_trace.py [h3|suite|suite50] SEEDS  (suite50: 7.07x the side, the 50x tests' canvas)
"""
import sys

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import _displace, _farmix, _grow, _pebbles, _shell, _swap, synthesize

H3 = {"ratios": (1.0, 1.5, 3.0), "counts": (150, 80, 30)}


def counts(state):
    prep = state.prep
    v = np.flatnonzero(~prep.void[state.src[: state.n]])
    return np.bincount(prep.size_class[state.src[v]], minlength=3).tolist()


def wrap(mod, name):
    orig = getattr(mod, name)

    def f(state, *a, **k):
        b = counts(state)
        r = orig(state, *a, **k)
        a_ = counts(state)
        if a_ != b:
            print(f"  {name:28s} {b} -> {a_}", flush=True)
        return r

    setattr(mod, name, f)


for mod, name in [(_displace, "fill_displaced"), (_shell, "fill_large_beside_far_small"), (_shell, "fill_beside_largest"),
                  (_farmix, "trade_far_small"), (_farmix, "trade_far_top"), (_shell, "fill_beside_far_small"),
                  (_grow, "fill_room"), (_pebbles, "fill_partners"), (_swap, "fill_swapped"), (_grow, "fill_holes")]:
    wrap(mod, name)
which = sys.argv[1]
ex = fidelity_suite().make_exemplar("three_sizes", rng=20, **H3) if which == "h3" else fidelity_suite().make_exemplar("three_sizes")
x0, y0, x1, y1 = ex.region.bounds
scale = 7.07 if which == "suite50" else 2.0
for seed in [int(v) for v in sys.argv[2].split(",")]:
    out = synthesize(ex, Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=seed, measure=False)
    ok = np.asarray(out.kind)
    print(seed, {n: int(np.count_nonzero(ok == i)) for i, n in enumerate(ex.kinds)}, flush=True)

"""s33h (needs benchmarks/results/s33h_rejected_move_large_to_stranded.patch applied): how many large stones ``_shell.fill_large_beside_far_small`` adds, and the farmix /
shell figures, on the suite's three sizes at 2x.

``PYTHONPATH=src:tests python benchmarks/s33h_probe.py 1,2``; S33H_OFF=1 turns the fill off.
"""
import os
import sys

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import _shell, synthesize

orig = _shell.fill_large_beside_far_small


def wrapped(state, room=None, since=0):
    if os.environ.get("S33H_OFF"):
        return 0
    n = orig(state, room, since)
    print("  fill_large_beside_far_small added", n, flush=True)
    return n


_shell.fill_large_beside_far_small = wrapped
ex = fidelity_suite().make_exemplar("three_sizes")
x0, y0, x1, y1 = ex.region.bounds
for seed in [int(v) for v in sys.argv[1].split(",")]:
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed, measure=False)
    k = list(ex.kinds)
    ok = np.asarray(out.kind)
    print(seed, {n: int(np.count_nonzero(ok == i)) for i, n in enumerate(k)}, flush=True)

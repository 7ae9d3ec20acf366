"""s34h (flags need benchmarks/results/s34h_rejected_refill_vacated.patch applied): tests/synth/test_synth_s30h_far_top.py's share of large stones far from every medium one
(three sizes h6s19 at 2x; the test asserts max over seeds 1/3 <= 0.03), per seed, and how many
large stones ``_shell.fill_large_beside_far_small`` moved. Flags MODULE.NAME=VALUE of strew.synth.

    PYTHONPATH=src:tests python benchmarks/s34h_fartop.py 1,3 [_shell.DONOR_TRIES=0 ...]
"""
import importlib
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, "tests/synth")
from strew_testing import fidelity_suite  # noqa: E402
from test_synth_s30h_far_top import H6, _far_large  # noqa: E402

from strew import Region  # noqa: E402
from strew.synth import _shell, synthesize  # noqa: E402

for kv in sys.argv[2:]:
    k, v = kv.split("=")
    mod, name = k.split(".")
    m = importlib.import_module("strew.synth." + mod)
    setattr(m, name, type(getattr(m, name))(float(v)))
orig = _shell.fill_large_beside_far_small
moved = []


def wrapped(state, room=None, since=0):
    c0 = int(getattr(state, "ceded_top", 0))
    n = orig(state, room, since)
    moved.append(c0 - int(getattr(state, "ceded_top", 0)))
    return n


_shell.fill_large_beside_far_small = wrapped
ex = fidelity_suite().make_exemplar("three_sizes", rng=19, **H6)
names, xy = np.asarray(ex.kind_names), np.asarray(ex.xy)
far = float(np.quantile(cKDTree(xy[names == "medium"]).query(xy[names == "large"])[0], 0.9))
x0, y0, x1, y1 = ex.region.bounds
for seed in [int(v) for v in sys.argv[1].split(",")]:
    moved.clear()
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed, measure=False)
    print(f"seed {seed}: far large share {_far_large(out, far):.4f} moved {sum(moved)}", flush=True)

"""s34h (flags need benchmarks/results/s34h_rejected_refill_vacated.patch applied): the suite's three sizes at 50x (tests/synth/test_synth_50x.py's draw): local map windows
scoring over 0.9 (the test fails on any over 1.0), and the far-small share of
test_three_sizes_50x_fewer_small_stones_far_from_large. Flags MODULE.NAME=VALUE of strew.synth.

    PYTHONPATH=src:tests python benchmarks/s34h_50x.py SEEDS [_grow.VACATED_FILL=0 _shell.DONOR_TRIES=0 ...]
"""
import importlib
import sys

import numpy as np

sys.path.insert(0, "tests/synth")
from strew_testing import synth_at_50x  # noqa: E402
from test_synth_50x import _far_share  # noqa: E402

for kv in sys.argv[2:]:
    k, v = kv.split("=")
    mod, name = k.split(".")
    m = importlib.import_module("strew.synth." + mod)
    setattr(m, name, type(getattr(m, name))(float(v)))
for seed in [int(v) for v in sys.argv[1].split(",")]:
    ex, out, region, rep = synth_at_50x("three_sizes", seed)
    score = np.asarray(rep.local["score"], float)
    ok = np.isfinite(score)
    print(f"seed {seed}: faithful {rep.faithful} windows {ok.sum()} over 1: {(score[ok] > 1).sum()} worst {rep.local['worst']} "
          f"far share {_far_share(ex, out, region):.4f}", flush=True)
    b = rep.local["worst"]["bounds"]
    xy, kn = np.asarray(out.xy), np.asarray(out.kind_names)
    exy, ekn = np.asarray(ex.xy), np.asarray(ex.kind_names)
    from scipy.spatial import cKDTree
    med = xy[kn == "medium"]
    inb = (med[:, 0] > b[0]) & (med[:, 0] < b[2]) & (med[:, 1] > b[1]) & (med[:, 1] < b[3])
    d = cKDTree(med).query(med[inb], k=2)[0][:, 1]
    em = exy[ekn == "medium"]
    de = cKDTree(em).query(em, k=2)[0][:, 1]
    q = [0.1, 0.3, 0.5, 0.7, 0.9]
    print("  worst window nn[medium>medium] q10-90", np.round(np.quantile(d, q), 1), "exemplar", np.round(np.quantile(de, q), 1),
          "counts", {k: int(((xy[kn == k][:, 0] > b[0]) & (xy[kn == k][:, 0] < b[2]) & (xy[kn == k][:, 1] > b[1]) & (xy[kn == k][:, 1] < b[3])).sum()) for k in ("small", "medium", "large")})

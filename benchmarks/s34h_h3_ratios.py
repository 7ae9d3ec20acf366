"""s34h (flags need benchmarks/results/s34h_rejected_refill_vacated.patch applied): the figures of tests/synth/test_synth_s31l_settle_by_place.py's h3s20 test (large and
small stones per area 20 in from the frame at 2x, against the exemplar's), per seed.

    PYTHONPATH=src:tests python benchmarks/s34h_h3_ratios.py 1,2 [NAME=VALUE of strew.synth._grow ...]
"""
import sys

import numpy as np

sys.path.insert(0, "tests/synth")
from strew_testing import fidelity_suite  # noqa: E402
from test_synth_s31l_settle_by_place import H3, _inner_per_area  # noqa: E402

from strew import Region  # noqa: E402
from strew.synth import _grow, synthesize  # noqa: E402

for kv in sys.argv[2:]:
    k, v = kv.split("=")
    setattr(_grow, k, type(getattr(_grow, k))(float(v)))

ex = fidelity_suite().make_exemplar("three_sizes", rng=20, **H3)
x0, y0, x1, y1 = ex.region.bounds
L, S = [], []
for seed in [int(v) for v in sys.argv[1].split(",")]:
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed, measure=False)
    L.append(_inner_per_area(out, "large", 20.0) / _inner_per_area(ex, "large", 0.0))
    S.append(_inner_per_area(out, "small", 20.0) / _inner_per_area(ex, "small", 0.0))
    m = _inner_per_area(out, "medium", 20.0) / _inner_per_area(ex, "medium", 0.0)
    print(f"seed {seed}: large {L[-1]:.3f} medium {m:.3f} small {S[-1]:.3f}", flush=True)
print(f"mean large {np.mean(L):.3f} (<= 1.34) small {np.mean(S):.3f} (>= 0.735)")

"""s34h (flags need benchmarks/results/s34h_rejected_refill_vacated.patch applied): tests/synth/test_synth_syn13w_farmix.py's far-small excess on the suite's three sizes at
2x, per seed (the test asserts seed 1 <= 1.2). Flags as NAME=VALUE of strew.synth._grow after the seeds.

    PYTHONPATH=src:tests python benchmarks/s34h_farmix.py 1,2,3 [VACATED_FILL=0]
"""
import sys

sys.path.insert(0, "tests/synth")
from strew_testing import fidelity_suite  # noqa: E402
from test_synth_syn13w_farmix import _far_excess  # noqa: E402

from strew import Region  # noqa: E402
from strew.synth import _grow, synthesize  # noqa: E402

for kv in sys.argv[2:]:
    k, v = kv.split("=")
    setattr(_grow, k, type(getattr(_grow, k))(float(v)))
ex = fidelity_suite().make_exemplar("three_sizes")
x0, y0, x1, y1 = ex.region.bounds
for seed in [int(v) for v in sys.argv[1].split(",")]:
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed, measure=False)
    print(f"seed {seed}: farmix {_far_excess(ex, out):.3f}", flush=True)

"""s28k: tests/synth/test_synth_sp_sized_scatter.py::test_two_sizes_h5s11_faithful's figures
(two sizes h5 at variant seed 11, 3.5x) under copyable's settings.

    PYTHONPATH=src python benchmarks/s28k_h5s11.py MODE [SEEDS=1,2]

MODE: largest | all | off. Prints nn[pebble>pebble] and the judge's failures.
"""

import sys

sys.path.insert(0, "tests")
import strew.synth._grow as G
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize
from strew_testing import fidelity_suite

H5 = dict(ratio=0.6, n_large=25, n_small=250)
mode = sys.argv[1]
seeds = [int(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "1,2").split(",")]
if len(sys.argv) > 3:
    G.COPYABLE_EDGE = sys.argv[3] == "1"
if mode == "off":
    G.COPYABLE_ONLY = False
else:
    G.COPYABLE_SEEDS = mode
ex = fidelity_suite().make_exemplar("two_sizes", rng=11, **H5)
x0, y0, x1, y1 = ex.region.bounds
for seed in seeds:
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
    rep = fidelity(ex, out, eq5=False, local=False)
    nn = {k: f"{v.value:.4f}/{v.tolerance:.3g}" for k, v in rep.metrics.items() if k.startswith("nn[") and v.applicable}
    print(mode, seed, "n", len(out), "faithful", rep.faithful, [f"{k}={v.value:.3g}/{v.tolerance:.3g}" for k, v in rep.metrics.items() if v.applicable and not v.passed], nn)

"""s28k: the figure of tests/synth/test_synth_fidelity.py::test_untuned_cluster_variants_are_faithful
(share of dots within 1.3 ring radii of a disc; the test asks > 0.9) under copyable's settings.

    PYTHONPATH=src python benchmarks/s28k_untuned.py [MODE=largest|all|off] [VARIANTS=1,3] [EDGE=1|0] [RNG=2]

RNG: synthesis seeds (comma list); the test uses 2. EDGE sets _grow.COPYABLE_EDGE.
"""

import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, "tests")
import strew.synth._grow as G
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize
from strew_testing import fidelity_suite

mode = sys.argv[1] if len(sys.argv) > 1 else "largest"
variants = [int(v) for v in (sys.argv[2] if len(sys.argv) > 2 else "1,3").split(",")]
if len(sys.argv) > 3:
    G.COPYABLE_EDGE = sys.argv[3] == "1"
if mode == "off":
    G.COPYABLE_ONLY = False
else:
    G.COPYABLE_SEEDS = mode
suite = fidelity_suite()
rngs = [int(r) for r in (sys.argv[4] if len(sys.argv) > 4 else "2").split(",")]
for v, rng in [(v, r) for v in variants for r in rngs]:
    ex = suite.make_exemplar("clusters", rng=v)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0))
    out = synthesize(ex, region, rng=rng, measure=False)
    rep = fidelity(ex, out, region, eq5=False, local=False)
    dots, discs = out.select(out.kind == out.kinds.index("dot")), out.select(out.kind == out.kinds.index("disc"))
    near = cKDTree(discs.xy).query(dots.xy)[0] < 1.3 * 12.5
    print(f"{mode} variant {v} rng {rng}: n {len(out)} discs {len(discs)} dots {len(dots)} near {near.mean():.4f} faithful {rep.faithful} {rep.failures}")

"""s27t: clusters h3s9 (test_synth_syc16_orphans's case) at 2x, dot density and the judge's
failures, for thin_crowded's removal order.

``PYTHONPATH=src python benchmarks/s27t_order.py ORDER SEED...`` with ORDER ``on`` or ``off``
(thin_crowded off). (While choosing, ORDER ``err``, the children farthest from their slot on
the parent's copy first, gave the same as ``crowd``, nearest another of its kind first:
1492 elements, faithful, seeds 1-2; ``off`` 1529/1526, faithful.)
"""

from __future__ import annotations

import sys

sys.path.insert(0, "tests")
import numpy as np

from strew import Region
from strew.metrics import fidelity
from strew.synth import _thin, synthesize
from strew_testing import fidelity_suite

CL = {"large": 5.0, "small": 2.0, "cluster_spacing": 30.0, "ring_min": 4, "ring_max": 5}
order = sys.argv[1]
if order == "off":
    _thin.THIN_CROWDED = False
ex = fidelity_suite().make_exemplar("clusters", rng=9, **CL)
x0, y0, x1, y1 = ex.region.bounds
for seed in map(int, sys.argv[2:]):
    region = Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0))
    out = synthesize(ex, region, rng=seed, measure=False)
    rep = fidelity(ex, out, region, eq5=False)
    print(order, seed, len(out), rep.faithful, rep.failures)

"""s27t: tests/synth/test_synth_fidelity.py::test_untuned_cluster_variants_are_faithful's
figures (clusters variants 1 and 3 at 2x, seed 2): the share of dots within 1.3 ring radii of
a disc (the test asks > 0.9), each kind's inner density ratio, the judge's failures.

``PYTHONPATH=src python benchmarks/s27t_untuned.py [off|on] [VARIANT...]``
"""

from __future__ import annotations

import sys

sys.path.insert(0, "tests")
import numpy as np
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import fidelity
from strew.synth import _thin, synthesize
from strew_testing import fidelity_suite, synth_inner_density_ratios

if sys.argv[1:2] == ["off"]:
    _thin.THIN_CROWDED = False
suite = fidelity_suite()
for variant in map(int, sys.argv[2:] or ["1", "3"]):
    ex = suite.make_exemplar("clusters", rng=variant)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0))
    out = synthesize(ex, region, rng=2, measure=False)
    rep = fidelity(ex, out, region, eq5=False, local=False)
    dots, discs = out.select(out.kind == out.kinds.index("dot")), out.select(out.kind == out.kinds.index("disc"))
    near = cKDTree(discs.xy).query(dots.xy)[0] < 1.3 * 12.5
    print(sys.argv[1:2], variant, "n", len(out), "near", round(float(near.mean()), 4), "dens", synth_inner_density_ratios(ex, rng=2), rep.failures)

"""Helper s32l probe: three sizes (suite exemplar) at 2x, seeds given: the farmix far-small
excess (tests/synth/test_synth_syn13w_farmix.py) and large/medium/small counts.

    PYTHONPATH=src:tests python benchmarks/s32l_probe.py 1,2,3
    S32L_OFF=1 ... : settling off (main's output)
"""
import sys
import numpy as np
sys.path.insert(0, "tests/synth")
from strew_testing import fidelity_suite
from strew import Region
from strew.synth import synthesize
from test_synth_syn13w_farmix import _far_excess
import os
if os.environ.get("S32L_OFF"):
    from strew.synth import _grow
    _grow.SETTLE_CLASSES = 0  # main's placing (byte-identical)

ex = fidelity_suite().make_exemplar("three_sizes")
x0, y0, x1, y1 = ex.region.bounds
for s in [int(v) for v in sys.argv[1].split(",")]:
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=s, measure=False)
    names = np.asarray(out.kind_names)
    print(s, "far_excess %.3f" % _far_excess(ex, out), {k: int((names == k).sum()) for k in ("small", "medium", "large")}, flush=True)

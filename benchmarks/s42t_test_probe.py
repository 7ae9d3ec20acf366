"""Helper s42t: whole-output share ratios (output / exemplar) of three sizes 150:80:30,
ratios 1:1.5:3 (--harder h3) at 2x the exemplar's side, as tests/synth/test_synth_s42t_middle_margin.py.

    PYTHONPATH=TREE/src:tests python benchmarks/s42t_test_probe.py 28,8 1,2
"""
import sys
import time

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize

H3 = dict(ratios=(1.0, 1.5, 3.0), counts=(150, 80, 30))
for v in [int(x) for x in sys.argv[1].split(",")]:
    ex = fidelity_suite().make_exemplar("three_sizes", rng=v, **H3)
    x0, y0, x1, y1 = ex.region.bounds
    for seed in [int(x) for x in sys.argv[2].split(",")]:
        t = time.process_time()
        out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=seed, measure=False)
        ratio = (np.bincount(out.kind, minlength=3) / len(out)) / (np.bincount(ex.kind, minlength=3) / len(ex))
        dens = np.bincount(out.kind, minlength=3) / out.region.geometry.area / (np.bincount(ex.kind, minlength=3) / ex.region.geometry.area)
        print(f"v{v} seed {seed} kinds {list(out.kinds)} share ratio {np.round(ratio, 3)} density ratio {np.round(dens, 3)} n={len(out)} cpu {time.process_time() - t:.1f}", flush=True)

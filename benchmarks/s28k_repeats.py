"""s28k: the figures of tests/synth/test_synth_seam50_repeats.py::test_fewer_repeated_copies_near_each_element
under one copyable mode (issue 13 point 1).

    PYTHONPATH=src python benchmarks/s28k_repeats.py MODE [SEED]

MODE: off (COPYABLE_ONLY False), tip (the branch as it is).
Prints n and _repeats for REPEAT_RADIUS 0 and 1, and their ratio (the test asks < 0.92).
"""

import sys

import numpy as np

sys.path.insert(0, "tests/synth")
sys.path.insert(0, "tests")
import strew.synth._grow as G
from strew import Region
from strew_testing import fidelity_suite
from test_synth_seam50_repeats import _grown, _repeats

mode = sys.argv[1]
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
if mode == "off":
    G.COPYABLE_ONLY = False
ex = fidelity_suite().make_exemplar("three_sizes")
x0, y0, x1, y1 = ex.region.bounds
side = float(np.sqrt((x1 - x0) * (y1 - y0)))
region = Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0))
off = _grown(ex, region, seed, 0.0)
on = _grown(ex, region, seed, 1.0)
a, b = _repeats(off, side), _repeats(on, side)
print(f"{mode} seed {seed}: n {off.n} {on.n}  repeats off {a:.4f} on {b:.4f}  ratio {b / a:.4f}")

"""Cold first run of synth on an exemplar that takes the shape limit (the suite's sticks).

Run it twice in a fresh process with an empty numba cache, once per tree, to see the
compile cost of the kernels a sticks fill uses (``synth._kernels.shape_counts`` since
this stop) separately from the warm run:

    NUMBA_CACHE_DIR=/tmp/empty_cache PYTHONPATH=src:benchmarks python benchmarks/integ29_cold_sticks.py
    NUMBA_CACHE_DIR=/tmp/empty_cache PYTHONPATH=src:benchmarks python benchmarks/integ29_cold_sticks.py

Prints CPU and wall seconds of the whole process's work after start-up, and the count.
"""

import sys
import time

t0, w0 = time.process_time(), time.time()
sys.path.insert(0, "benchmarks")
from _runner import fidelity_suite

from strew import Region
from strew.synth import synthesize

ex = fidelity_suite().make_exemplar("sticks")
x0, y0, x1, y1 = ex.region.bounds
out = synthesize(ex, Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0)), rng=1)
print(f"cpu {time.process_time() - t0:.1f} wall {time.time() - w0:.1f} n {len(out)}")

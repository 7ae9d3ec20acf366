"""Cold first run of synth on a built-in exemplar (grid, stripes, rings, apples).

Run it in a fresh process with an empty numba cache, once per tree, to see the compile cost
of the kernels a fill uses separately from the warm run (this stop added numba kernels for
DBSCAN and the own-jitter step, s34v):

    NUMBA_CACHE_DIR=$(mktemp -d) PYTHONPATH=TREE/src python benchmarks/integ30_cold.py grid
    PYTHONPATH=TREE/src python benchmarks/integ30_cold.py grid      # warm: cache filled

Prints CPU and wall seconds of the process's work after start-up (imports, compiles, one
fill of the benchmark's size), and the element count.
"""

import sys
import time

t0, w0 = time.process_time(), time.time()
from strew import Region
from strew.synth import fill, new_state
from strew.synth._exemplars import EXEMPLARS

SIZES = {"rings": (300, 260), "grid": (400, 400), "stripes": (320, 320), "apples": (300, 300)}
case = sys.argv[1] if len(sys.argv) > 1 else "grid"
ex = EXEMPLARS[case]()
st = new_state(ex, Region.rectangle(*SIZES[case]), rng=1)
fill(st)
print(f"{case} cpu {time.process_time() - t0:.1f} wall {time.time() - w0:.1f} n {st.n}")

"""Cold first run (empty numba cache) of synth on the fidelity suite's exemplar of a class (argument; default two_sizes),
where s70h's density rule and s70p's thinning order act (integ39).

    NUMBA_CACHE_DIR=$(mktemp -d) PYTHONPATH=TREE/src:tests python benchmarks/integ39_cold_class.py two_sizes
"""

import sys
import time

from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize

t0, c0 = time.perf_counter(), time.process_time()
cls = sys.argv[1] if len(sys.argv) > 1 else "two_sizes"
ex = fidelity_suite().make_exemplar(cls, rng=1)
x0, y0, x1, y1 = ex.region.bounds
out = synthesize(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1)
print(f"{cls} cpu {time.process_time() - c0:.1f} wall {time.perf_counter() - t0:.1f} n {len(out)}", file=sys.stdout)

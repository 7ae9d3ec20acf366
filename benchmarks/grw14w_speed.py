"""Helper grw14w: grow speed (elements per CPU s) on --harder three_sizes h12s7 at 3.5x, seeds
1-2 (rows DISC_RINGED changes; every other exemplar's pair gaps are unchanged).

Measured 17:06 UTC, alternating trees in one session under load: d6d394e 1811, 1724 / 1795,
1822 el/CPU s; grw14w 1577, 1576 / 1477, 1219 (median ratio about 0.85: placements refused
by the gap).

    PYTHONPATH=TREE/src python benchmarks/grw14w_speed.py
"""

import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

import strew
from strew import Region
from strew.grow import grow

mk = _harder_suite()
ex = mk.make_exemplar("three_sizes", rng=7, **HARDER["three_sizes"][12])
x0, y0, x1, y1 = ex.region.bounds
grow(ex, region=Region.rectangle(60, 60), rng=1)  # warm-up
res = []
for seed in (1, 2):
    t = time.process_time()
    out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    dt = time.process_time() - t
    res.append((seed, len(out), round(dt, 2), round(len(out) / dt)))
print(strew.__file__, res)

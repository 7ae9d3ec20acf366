"""Helper g36t: test_grow_gvar14g's case (two_sizes rng 8, ratio 0.6, 40:120, 3.5x), its
share of stones whose nearest pebble is farther than the exemplar's farthest, the hole
pass's fills and the lone-larger swaps.

    SEED=1 PYTHONPATH=src python benchmarks/g36t_pebbles.py
"""
import os
import sys

sys.path.insert(0, "tests")

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

import strew.grow._growth as G
import strew.grow._void_holes as vh
from strew import Region
from strew.grow import grow

log = {"fill": [], "swap": []}
o_fill, o_swap = vh.fill_void_holes, G.swap_lone_larger


def fill(g, *a, **k):
    n = o_fill(g, *a, **k)
    log["fill"].append(n)
    return n


def swap(g, *a, **k):
    n = o_swap(g, *a, **k)
    log["swap"].append(n)
    return n


G.fill_void_holes, G.swap_lone_larger = fill, swap


def s2p(arr, region):
    st = arr.xy[arr.kind == arr.kinds.index("stone")]
    pb = arr.xy[arr.kind == arr.kinds.index("pebble")]
    d = cKDTree(pb).query(st)[0]
    return d[d <= region.distance_to_boundary(st)]


ex = fidelity_suite().make_exemplar("two_sizes", rng=8, ratio=0.6, n_large=40, n_small=120)
far = float(s2p(ex, ex.region).max())
x0, y0, x1, y1 = ex.region.bounds
region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
out = grow(ex, region=region, rng=int(os.environ.get("SEED", 1)))
d = s2p(out, region)
print("share", float(np.mean(d > far)), "n", len(out), "stones", int((out.kind == 0).sum()), "fills", log["fill"], "swaps", log["swap"],
      "reach", vh.small_fill.__name__)

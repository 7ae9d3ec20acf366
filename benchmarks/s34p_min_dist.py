"""Helper s34p: the learned closest approach (Prepared.min_dist) per kind pair against the exemplar's nn quantiles.

    PYTHONPATH=src python benchmarks/s34p_min_dist.py two_sizes:9:24 three_sizes:6:24
"""
import sys
sys.path.insert(0, "benchmarks")
import numpy as np
from grow_variants import _harder_suite
from synth_variants import _harder
from strew import Region
from strew.synth import new_state
from scipy.spatial import cKDTree
for spec in sys.argv[1:]:
    name, i, v = spec.split(":")
    ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
    st = new_state(ex, Region.rectangle(100, 100), rng=1)
    p = st.prep
    print(spec, "counts", np.bincount(p.skind), "rc", [round(float(np.median(p.rc[p.skind == k])), 2) for k in range(p.skind.max() + 1)])
    print(" min_dist\n", np.round(p.min_dist, 2))
    for a in range(p.skind.max() + 1):
        for b in range(p.skind.max() + 1):
            pa, pb = p.pos[p.skind == a], p.pos[p.skind == b]
            d = cKDTree(pb).query(pa, k=2 if a == b else 1)[0]
            d = d[:, 1] if a == b else d
            print(f"  nn[{a}>{b}] quantiles 0,.1,.5: {np.round(np.quantile(d, [0, .1, .5]), 1)}  rc sum med {np.median(p.rc[p.skind==a])+np.median(p.rc[p.skind==b]):.1f}")

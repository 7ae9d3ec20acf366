"""Helper g26s: which exemplar references (sub ids, §5.4) the output elements that miss
the exemplar's lattice pattern (the judge's regularity) copy, fixed mode; and each
reference ring's largest slot deviation from the ring-average diagonal offsets.

    PYTHONPATH=src python benchmarks/g26s_refs.py [CLASS:LABEL=scales:p2s18] [SEED=1]
"""
import collections
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite
from fresh17_rows import exemplar

from strew import Region, _fidelity
from strew.grow import _growth, grow
from strew.grow._objects import ELEMENT

spec = sys.argv[1] if len(sys.argv) > 1 else "scales:p2s18"
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
cls, label = spec.split(":")
ex = exemplar(fidelity_suite(), cls, label)
G = {}
oi = _growth._Grower.__init__


def init(self, *a, **k):
    oi(self, *a, **k)
    G["g"] = self


_growth._Grower.__init__ = init
x0, y0, x1, y1 = ex.region.bounds
out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
g = G["g"]
els = [i for i in range(len(g.xy)) if g.state[i] == ELEMENT]
sub = np.array([int(g.sub[i]) for i in els])
calls = []
orig = _fidelity._lattice_match


def spy(sm, tree, s, template):
    calls.append((sm, tree, s, template))
    return orig(sm, tree, s, template)


_fidelity._lattice_match = spy
rep = _fidelity.fidelity(ex, out, eq5=False, local=False)
sm, tree, s, tpl = calls[-1]
import shapely

edge = shapely.distance(sm.region.boundary, shapely.points(sm.xy))
inn = np.flatnonzero((edge >= _fidelity.LATTICE_REACH * s + 0.5 * s) & shapely.contains_xy(sm.window, sm.xy[:, 0], sm.xy[:, 1]))
ok = orig(sm, tree, s, tpl)[inn]
assert len(sm.xy) == len(els)
# (the output keeps the grower's element order: match positions to be sure)
from scipy.spatial import cKDTree

gxy = np.array([g.xy[i] for i in els])
d, idx = cKDTree(gxy).query(sm.xy)
assert d.max() < 1e-6
use = collections.Counter(sub[idx[inn]].tolist())
miss = collections.Counter(sub[idx[inn[~ok]]].tolist())
# the exemplar's references: largest diagonal-slot deviation from the mean offsets
exy = ex.xy
t = cKDTree(exy)
dd, jj = t.query(exy, k=5)
print(f"{spec} seed {seed}: regularity {rep.metrics['regularity'].result:.4f}; interior {len(inn)}, miss {int((~ok).sum())}")
print("   reference: uses / misses (miss share) / its 4 nearest distances, for the references with the most misses")
for r, m in miss.most_common(12):
    print(f"   ref {r}: {use[r]} / {m} ({m / use[r]:.2f}) nn {np.round(dd[r, 1:], 1).tolist()}")
sh = np.array([miss[r] / use[r] for r in use if use[r] >= 10])
print(f"   references used 10+ times: {len(sh)}, miss share q50/q90/max {np.round(np.quantile(sh, [0.5, 0.9, 1.0]), 3).tolist()}")

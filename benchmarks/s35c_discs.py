"""s35c: the discs of a clusters row's exemplar: depth in the exemplar domain / r-bar, interior or not, k-coherence set, disc steps in the neighbourhoods.

    PYTHONPATH=src:benchmarks python benchmarks/s35c_discs.py p2s25
"""
import sys, numpy as np, shapely
sys.path.insert(0,'benchmarks')
from _runner import fidelity_suite
import fresh17_rows
from strew.synth import _prepare as P
mk = fidelity_suite()
label = sys.argv[1] if len(sys.argv)>1 else 'p2s25'
ex = fresh17_rows.exemplar(mk, 'clusters', label)
pos = np.asarray(ex.xy)
a = P._spacing(pos); poly, hp = P.exemplar_domain(pos, a)
print('domain bounds', poly.bounds, 'spacing', a)
depth = shapely.distance(poly.exterior, shapely.points(pos))
from strew.synth import prepare
from strew.synth._api import as_selection
prep = P.prepare(as_selection(ex))
big = np.flatnonzero(prep.size_class==1)
for i in big: print(i, pos[i].round(1), 'depth', round(depth[i],1), 'rbar', round(prep.rbar[i],1), 'ratio', round(depth[i]/prep.rbar[i],2), 'inner', i in prep.interior[0], 'co', prep.co[i])
for e in (24, 39, 8):
    seg = slice(prep.nb_ptr[e], prep.nb_ptr[e+1])
    o = prep.nb_off[seg]; c = prep.size_class[prep.nb_idx[seg]]
    print(e, 'disc steps', o[c==1].round(1), 'n dots', (c==0).sum(), 'dist', np.hypot(*o[c==1].T).round(1))
# nn of discs
from scipy.spatial import cKDTree
d,_ = cKDTree(pos[big]).query(pos[big], k=3); print('disc nn', d[:,1].round(1), d[:,2].round(1))
fp = prep.free_off[prep.free_ptr[24]:prep.free_ptr[25]]; print('free of 24', len(fp), np.hypot(*fp.T).round(0))

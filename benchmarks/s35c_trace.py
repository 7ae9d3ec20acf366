"""s35c: trace synth growth on a clusters row at 3.5x (per iteration: iteration, n, horizon, live free-space points, failed points) and the elements each post pass adds.

    PYTHONPATH=src:benchmarks python benchmarks/s35c_trace.py p2s25 1
"""
import sys, numpy as np
sys.path.insert(0,'benchmarks')
from _runner import fidelity_suite
import fresh17_rows
from strew import Region
from strew.synth._api import new_state
from strew.synth import _grow as G
mk = fidelity_suite()
label = sys.argv[1] if len(sys.argv)>1 else 'p2s25'
ex = fresh17_rows.exemplar(mk, 'clusters', label)
region = Region.rectangle(1050, 1050)
st = new_state(ex, region, rng=int(sys.argv[2]) if len(sys.argv)>2 else 1)
p = st.prep
log=[]
orec = G._record
def rec(state, t0, sk):
    log.append((state.iterations, state.n, int(state.horizon.sum()), int(state._alive.sum()), int((state._fails>0).sum())))
    return orec(state, t0, sk)
G._record = rec
# wrap post passes
import strew.synth._displace as D, strew.synth._shell as S, strew.synth._farmix as F
for mod, name in ((G,'_complete_anchor_rings'),(G,'fill_room'),(G,'fill_holes'),(D,'fill_displaced'),(S,'fill_beside_largest')):
    f = getattr(mod,name)
    def w(*a, _f=f, _n=name, **k):
        n0 = a[0].n; r = _f(*a, **k); print('pass', _n, n0, '->', a[0].n); return r
    setattr(mod,name,w)
G.fill(st)
for l in log[::max(1,len(log)//40)]: print(l)
print(log[-1])
is_disc = p.size_class[st.src]==1
pos = st.pos
print('n', st.n, 'discs', is_disc.sum())
# free points of discs: 
print('free_r', np.unique(np.round(p.free_r,1)), 'free_ptr sizes', np.diff(p.free_ptr)[p.size_class==1], np.diff(p.free_ptr)[p.size_class==0][:10])

"""g27g: trace the largest frame-from-field deviation (degrees, modulo 60) of the hexagonal
lattice grown along the 90 degree field over 30 x 20 spacings (tests/grow/test_grow_flow_turn.py)
after each pass of the growth and the flow passes after it.

    PYTHONPATH=src:tests python benchmarks/g27g_frame_trace.py
"""
import numpy as np, functools
from strew import Region
from strew.grow import grow
import strew.grow._growth as G
from strew_testing import fidelity_suite
SP=12.0
w,h=30*SP,20*SP
def field(p):
    a=np.radians(90.0)*np.clip(np.asarray(p)[:,0]/w,0,1)
    return np.c_[np.cos(a),np.sin(a)]
def dev(st):
    idx=np.asarray(st.order)
    xy=st.pos[idx]; v=field(xy)
    d=np.degrees(np.mod(st.rot[idx]-np.arctan2(v[:,1],v[:,0]),np.pi/3)); d=np.minimum(d,60-d)
    k=int(np.argmax(d)); return d.max(), k, idx[k], xy[k], len(idx)
def wrap(name):
    f=getattr(G,name)
    @functools.wraps(f)
    def g(st,*a,**k):
        r=f(st,*a,**k)
        print(name, k.get('band',''), k.get('push',''), 'max dev %.3f at order#%d id %d xy %s n %d'%dev(st), flush=True)
        return r
    setattr(G,name,g)
for n in ['insert_stretched','reshape_shear','close_holes','relax_network','densify','regrow_sheared','close_gaps']:
    wrap(n)
orig=G._Growth.settle if hasattr(G,'_Growth') else None
S=G._Grower.settle
def settle(st):
    print('before settle','max dev %.3f at order#%d id %d xy %s n %d'%dev(st))
    S(st)
    print('after settle','max dev %.3f at order#%d id %d xy %s n %d'%dev(st), flush=True)
G._Grower.settle=settle
ex=fidelity_suite().make_exemplar("hex_lattice",nx=8,ny=8)
out=grow(ex,region=Region.rectangle(w,h),mode="flow",flow=field,rng=1)
v=field(out.xy); d=np.degrees(np.mod(out.rotation-np.arctan2(v[:,1],v[:,0]),np.pi/3)); d=np.minimum(d,60-d)
k=np.argmax(d); print('final', d.max(), k, out.xy[k], len(out.xy))

"""g42f: how often flow_respace fires on one held-out case and how long the runs of
front seeds it finds are (per side; bincount of lengths 0..4).

    [NEAR=1] PYTHONPATH=src python benchmarks/g42f_respace_runs.py hex:16:2,14

NEAR=1 sets GrowParams.flow_respace_near (only on the g42f experiment patch).
"""
import sys, math, numpy as np
sys.path.insert(0,'benchmarks')
import grow as gb
from strew import Region
from strew.fields import flow_field
from strew.grow import grow, _growth
G=_growth._Grower
import os
if os.environ.get("NEAR"):
    _oi=_growth.GrowParams.__init__
    def _i(self,*a,**k):
        _oi(self,*a,**k); object.__setattr__(self,"flow_respace_near",True)
    _growth.GrowParams.__init__=_i
stats=dict(calls=0,cand=0,runs=[],steps=[],fired=0,L=[])
orig_run=G._seed_run
orig=G.flow_respace
def fr(self,s):
    stats['calls']+=1
    r=orig(self,s)
    stats['fired']+=int(r)
    return r
G.flow_respace=fr
def sr(self,start,ux,uy,k,taken):
    out=orig_run(self,start,ux,uy,k,taken)
    stats['runs'].append(len(out))
    return out
G._seed_run=sr
kind,n,st=sys.argv[1].split(':')
n=int(n)
if kind=='scales':
    from scipy.spatial import cKDTree
    ex=gb._suite_exemplar("scales"); sp=float(np.median(cKDTree(ex.xy).query(ex.xy,7)[0][:,1:]))
else:
    ex=gb._suite_exemplar("hex_lattice",nx=8,ny=8); sp=12.0
th=np.linspace(0,np.pi/2,30); aa=n*sp
region=Region.rectangle(aa,aa)
af=flow_field([np.c_[r*np.cos(th),r*np.sin(th)] for r in (aa/3,aa*5/6)])
s=None if st=='c' else tuple(float(v)*sp for v in st.split(','))
out=grow(ex,region=region,mode='flow',flow=af,rng=1,start=s)
inner=region.distance_to_boundary(out.xy)>2*sp
print(sys.argv[1],'six',gb.hex_share(out.xy,sp,inner),'calls',stats['calls'],'fired',stats['fired'],'runs',np.bincount(stats['runs']) if stats['runs'] else None)

"""g42f: the interior sites that miss the six share (benchmarks/grow.py hex_share) on
held-out flow cases, split by (neighbours within 1.15, within 0.85) and Delaunay degree;
the Delaunay-six ones by their longest bond (spacings).

    PYTHONPATH=src python benchmarks/g42f_where.py "hex:16:2,14;scales:16:14,2"
"""
import sys, numpy as np
sys.path.insert(0,'benchmarks')
import grow as gb
from scipy.spatial import cKDTree, Delaunay
from strew import Region
from strew.fields import flow_field
from strew.grow import grow
for case in sys.argv[1].split(';'):
    kind,n,st=case.split(':'); n=int(n)
    if kind=='scales':
        ex=gb._suite_exemplar("scales"); sp=float(np.median(cKDTree(ex.xy).query(ex.xy,7)[0][:,1:]))
    else:
        ex=gb._suite_exemplar("hex_lattice",nx=8,ny=8); sp=12.0
    th=np.linspace(0,np.pi/2,30); aa=n*sp
    region=Region.rectangle(aa,aa)
    af=flow_field([np.c_[r*np.cos(th),r*np.sin(th)] for r in (aa/3,aa*5/6)])
    s=None if st=='c' else tuple(float(v)*sp for v in st.split(','))
    out=grow(ex,region=region,mode='flow',flow=af,rng=1,start=s)
    xy=out.xy; inner=region.distance_to_boundary(xy)>2*sp
    tree=cKDTree(xy)
    hi=np.array([len(tree.query_ball_point(p,1.15*sp))-1 for p in xy])
    lo=np.array([len(tree.query_ball_point(p,0.85*sp))-1 for p in xy])
    # Delaunay degree & longest delaunay bond
    tri=Delaunay(xy); ind,nb=tri.vertex_neighbor_vertices
    deg=np.diff(ind); mx=np.array([np.max(np.hypot(*(xy[nb[ind[i]:ind[i+1]]]-xy[i]).T)) for i in range(len(xy))])/sp
    bad=inner&~((hi==6)&(lo==0))
    print(case,'inner',inner.sum(),'bad',bad.sum(),'six',1-bad.sum()/inner.sum())
    print(' bad by (hi,lo):',dict(zip(*np.unique([f"{a},{b}" for a,b in zip(hi[bad],lo[bad])],return_counts=True))))
    print(' bad delaunay degree:',dict(zip(*np.unique(deg[bad],return_counts=True))))
    print(' bad with delaunay deg 6:',((deg==6)&bad).sum(),' their max bond (sp) q:',np.round(np.quantile(mx[(deg==6)&bad],[0,.25,.5,.75,1]),3) if ((deg==6)&bad).any() else None)
    import os; os.makedirs('/tmp/g42f', exist_ok=True)
    np.save(f'/tmp/g42f/out_{case.replace(":","_").replace(",","_")}.npy',xy)

"""g29f: the lattice's turn from the field (six-fold mean bond angle of each element's
neighbours within 0.85-1.15 spacing, minus the quarter circles' tangent) binned by the angle
from the start's radius, on growths saved by ``benchmarks/g29f_where.py --npz``.

    python benchmarks/g29f_orient.py benchmarks/results/g29f_r3_on.npz ...
"""
import numpy as np
from scipy.spatial import cKDTree
import sys
for f in sys.argv[1:]:
    d=np.load(f); xy=d['xy']; sp=float(d['sp']); aa=float(d['aa']); st=d['start']
    t=cKDTree(xy); dd,ii=t.query(xy,7)
    inner=(xy.min(1)>2*sp)&(xy.max(1)<aa-2*sp)
    phi=np.degrees(np.arctan2(xy[:,1],xy[:,0]))-45
    fa=np.arctan2(xy[:,1],xy[:,0])+np.pi/2
    mis=[]
    for k in range(len(xy)):
        v=xy[ii[k,1:]]-xy[k]; ok=(dd[k,1:]<1.15*sp)&(dd[k,1:]>0.85*sp)
        if ok.sum()<4: mis.append(np.nan); continue
        a=np.arctan2(v[ok,1],v[ok,0])
        z=np.exp(6j*(a-fa[k])).mean()
        mis.append(np.degrees(np.angle(z))/6)
    mis=np.array(mis)
    print(f)
    for lo,hi in [(-50,-30),(-30,-15),(-15,-5),(-5,5),(5,15),(15,30),(30,50)]:
        m=inner&(phi>=lo)&(phi<hi)&np.isfinite(mis)
        print(f"  phi {lo:4d}..{hi:3d}: lattice - field mean {np.mean(mis[m]):6.1f} deg  |p90| {np.percentile(abs(mis[m]),90):5.1f}  n {m.sum()}")

"""Who placed each element near the seams (issue 19.4, helper w28h): per bin of signed distance d / s to the
nearest inner border (negative: the finished side), each kind's count placed by the tile holding its centre / by
another tile (orn19m worlds' ``tile`` column against the tile holding the centre).

``python benchmarks/w28h_placer.py benchmarks/results/orn19m_TAG_sS_TT.npz [...]``
"""
import sys

import numpy as np
sys.path.insert(0,'benchmarks')
import orn19m_willow as W
from pathlib import Path
edges=np.arange(-3,3.01,0.5); nb=len(edges)-1
tot=None
for f in sys.argv[1:]:
    w=W._world(Path(f)); ins=w['inside']; kinds=w['kinds']
    b=np.clip(np.digitize(w['sd'],edges)-1,0,nb-1); near=w['d']<3
    c=np.zeros((nb,len(kinds),2))
    m=ins&near
    np.add.at(c,(b[m],w['kind'][m],w['other'][m].astype(int)),1)
    tot=c if tot is None else tot+c
print('bin   '+' '.join(f'{k:>12s}' for k in kinds)+'   (own/other placer)')
for i in range(nb):
    print(f'{edges[i]:+.1f} '+' '.join(f'{int(tot[i,k,0]):5d}/{int(tot[i,k,1]):<5d}' for k in range(len(kinds))))

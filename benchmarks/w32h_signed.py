"""Kept vines and twigs by signed distance d / s to the nearest inner border (negative: the
finished tile's side), pooled tiled / control (issue 19.4, helper w32h).

``python benchmarks/w32h_signed.py TILED:CTL,TILED:CTL [...]`` (orn19m worlds, seed 19, tiles 40-56).
"""
import sys, numpy as np
sys.path.insert(0,'benchmarks')
import orn19m_willow as W
from pathlib import Path
R=Path('benchmarks/results')
edges=np.array([-100,-6,-5,-4,-3,-2,-1,0,1,2,3,4,5,6,100.])
for pairs in [a.split(',') for a in sys.argv[1:]]:
  for kk in ('vine','twig'):
    A={'t':0,'c':0}
    for pair in pairs:
      t,c=pair.split(':')
      for T in (40,44,48,52,56):
        ft=R/f'orn19m_{t}_s19_T{T}.npz'; fc=R/f'orn19m_{c}_s19_T{T}.npz'
        if not ft.exists() or not fc.exists(): continue
        for lab,f in (('t',ft),('c',fc)):
            w=W._world(f); k=np.array(w['kinds'])[w['kind']]
            m=(k==kk)&w['inside']
            A[lab]=A[lab]+np.histogram(w['sd'][m],edges)[0]
    print(pairs[0].split(':')[0],kk,' '.join(f"[{edges[i]:g},{edges[i+1]:g}):{A['t'][i]}/{A['c'][i]}" for i in range(len(edges)-1)))

"""Ornament vase: in which square panels does the seed's vine deliver no flower at all
(issue 19.4: a tiled world's phase-0 tile is a square of T + 2 reach; at 313948f the
vase grew hooks only in every panel from 145 on, tiled world or not).

``python benchmarks/vas19s_seed_scan.py``: panels (0, 0)-(L, L), L = 40..300 step 5,
seed 1, the first 40 elements (the vines' phase comes first).
"""
import numpy as np, strew, shapely
from strew.ornament import grow_ornament
bad=[]
Ls=np.arange(40,301,5)
for L in Ls:
    a=grow_ornament('vase', strew.Region(shapely.box(0,0,L,L)), rng=1, max_elements=40)
    if 'lotus' not in a.kinds and 'peony' not in a.kinds: bad.append(int(L))
print(len(bad),'of',len(Ls),'square panels (0,0)-(L,L), L=40..300 step 5, grow no flower:',bad)

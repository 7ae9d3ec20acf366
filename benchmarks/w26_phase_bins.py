"""Elements of tile-48 vase worlds (benchmarks/hie15_make.py) by the phase of the tile
holding them (2 x 2 phases) and distance to the nearest tile line (bins 0-4-8-12-16-20-25),
summed over seeds (helper w26).

``python benchmarks/w26_phase_bins.py TAG,TAG,... SEED,SEED,...``
"""
import sys

import numpy as np

R='benchmarks/results/orn19m_%s.npz'
bins=[0,4,8,12,16,20,25]
for tag in sys.argv[1].split(','):
    tot=np.zeros((4,6),int)
    for s in sys.argv[2].split(','):
        d=np.load(R%f"{tag}_s{s}_T48"); x,y=np.asarray(d['x']),np.asarray(d['y'])
        i=np.clip((x//48).astype(int),0,3); j=np.clip((y//48).astype(int),0,3); ph=(j%2)*2+i%2
        dx=np.abs((x+24)%48-24); dy=np.abs((y+24)%48-24); dd=np.minimum(dx,dy)
        for p in range(4): tot[p]+=np.histogram(dd[ph==p],bins=bins)[0]
    print(tag, ' | '.join(f"ph{p} {tot[p].sum()} {tot[p].tolist()}" for p in range(4)))

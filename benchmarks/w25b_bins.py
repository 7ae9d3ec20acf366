"""Elements of vase worlds (benchmarks/hie15_make.py, tile 48) by distance to the nearest
tile line (bins 0-4-8-12-16-20-25), per tag and seed (helper w25b).

``python benchmarks/w25b_bins.py TAG,TAG,... SEED,SEED,...``
"""
import numpy as np, sys
R='benchmarks/results/orn19m_%s.npz'
for s in sys.argv[2].split(','):
    row=[]
    for tag in sys.argv[1].split(','):
        try: d=np.load(R%f"{tag}_s{s}_T48")
        except FileNotFoundError: continue
        x,y=np.asarray(d['x']),np.asarray(d['y'])
        dx=np.abs((x+24)%48-24); dy=np.abs((y+24)%48-24); dd=np.minimum(dx,dy)
        h=np.histogram(dd,bins=[0,4,8,12,16,20,25])[0]
        row.append(f"{tag}:{len(x)} {h.tolist()}")
    print(s,' | '.join(row))

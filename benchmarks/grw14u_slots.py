"""Helper grw14u: why the lone elements of a kind are lone (grow, fixed mode, --harder three_sizes).

At the end of the growth, for the elements of kind KIND beyond the reference's upper decile of
nearest-own-kind distances (strew.grow._lone_kin.kin_reach), what holds the own-kind slots of
their rings: an element within half the slot's distance (by kind), or none but one too close
for the reference (by kind), or nothing. At a2b29a1, h9s7 seed 1: 173 lone of 426; slots held
by large 50, medium 71, small 46; free but too close to a large 71; free 19. With the lone-kin pass (042e9e0): 133 lone of 459.

    PYTHONPATH=src python benchmarks/grw14u_slots.py 9 7 1,2 medium
"""
import collections
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

import strew.grow._lone_kin as K
from strew import Region
from strew.grow import _growth as G
from strew.grow import grow
from strew.grow._objects import ELEMENT

mk=_harder_suite()
i,v=map(int,sys.argv[1:3]); seeds=[int(s) for s in sys.argv[3].split(',')]; KA=sys.argv[4]
ex=mk.make_exemplar("three_sizes", rng=v, **HARDER["three_sizes"][i])
Gr=G._Grower; r0=Gr.result
def result(g, meta):
    from scipy.spatial import cKDTree
    a=list(ex.kinds).index(KA)
    q = K.kin_reach(g)[0]
    els=np.asarray([i for i in g.order if g.state[i]==ELEMENT])
    ia=els[g.kind[els]==a]; d=cKDTree(g.pos[ia]).query(g.pos[ia],k=2)[0][:,1]
    seen=d<=np.asarray(g.region.distance_to_boundary(g.pos[ia]))
    lone=ia[seen & (d>q[a])]
    print(f" q={q[a]:.1f} lone {len(lone)} of {seen.sum()}")
    C=collections.Counter()
    R=g.rings
    for s in lone.tolist():
        r=int(g.refslot[s]); n=int(R['n'][r]); th=float(g.frame[s]); c,sn=math.cos(th),math.sin(th); x,y=g.xy[s]
        for j in range(n):
            if int(R['kind'][r,j])!=a: continue
            rx,ry=R['rel'][r,j]; cx,cy=x+c*rx-sn*ry, y+sn*rx+c*ry
            nb=[o for o in g.near(cx,cy,0.5*math.hypot(rx,ry),(ELEMENT,)) if o!=s]
            if nb:
                o=min(nb,key=lambda o:(g.xy[o][0]-cx)**2+(g.xy[o][1]-cy)**2)
                C['occupied by '+ex.kinds[int(g.kind[o])]]+=1
            else:
                hit=[ex.kinds[int(g.kind[o])] for o in g.near(cx,cy,float(g.pair_close_max[a]),(ELEMENT,)) if o!=s and (g.xy[o][0]-cx)**2+(g.xy[o][1]-cy)**2<g.pair_close[a,g.kind[o]]**2]
                C['free; too close to '+str(sorted(set(hit)))]+=1
        C[f"lone with own-kind slots {sum(int(R['kind'][r,j])==a for j in range(n))}"]+=1
    for k,vv in sorted(C.items()): print("  ",k,vv)
    return r0(g,meta)
Gr.result=result
x0,y0,x1,y1=ex.region.bounds
for seed in seeds:
    out=grow(ex, region=Region.rectangle(3.5*(x1-x0),3.5*(y1-y0)), rng=seed)

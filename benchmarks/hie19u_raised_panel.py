"""hierarchy in a panel with every vines-phase goal raised (helper hie19u, issue 19.4):
``PYTHONPATH=TREE/src python benchmarks/hie19u_raised_panel.py [SIDE R]`` grows hierarchy in a
SIDE x SIDE panel (seed at the centre, rng 1) plain and with handed-over circles of radius R
(phase "vines") on a 5-unit grid (strew.ornament._engine._handed_over), and prints the vines'
count and chord (mean, median) and the kind counts of both."""
import sys, time
import numpy as np
import strew
from strew.ornament._engine import grow_elements
def chords(orn):
    out=[]
    for e in orn.elements:
        if e.type=='vine':
            p=e.proxy.point_at(np.array([0.0,1.0]))
            out.append(float(np.hypot(*(p[1]-p[0]))))
    return np.array(out)
L=float(sys.argv[1]) if len(sys.argv)>1 else 60.0
R=float(sys.argv[2]) if len(sys.argv)>2 else 20.0
reg=strew.Region.rectangle(L,L)
seeds=[[L/2,L/2]]
t=time.process_time()
plain=grow_elements("hierarchy",reg,seeds=seeds,rng=1)
t1=time.process_time()-t
grid=np.arange(0.0,L+1,5.0)
raised=grow_elements("hierarchy",reg,seeds=seeds,rng=1,_holes=[[x,y,R,"vines"] for x in grid for y in grid])
for name,o in (("plain",plain),("raised",raised)):
    c=chords(o)
    kinds={}
    for e in o.elements: kinds[e.type]=kinds.get(e.type,0)+1
    print(name, "vines",len(c),"chord mean %.2f median %.2f"%(c.mean(),np.median(c)), kinds)
print("cpu plain %.2f"%t1)

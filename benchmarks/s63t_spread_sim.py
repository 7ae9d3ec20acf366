"""Helper s63t: what ``_grow._top_spread``'s windows read (variance over mean of the count,
divided by ``_grow._window_dispersion``) on 20 independent uniform points in a unit frame and
on a hard-core pattern of 20 points (no two nearer than 0.16), over draws, for three window
sides: the reading's mean and its spread over frames.

    PYTHONPATH=src:benchmarks python benchmarks/s63t_spread_sim.py
"""
import numpy as np
rng=np.random.default_rng(0)
from strew.synth._grow import _window_dispersion as F0
def f(pts, side, k):
    cx,cy=np.meshgrid(np.linspace(0,1-side,k),np.linspace(0,1-side,k)); cx,cy=cx.ravel(),cy.ravel()
    c=((pts[None,:,0]>=cx[:,None])&(pts[None,:,0]<cx[:,None]+side)&(pts[None,:,1]>=cy[:,None])&(pts[None,:,1]<cy[:,None]+side)).sum(1)
    return c.var()/c.mean()
def hardcore(N, d):
    out=[]
    while len(out)<N:
        p=rng.uniform(0,1,2)
        if all(np.hypot(*(p-q))>=d for q in out): out.append(p)
    return np.array(out)
for side,k in ((0.5,21),(1/3,31),(0.25,41)):
    v=np.array([f(rng.uniform(0,1,(20,2)),side,k) for _ in range(200)])/F0(side,k)
    h=np.array([f(hardcore(20,0.16),side,k) for _ in range(100)])/F0(side,k)
    print(f"side {side:.2f} F0 {F0(side,k):.3f} uniform D mean {v.mean():.2f} sd {v.std():.2f}  hardcore(20,d=.16) D mean {h.mean():.2f} sd {h.std():.2f}")

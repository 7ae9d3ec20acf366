"""Helper seam17 (issue 13 point 2): two sizes at 50x, seed 3: the hole behind the failing
edge windows (0,7),(0,8) (empty_circle 1.451). Prints the synth state's elements within 45
of the hole's centre (921, 24) just before the output is made (after thin_orphans, grow()'s
last pass), with their exemplar radius, collision radius and birth iteration, then the
output's elements there: the elements whose outline crosses the region's edge are dropped
when the output is clipped (``SynthState.to_arrangement(clip=True)``), after every fill pass.

    python benchmarks/seam17_edge_hole.py
"""
import sys

import numpy as np

sys.path.insert(0,'benchmarks')
from _runner import fidelity_suite

import strew.synth._thin as T
from strew import Region
from strew.synth import synthesize

if '--quick' in sys.argv[1:]:
    print('seam17_edge_hole: skipped: a 50x canvas')
    sys.exit(0)
mk=fidelity_suite(); ex=mk.make_exemplar('two_sizes')
c=np.array([921.0,24.0])
x0,y0,x1,y1=ex.region.bounds; region=Region.rectangle(7.07*(x1-x0),7.07*(y1-y0))
print('radii', {k:s.radius for k,s in ex.shapes.items()})
f=T.thin_orphans
def w(state,since=0):
    r=f(state,since); prep=state.prep
    pos=state.pos; d=np.hypot(*(pos-c).T); near=np.flatnonzero(d<45)
    for i in near: print('  state el', np.round(pos[i],1), prep.kinds[prep.kind[state.src[i]]] if hasattr(prep,'kinds') else prep.kind[state.src[i]], 'r', round(float(prep.r[state.src[i]]),1), 'rc', round(float(prep.rc[state.src[i]]),1), 'd', round(d[i],1), 'born', state.born[i])
    return r
T.thin_orphans=w
out=synthesize(ex,region,rng=3,measure=False)
d=np.hypot(*(out.xy-c).T); print('final within 45:', [(np.round(out.xy[i],1).tolist(), out.kinds[out.kind[i]]) for i in np.flatnonzero(d<45)])

"""s35c: render a clusters row's exemplar and its synth output at 3.5x (discs red, dots blue) to /tmp/s35c_LABEL.png.

    PYTHONPATH=src:benchmarks python benchmarks/s35c_render.py p2s25 1
"""
import sys, numpy as np
sys.path.insert(0,'benchmarks')
from _runner import fidelity_suite
import fresh17_rows
from synth_variants import run
import matplotlib; matplotlib.use('Agg'); import matplotlib.pyplot as plt
mk = fidelity_suite()
label = sys.argv[1] if len(sys.argv)>1 else 'p2s25'
ex = fresh17_rows.exemplar(mk, 'clusters', label)
kn = np.asarray(ex.kind_names); print('exemplar', ex.region.bounds, len(kn), {k:int((kn==k).sum()) for k in set(kn)})
out,_ = run(ex, 3.5, int(sys.argv[2]) if len(sys.argv)>2 else 1, None)
ko = np.asarray(out.kind_names); print('out', out.region.bounds, len(ko), {k:int((ko==k).sum()) for k in set(ko)})
fig, ax = plt.subplots(1,2, figsize=(14,7))
for a, arr in zip(ax, (ex, out)):
    xy = np.asarray(arr.xy); k = np.asarray(arr.kind_names)
    for name, c in (('disc','r'),('dot','b')):
        a.scatter(xy[k==name,0], xy[k==name,1], s=4, c=c)
    x0,y0,x1,y1 = arr.region.bounds; a.plot([x0,x1,x1,x0,x0],[y0,y0,y1,y1,y0],'k-'); a.set_aspect('equal')
plt.savefig(f'/tmp/s35c_{label}.png', dpi=70)

"""Helper g35t: the hole pass's kind-reach gate, variants tried by monkeypatch on three_sizes h9s25.

    V=A|B ROW=three_sizes:9:25 SEED=1 PYTHONPATH=src python benchmarks/g35t_variants.py

A: other kinds asked within max(reach, hole radius); B: every reach widened by the fit's
reach (fit_reach x l_short). (D2, committed as ``_askable``, and E, no other kind asked,
were the same with the reach dropped; see benchmarks/results/g35t_findings.txt.) Run on a
tree without ``_askable`` (its parent) for the figures there.
"""
import sys, os, numpy as np
sys.argv=['x']; sys.path.insert(0,'benchmarks')
import g35t_probe as P
from strew.grow._objects import ELEMENT
V = os.environ['V']
def near(g, cx, cy, reach):
    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT])
    d = np.hypot(g.pos[els,0]-cx, g.pos[els,1]-cy)
    r = d.min(); k = g.kind[els]
    mv = g.p.fit_reach * g.l_short
    a = 0
    for b in np.flatnonzero(np.isfinite(reach)):
        db = d[k == b].min() if (k == b).any() else np.inf
        if V == 'A': lim = max(reach[b], r * 1.0001) if b != a else reach[b]
        elif V == 'B': lim = reach[b] + mv
        else: lim = reach[b]
        if db > lim: return False
    return True
P.o_near = near
seed = int(os.environ.get('SEED', 1))
ex,out=P.metrics(os.environ.get('ROW','three_sizes:9:25'),seed)
print(V, 'seed', seed, 'n', len(out), [(c['near_fail'], c['refused'], c['made']) for c in P.calls])

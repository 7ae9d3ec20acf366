"""Helper syn13y (issue 13 point 1): one three sizes --harder set at 3.5x, per synth seed: fidelity failures,
counts per kind (per exemplar area) and metric density ratios, which synth pass placed each kind, and the
signed decile errors of chosen nn metrics against the exemplar (in units of s).

    python benchmarks/syn13y_diag.py HARDER_INDEX SEEDS [VARIANT] ["a>b;c>d"] [save]

Figures (d6d394e, ``7 1,2 7``): h7s7 nn[small>medium] 0.0568/0.0516 (tol 0.0509), signed error q70/q80/q90
+0.06/+0.11/+0.25 s, medium 0.90-0.92x density; with fill_beside_far_small 0.0469/0.0428.
"""
import sys

import numpy as np

sys.path.insert(0, 'benchmarks')
from grow_variants import HARDER, _harder_suite

import strew._fidelity as F
import strew.synth._displace as DP
import strew.synth._farmix as FM
import strew.synth._grow as G
import strew.synth._pebbles as PB
import strew.synth._shell as SH
import strew.synth._swap as SW
from strew import Region
from strew.synth import synthesize

hidx = int(sys.argv[1]); seeds = [int(x) for x in sys.argv[2].split(',')]; var = int(sys.argv[3]) if len(sys.argv) > 3 else 7
pairs = sys.argv[4].split(';') if len(sys.argv) > 4 else ['small>medium', 'medium>medium', 'small>small', 'small>large']
mk = _harder_suite()
ex = mk.make_exemplar('three_sizes', rng=var, **HARDER['three_sizes'][hidx])
cap = {}
orig = F._discrepancies
def disc(a, b, kinds, s, **kw):
    if 'res' not in cap: cap['res'] = (a, b, kinds, s)
    return orig(a, b, kinds, s, **kw)
F._discrepancies = disc
# pass tagging
tags = {}
def wrap(mod, name):
    f = getattr(mod, name)
    def w(state, *a, **k):
        before = set(map(tuple, np.round(state.pos[:state.n], 6)))
        r = f(state, *a, **k)
        after = np.round(state.pos[:state.n], 6)
        for p in map(tuple, after):
            if p not in before: tags[p] = name
        return r
    setattr(mod, name, w)
for mod, name in [(SH, 'fill_beside_largest'), (SH, 'fill_beside_far_small'), (FM, 'trade_far_small'), (G, 'fill_room'), (G, 'fill_holes'), (DP, 'fill_displaced'), (PB, 'fill_partners'), (SW, 'fill_swapped'), (G, '_complete_anchor_rings')]:
    wrap(mod, name)
x0, y0, x1, y1 = ex.region.bounds
print('exemplar counts', {k: int(np.sum(ex.kind == i)) for i, k in enumerate(ex.kinds)})
for seed in seeds:
    cap.clear(); tags.clear()
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = synthesize(ex, region, rng=seed, measure=False)
    rep = F.fidelity(ex, out, eq5=False, local=False)
    a, b, kinds, s = cap['res']
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    ratio = 3.5**2
    cnt = {k: int(np.sum(out.kind == i)) for i, k in enumerate(out.kinds)}
    print(f'seed {seed} n={len(out)} faithful={rep.faithful} {fails}')
    print('  counts/12.25', {k: round(v / ratio, 1) for k, v in cnt.items()}, 'density ratio', [round(a.density[i] / b.density[i], 3) for i in range(len(kinds))])
    # pass tags by kind
    xy = np.round(out.xy, 6)
    t = [tags.get(tuple(p), 'growth') for p in xy]
    from collections import Counter
    for i, k in enumerate(out.kinds):
        c = Counter(tt for tt, kk in zip(t, out.kind) if kk == i)
        print('  placed', k, dict(c))
    for pr in pairs:
        ka, kb = pr.split('>')
        i, j = kinds.index(ka), kinds.index(kb)
        name = f'nn[{pr}]'
        print(f'  {name} value {rep.metrics[name].value:.4f} tol {rep.metrics[name].tolerance:.4f}')
        print('    ex deciles ', np.round(b.nn[i, j] / s, 3))
        print('    signed err ', np.round((a.nn[i, j] - b.nn[i, j]) / s, 3))
    if len(sys.argv) > 5:
        import pickle; pickle.dump((ex, out, t), open(f'syn13y_out_h{hidx}_s{seed}.pkl', 'wb'))

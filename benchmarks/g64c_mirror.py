"""Helper g64c: counterfactual for next step 1 of g64c_notes.md (src untouched, by wrapping
``_clusters.hub_reference``): where the interior hubs' rings together leave a bearing gap wider than §4's skew
angle (2/3 pi), each interior ring also gets the point reflection x_i - (x_j - x_i) of each neighbour j, as a
virtual hub (not interior), unless it lies within the hubs' least distance of a ring member; grow (fixed) on
``--varied`` clusters p2s37 as ``grow_variants.run``.

    PYTHONPATH=src:benchmarks python benchmarks/g64c_mirror.py clusters:p2s37 1-6
"""
import math
import sys
from types import SimpleNamespace

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import strew.grow._clusters as C
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run
from strew.grow._analysis import Reference
from strew.metrics import fidelity

_hr = C.hub_reference
INFO = []


def _bear(xy, i, js):
    return sorted(math.atan2(*(xy[j] - xy[i])[::-1]) % (2 * math.pi) for j in js)


def mirrored(hx):
    ref = _hr(hx)
    if ref is None:
        return ref
    xy = hx.xy
    inter = np.flatnonzero(ref.interior)
    allb = sorted(b for i in inter for b in _bear(xy, i, ref.rings[i]))
    gap = max(np.diff(allb + [allb[0] + 2 * math.pi]))
    if gap <= 2 * math.pi / 3:
        return ref
    least = float(min(np.hypot(*(xy[a] - xy[b])) for a, b in ref.edges))
    new_xy = [p for p in xy]
    rings = [list(r) for r in ref.rings]
    edges = [tuple(e) for e in np.asarray(ref.edges).tolist()]
    for i in inter:
        for j in list(ref.rings[i]):
            v = 2 * xy[i] - xy[j]
            if min(np.hypot(*(new_xy[k] - v)) for k in rings[i]) < least:
                continue
            new_xy.append(v)
            k = len(new_xy) - 1
            rings[i].append(k)
            rings.append(np.array([i]))
            edges.append((int(i), k))
        P = np.asarray(new_xy)
        rings[i] = np.array(sorted(rings[i], key=lambda k: math.atan2(P[k][1] - P[i][1], P[k][0] - P[i][0])))
    P = np.asarray(new_xy)
    n = len(P)
    m = n - len(xy)
    ex2 = type(hx)(hx.shapes, np.r_[hx.kind, np.full(m, hx.kind[0])], P[:, 0], P[:, 1], np.r_[hx.rotation, np.zeros(m)], np.r_[hx.scale, np.ones(m)], region=hx.region)
    interior = np.r_[ref.interior, np.zeros(m, bool)]
    rings = [np.asarray(r, dtype=np.int64) for r in rings]
    INFO.append(f"    mirrored: gap {math.degrees(gap):.0f} deg > 120; {m} virtual hubs; rings of interior hubs "
                f"{[(int(i), [round(math.degrees(b)) for b in _bear(P, i, rings[i])]) for i in inter]}")
    return Reference(ex2, np.asarray(sorted(edges), dtype=np.int64), interior, rings, ref.mean_edge, ref.shortest_edge)


C.hub_reference = mirrored
mk = fidelity_suite()
cls, label = sys.argv[1].split(":")
ex = exemplar(mk, cls, label)
for seed in _variants.ints(sys.argv[2]):
    INFO.clear()
    out, sc = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
    rep = fidelity(ex, out, eq5=False, local=False)
    shown = [f"{k}={m.value:.3g}/{m.tolerance:.3g}{'' if m.passed else '!'}" for k, m in rep.metrics.items() if m.applicable and (k.startswith("g[") or k.startswith("density") or k.startswith("empty") or not m.passed)]
    xy = np.c_[out.x, out.y]
    print(f" seed {seed} mirrored rings: {'pass' if rep.faithful else 'FAIL'} n={len(out)} scale {sc:.2f} x+y {xy.sum(1).min():.0f}-{xy.sum(1).max():.0f}  {' '.join(shown)}", flush=True)
    if seed == 1:
        print(INFO[0])
        from s64c_deciles import render
        render(out, "benchmarks/results/g64c_p2s37_mirror_s1.png")

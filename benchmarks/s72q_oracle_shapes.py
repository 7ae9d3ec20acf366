"""Helper s72q: the three_sizes generator at the output's size (side x SCALE, counts x SCALE^2) with the
EXEMPLAR'S OWN stone shapes (drawn from the exemplar's rng, as make.three_sizes does) and fresh positions
(rng 5000 + d), judged against the exemplar as the audit (eq5, local off). The plain oracle
(svar13i_oracle.py) draws new shapes for d >= 1, so its draws mix shape and placement noise.

    PYTHONPATH=src:benchmarks python benchmarks/s72q_oracle_shapes.py three_sizes:p4s46 DRAWS [SCALE] [--kind 1]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite

import shapely
from scipy.spatial import cKDTree

from strew.metrics import fidelity


def deciles(p, geom):
    d = cKDTree(p).query(p, k=2)[0][:, 1]
    return np.quantile(d[d <= shapely.distance(geom.boundary, shapely.points(p))], np.arange(1, 10) / 10), d

mk = fidelity_suite()
spec, draws = sys.argv[1], int(sys.argv[2])
scale = float(sys.argv[3]) if len(sys.argv) > 3 and not sys.argv[3].startswith("-") else 3.5
K = int(sys.argv[sys.argv.index("--kind") + 1]) if "--kind" in sys.argv else 1
cls, label = spec.split(":")
i, _, v = label[1:].partition("s")
kw = dict((_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)])
ex = mk.make_exemplar(cls, rng=int(v), **kw)
size, small, ratios, counts, gap = 210.0 * scale, 2.6, (1.0, 2.0, 4.0), kw["counts"], 1.2
ratios = kw.get("ratios", ratios)
small = kw.get("small", small)
names = ("small", "medium", "large")
colours = ("#d8c9a3", "#a59a86", "#6f6a62")
vals = []
for d in range(draws):
    g0 = np.random.default_rng(int(v))
    shapes = {nm: mk.Shape.polygon(mk._stone(g0, small * rt, vertices=7 + 2 * j), style={"fill": col}) for j, (nm, rt, col) in enumerate(zip(names, ratios, colours))}
    g = np.random.default_rng(5000 + d)
    pl, rl = np.zeros((0, 2)), np.zeros(0)
    p_all, k_all, s_all = [], [], []
    for idx in (2, 1, 0):
        n = int(round(counts[idx] * scale * scale))
        sc = g.uniform(0.9, 1.1, n)
        p, r = mk._dart(g, (0, 0, size, size), shapes[names[idx]].radius * sc, n, gap=gap, placed=(pl, rl), tries=40000)
        pl, rl = np.r_[pl, p], np.r_[rl, r]
        p_all.append(p)
        k_all.append(np.full(len(p), idx))
        s_all.append(sc[: len(p)])
    p = np.concatenate(p_all)
    arr = mk._finish("three_sizes", shapes, np.concatenate(k_all), p, g.uniform(0, 2 * np.pi, len(p)), np.concatenate(s_all), box=(0, 0, size, size), params={})
    rep = fidelity(ex, arr, eq5=False, local=False)
    key = f"nn[{ex.kinds[K]}>{ex.kinds[K]}]"
    m = rep.metrics[key]
    vals.append(m.value)
    fails = [f"{k}={mm.value:.3g}/{mm.tolerance:.3g}" for k, mm in rep.metrics.items() if mm.applicable and not mm.passed]
    q, _ = deciles(np.asarray(arr.xy)[arr.kind == K], arr.region.geometry)
    print(f"draw {d} n={len(arr)} counts {np.bincount(arr.kind)} {'pass' if rep.faithful else 'FAIL'} {key} {m.value:.3f}/{m.tolerance:.3f} {' '.join(fails)} deciles {np.round(q, 1)}", flush=True)
print(f"{spec} scale {scale}: {key} median {np.median(vals):.3f}, passes {sum(x <= m.tolerance for x in vals)}/{len(vals)}")

"""Helper g42s: nn[a>b] deciles (Hanisch, in units of s) of the exemplar, grow (3.5x) and the
class generator at 3.5x:  PYTHONPATH=src:benchmarks python benchmarks/g42s_nn_probe.py stripes:v29 0 0 1,2
"""
import sys, numpy as np
sys.path.insert(0, "benchmarks")
from fresh17_rows import exemplar
from _runner import fidelity_suite
from grow_variants import run
from types import SimpleNamespace
from scipy.spatial import cKDTree
import svar13i_oracle as O
mk = fidelity_suite()
D = np.arange(1, 10) / 10
def dec(arr, a, b, s):
    xy = np.asarray(arr.xy); k = np.asarray(arr.kind)
    A, B = xy[k == a], xy[k == b]
    d, _ = cKDTree(B).query(A, k=2 if a == b else 1)
    d = d[:, 1] if a == b else d
    e = arr.region.distance_to_boundary(A)
    d = d[d < e]
    return np.quantile(d, D) / s, len(d)
spec, a, b = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
cls, lab = spec.split(":")
ex = exemplar(mk, cls, lab)
s = np.median(cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1])
print(ex.kinds, len(ex), np.bincount(np.asarray(ex.kind)))
q0, n0 = dec(ex, a, b, s); print("ex    ", n0, q0.round(3))
for seed in [int(x) for x in sys.argv[4].split(",")]:
    out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
    q, n = dec(out, a, b, s); print("grow", seed, n, q.round(3), "diff", (q - q0).round(3), "mad", np.mean(np.abs(q - q0)).round(4), np.bincount(np.asarray(out.kind)))
kw = dict(ex.meta.get("params", {})) if hasattr(ex, "meta") else {}
big = O.big_params(cls, kw, 3.5)
for v in (1001, 1002):
    orc = mk.make_exemplar(cls, rng=v, **big)
    q, n = dec(orc, a, b, s); print("oracle", v, n, q.round(3), "diff", (q - q0).round(3), "mad", np.mean(np.abs(q - q0)).round(4), np.bincount(np.asarray(orc.kind)))

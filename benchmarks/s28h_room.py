"""Helper s28h (issue 13 point 1): room left for one more element of a kind, exemplar against synth output.

For the exemplar (inner frame, eroded by MARGIN) and for a saved output (``/tmp/ssz/...json``, from
``ssz_row.py``; eroded by 20), the share of area where a disc of the kind's median bounding radius plus
GAP/2 fits between the elements' bounding discs (each grown by GAP/2: the generator's dart test), and the
number of such extra discs a greedy throw fits, per 1e4 units of area; next to each kind's count per 1e4.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s28h_room.py CLASS:H:V OUT.json[,OUT.json...] [--kind small] [--gap 1.2]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from scipy.spatial import cKDTree
from synth_variants import _harder

from strew.io import load

args = [a for a in sys.argv[1:] if not a.startswith("--")]
kind = sys.argv[sys.argv.index("--kind") + 1] if "--kind" in sys.argv else "small"
gap = float(sys.argv[sys.argv.index("--gap") + 1]) if "--gap" in sys.argv else 1.2
args = [a for a in args if a not in (kind, str(gap))]
name, i, v = args[0].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])


def room(arr, margin, rk, rng=np.random.default_rng(0)):
    xy = np.asarray(arr.xy, float)
    r = np.asarray(arr.radii, float) + gap / 2
    kn = np.asarray(arr.kind_names)
    g = arr.region.geometry.buffer(-margin)
    x0, y0, x1, y1 = g.bounds
    gx, gy = np.meshgrid(np.arange(x0, x1, 0.4), np.arange(y0, y1, 0.4))
    p = np.c_[gx.ravel(), gy.ravel()]
    p = p[shapely.contains_xy(g, p[:, 0], p[:, 1])]
    tree = cKDTree(xy)
    rmax = r.max()
    ok = np.ones(len(p), bool)
    for j, nb in enumerate(tree.query_ball_point(p, rk + rmax)):
        if nb and np.any(np.hypot(*(xy[nb] - p[j]).T) < rk + r[nb]):
            ok[j] = False
    free = p[ok]
    order = rng.permutation(len(free))
    ft = cKDTree(free)
    dead = np.zeros(len(free), bool)
    kept = 0
    for j in order:
        if dead[j]:
            continue
        kept += 1
        dead[ft.query_ball_point(free[j], 2 * rk)] = True
    cnt = {k: round(float(np.sum((kn == k) & shapely.contains_xy(g, xy[:, 0], xy[:, 1])) / g.area * 1e4), 2) for k in sorted(set(kn))}
    return ok.mean(), kept / g.area * 1e4, cnt


kn = np.asarray(ex.kind_names)
rk = float(np.median(np.asarray(ex.radii)[kn == kind])) + gap / 2
m = 2 * float(np.asarray(ex.radii).max())
a, n, c = room(ex, 0.0, rk)
print(f"{name} h{i}s{v} kind {kind} rk {rk:.2f}: exemplar room share {a:.4f} extra/1e4 {n:.2f} counts {c}")
for f in args[1].split(","):
    out = load(f)
    a, n, c = room(out, 20.0, rk)
    print(f"  {f.rsplit('/', 1)[-1]}: room share {a:.4f} extra/1e4 {n:.2f} counts {c}")

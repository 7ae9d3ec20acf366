"""Helper g33s: sparse_voids' apple-free frame band in the exemplar and grow's apple holes.

    PYTHONPATH=src python benchmarks/g33s_holes.py CLASS:LABEL SEED

Prints the exemplar's hidden (void) elements by distance from the frame (the generator's
dart keeps apple centres >= spacing/2 from the frame, voids only >= void_spacing/2), and for
grow's result (as the audit) the apple holes: Voronoi vertices of the apples farther than
the exemplar's largest interior apple empty circle, how many voids each holds within its
radius, their distance from the frame, and the share of the result's voids that lie in holes.
"""
import os
import sys
from types import SimpleNamespace

import numpy as np
from scipy.spatial import Voronoi, cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402
from grow_variants import run  # noqa: E402


def hide(a):
    v = a.columns.get("void")
    return np.zeros(len(a), bool) if v is None else np.asarray(v, bool)


def frame_d(xy, b):
    x0, y0, x1, y1 = b
    return np.minimum.reduce([xy[:, 0] - x0, x1 - xy[:, 0], xy[:, 1] - y0, y1 - xy[:, 1]])


def holes(a, rmax):
    h = hide(a)
    ap, vd = a.xy[~h], a.xy[h]
    b = a.region.bounds
    V = Voronoi(ap).vertices
    V = V[frame_d(V, b) > 0]
    r, _ = cKDTree(ap).query(V)
    big = r > rmax
    tv = cKDTree(vd)
    inside = np.zeros(len(vd), bool)
    for c, rr in zip(V[big], r[big]):
        inside[tv.query_ball_point(c, rr - 1e-9)] = True
    return V, r, big, inside


def main():
    spec, seed = sys.argv[1], int(sys.argv[2])
    cls, label = spec.split(":")
    ex = exemplar(fidelity_suite(), cls, label)
    h = hide(ex)
    p = ex.meta.get("params") or {}
    db = frame_d(ex.xy, ex.region.bounds)
    print(f"{spec} params {p}")
    print(f"  exemplar apples {int((~h).sum())} min frame dist {db[~h].min():.1f}; voids {int(h.sum())}, of them within {db[~h].min():.0f} of the frame: {int((db[h] < db[~h].min()).sum())}")
    print(f"  exemplar voids/apple: all {h.sum() / (~h).sum():.2f}; interior (> {db[~h].min():.0f} from frame) {(h & (db >= db[~h].min())).sum() / (~h).sum():.2f}")
    s = float(np.median(cKDTree(ex.xy[~h]).query(ex.xy[~h], 2)[0][:, 1]))
    Ve, re, _, _ = holes(ex, np.inf)
    inner = frame_d(Ve, ex.region.bounds) > db[~h].min()
    rmax = float(re[inner].max())
    print(f"  exemplar s={s:.1f}; largest apple empty circle with centre beyond the apple band: {rmax:.1f} ({rmax / s:.2f} s); overall {re.max():.1f}")
    out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
    V, r, big, inside = holes(out, rmax)
    ho = hide(out)
    dV = frame_d(V, out.region.bounds)
    print(f"  grow seed {seed}: apples {int((~ho).sum())} voids {int(ho.sum())} ({ho.sum() / (~ho).sum():.2f}/apple)")
    print(f"  apple-Voronoi vertices beyond {rmax:.1f}: {int(big.sum())}/{len(V)}; of them > 40 from the frame {int((big & (dV > 40)).sum())}; radius max {r.max():.1f}")
    print(f"  voids inside those holes: {int(inside.sum())} ({inside.mean():.2%} of the voids)")
    vo = out.xy[ho]
    if inside.any():
        ap = out.xy[~ho]
        dv = cKDTree(ap).query(vo)[0]
        print(f"  void distance to nearest apple (quantiles .5 .9 .99 max): result {np.round(np.quantile(dv, [.5, .9, .99, 1]), 1)}", end="")
        de = cKDTree(ex.xy[~h]).query(ex.xy[h])[0]
        di = de[db[h] >= db[~h].min()]
        print(f"  exemplar all {np.round(np.quantile(de, [.5, .9, .99, 1]), 1)} interior {np.round(np.quantile(di, [.5, .9, .99, 1]), 1)}")
        # placement order of the voids far from apples
        far = dv > np.quantile(di, 0.99) if len(di) else dv > 0
        idx = np.flatnonzero(ho)[far]
        print(f"  voids farther from an apple than the exemplar interior's 99%: {int(far.sum())}; their placement ranks (quartiles) {np.round(np.quantile(idx / len(out), [.25, .5, .75]), 2) if len(idx) else []}; frame dist quartiles {np.round(np.quantile(frame_d(vo[far], out.region.bounds), [.25, .5, .75]), 0) if len(idx) else []}")


if __name__ == "__main__":
    main()

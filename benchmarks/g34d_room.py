"""Helper g34d: is an exemplar saturated? Room left for one more element, per exemplar.

    PYTHONPATH=src python benchmarks/g34d_room.py CLASS[,CLASS...] VARIANT_SEEDS

For each label (v, p0..pN as ``--varied`` names them) and variant seed: the least centre
distance d_min between visible elements, and the share of the interior Delaunay
circumcircles (centre at least d_min inside the frame) whose radius is at least d_min:
room for one more element at the exemplar's own least distance (0 for a saturated
dart throw or a lattice). Also the nearest-neighbour CV.
"""
import os
import sys

import numpy as np
from scipy.spatial import Delaunay, cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants  # noqa: E402
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402


def room(ex):
    xy = np.asarray(ex.xy, dtype=float)
    v = ex.columns.get("void")
    if v is not None:
        xy = xy[~np.asarray(v, dtype=bool)]
    nn = cKDTree(xy).query(xy, k=2)[0][:, 1]
    dmin = float(nn.min())
    t = Delaunay(xy)
    a, b, c = (xy[t.simplices[:, i]] for i in range(3))
    d = 2 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    ok = np.abs(d) > 1e-12
    a2, b2, c2 = (np.sum(p * p, axis=1) for p in (a, b, c))
    ux = (a2 * (b[:, 1] - c[:, 1]) + b2 * (c[:, 1] - a[:, 1]) + c2 * (a[:, 1] - b[:, 1]))[ok] / d[ok]
    uy = (a2 * (c[:, 0] - b[:, 0]) + b2 * (a[:, 0] - c[:, 0]) + c2 * (b[:, 0] - a[:, 0]))[ok] / d[ok]
    r = np.hypot(ux - a[ok, 0], uy - a[ok, 1])
    x0, y0, x1, y1 = ex.region.bounds
    inside = np.minimum.reduce([ux - x0, x1 - ux, uy - y0, y1 - uy]) >= dmin
    share = float(np.mean(r[inside] >= dmin)) if inside.any() else 0.0
    return dmin, share, float(nn.std() / nn.mean()), len(xy)


def free_share(ex, step=0.25):
    """Share of the exemplar's interior where its smallest element fits with the least
    outline gap (bounding discs) the exemplar has between any two elements."""
    xy = np.asarray(ex.xy, dtype=float)
    rad = np.array([float(ex.shapes[k].radius) for k in ex.kinds])[np.asarray(ex.kind)] * np.asarray(ex.scale, dtype=float)
    v = ex.columns.get("void")
    if v is not None:
        keep = ~np.asarray(v, dtype=bool)
        xy, rad = xy[keep], rad[keep]
    t = cKDTree(xy)
    d, q = t.query(xy, k=min(8, len(xy)))
    gap = d[:, 1:] - rad[:, None] - rad[q[:, 1:]]
    gmin = max(float(gap.min()), 0.0)
    need = float(rad.min()) + gmin
    x0, y0, x1, y1 = ex.region.bounds
    m = float(2 * rad.max() + gmin)
    h = step * need
    gx, gy = np.meshgrid(np.arange(x0 + m, x1 - m, h), np.arange(y0 + m, y1 - m, h))
    pts = np.c_[gx.ravel(), gy.ravel()]
    dd, qq = t.query(pts, k=min(8, len(xy)))
    free = np.min(dd - rad[qq], axis=1) >= need
    return float(free.mean()), need


def main():
    classes, seeds = sys.argv[1].split(","), _variants.ints(sys.argv[2])
    mk = fidelity_suite()
    for cls in classes:
        sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
        for lab in ["v"] + [f"p{i}s" for i in range(len(sets))]:
            row = []
            for s in seeds:
                ex = exemplar(mk, cls, f"{lab}{s}")
                dmin, share, cv, n = room(ex)
                fs, need = free_share(ex)
                row.append(f"{share:.2f}/{fs:.3f}")
            print(f"  {cls:12s} {lab:4s} room share (seeds {seeds}): {' '.join(row)}  (last: n={n} dmin={dmin:.1f} nn cv {cv:.2f})", flush=True)


if __name__ == "__main__":
    main()


def free_share_outline(ex, step=0.25):
    """As :func:`free_share` with the true outlines: the smallest kind's equal-area disc
    with the least outline gap between any two (visible) elements."""
    import shapely

    g = np.asarray(ex.geometry)
    v = ex.columns.get("void")
    keep = np.ones(len(ex), dtype=bool) if v is None else ~np.asarray(v, dtype=bool)
    g = g[keep]
    tree = shapely.STRtree(g)
    rad = np.asarray(ex.radii, dtype=float)[keep]
    a, b = tree.query(g, predicate="dwithin", distance=float(4 * rad.max()))
    m = a < b
    gmin = max(float(shapely.distance(g[a[m]], g[b[m]]).min()), 0.0)
    area = shapely.area(g)
    r_eq = float(np.sqrt(area.min() / np.pi))
    need = r_eq + gmin
    x0, y0, x1, y1 = ex.region.bounds
    mg = float(2 * rad.max() + gmin)
    h = step * need
    gx, gy = np.meshgrid(np.arange(x0 + mg, x1 - mg, h), np.arange(y0 + mg, y1 - mg, h))
    pts = shapely.points(gx.ravel(), gy.ravel())
    near = tree.query(pts, predicate="dwithin", distance=need)
    blocked = np.zeros(len(pts), dtype=bool)
    blocked[near[0]] = True
    return float(1 - blocked.mean()), need

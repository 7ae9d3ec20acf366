"""flow14v: where the worst held-out flow cases (issue 14 point 2) keep their non-six
sites: the interior sites failing the six-neighbour test grouped by distance to the
region's edge, to the start, and by the field's bend there (|grad theta| x spacing,
theta the field's angle; a lattice row bent over radius R has R / spacing rows per
radian); with ``benchmarks/grow.py``'s ``lattice_defects`` and ``defect_classes``.

    PYTHONPATH=src python benchmarks/flow14v_where.py [--json F] [--cases hex:24:22,2,...]
"""
import argparse
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import grow as gb  # noqa: E402

from strew import Region  # noqa: E402
from strew.fields import flow_field  # noqa: E402
from strew.grow import grow  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--json", default="")
ap.add_argument("--cases", default="hex:24:22,2;hex:16:14,2;hex:20:18,2;scales:16:14,2;hex:24:c")
a = ap.parse_args()


def exemplar(kind):
    if kind == "scales":
        from scipy.spatial import cKDTree

        ex = gb._suite_exemplar("scales")
        return ex, float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
    return gb._suite_exemplar("hex_lattice", nx=8, ny=8), 12.0


def bend_at(flow, pts, h):
    """|grad theta| at pts (central differences of the doubled angle, step h)."""
    def z2(p):
        v = np.asarray(flow(p), dtype=float)
        z = (v[:, 0] + 1j * v[:, 1]) / np.maximum(np.hypot(v[:, 0], v[:, 1]), 1e-300)
        return z * z
    z = z2(pts)
    gx = (z2(pts + [h, 0]) - z2(pts - [h, 0])) / (2 * h)
    gy = (z2(pts + [0, h]) - z2(pts - [0, h])) / (2 * h)
    return np.hypot(np.imag(np.conj(z) * gx) / 2, np.imag(np.conj(z) * gy) / 2)


th = np.linspace(0, np.pi / 2, 30)
res = {}
for case in a.cases.split(";"):
    kind, n, st = case.split(":")
    n = int(n)
    ex, sp = exemplar(kind)
    aa = n * sp
    region = Region.rectangle(aa, aa)
    af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
    s = None if st == "c" else tuple(float(v) * sp for v in st.split(","))
    out = grow(ex, region=region, mode="flow", flow=af, rng=1, start=s)
    xy = out.xy
    inner = region.distance_to_boundary(xy) > 2 * sp
    x0, y0, x1, y1 = region.bounds
    grid = np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0].reshape(2, -1).T
    d = gb.lattice_defects(xy, sp, inner, grid)
    c = gb.defect_classes(xy, sp, inner, region, grid, af)
    from scipy.spatial import cKDTree

    tree = cKDTree(xy)
    idx = np.flatnonzero(inner)
    hi = np.array([len(tree.query_ball_point(xy[i], 1.15 * sp)) - 1 for i in idx])
    lo = np.array([len(tree.query_ball_point(xy[i], 0.85 * sp)) - 1 for i in idx])
    bad = ~((hi == 6) & (lo == 0))
    kb = bend_at(af, xy[idx], sp / 4) * sp  # field's bend in radians per spacing
    edge = region.distance_to_boundary(xy[idx]) / sp
    s0 = np.array([aa / 2, aa / 2]) if s is None else np.array(s)
    dstart = np.hypot(*(xy[idx] - s0).T) / sp
    rad = np.hypot(*xy[idx].T) / sp  # distance to the arcs' centre (0, 0), spacings

    def split(v, edges, bad=bad):
        rows = []
        for lo_, hi_ in zip(edges[:-1], edges[1:]):
            m = (v >= lo_) & (v < hi_)
            rows.append([lo_, hi_, int(m.sum()), int((m & bad).sum()), round(float((m & bad).sum() / max(m.sum(), 1)), 3)])
        return rows

    r = dict(six=round(1 - float(bad.mean()), 4), n_bad=int(bad.sum()), **d)
    r.update({k: (round(v, 4) if isinstance(v, float) else v) for k, v in c.items()})
    r.update(by_edge=split(edge, [2, 3, 4, 6, 99]), by_start=split(dstart, [0, 4, 8, 12, 16, 99]),
             by_bend=split(kb, [0, 0.04, 0.06, 0.08, 0.12, 0.2, 9]), by_radius=split(rad, [0, 4, 8, 12, 16, 20, 99]),
             bend_q=[round(float(q), 4) for q in np.quantile(kb, [0.1, 0.5, 0.9])],
             bend_bad_mean=round(float(kb[bad].mean()), 4), bend_good_mean=round(float(kb[~bad].mean()), 4))
    res[case] = r
    print(case, json.dumps(r), flush=True)
    np.savez(f"/tmp/flow14v/{case.replace(':', '_').replace(',', '-')}.npz", xy=xy, inner=inner, bad_idx=idx[bad], kb=kb, idx=idx)
if a.json:
    json.dump(res, open(a.json, "w"), indent=1)

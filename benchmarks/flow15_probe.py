"""flow15: the held-out flow cases' worst sheared patch (issue 14 point 2): per regrow
attempt (``_flow_regrow``) the patch's size, where it lies (distance to the arcs' centre
(0, 0) in spacings), the field's bend there (|grad theta| x spacing), its width across
the field, the rows a lattice bent along it needs (k w^2 / (2 spacing)), and the six
share before / after the attempt; the final six share and elements turned > 12 deg from
the field (the band test's count).

    PYTHONPATH=src python benchmarks/flow15_probe.py [--cases hex:16:14,2;...] [--turns 1.0] [--json F]
"""
import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import grow as gb

from strew import Region
from strew.fields import flow_field
from strew.grow import _flow_regrow as fr
from strew.grow import grow
from strew.grow._flow_net import _six_share
from strew.grow._flow_retry import interior_score

ap = argparse.ArgumentParser()
ap.add_argument("--json", default="")
ap.add_argument("--cases", default="hex:16:14,2;hex:16:2,14;hex:16:c")
ap.add_argument("--turns", default="")
ap.add_argument("--rng", type=int, default=1)
a = ap.parse_args()
if a.turns:
    fr.REGROW_TURNS = tuple(float(v) for v in a.turns.split(","))



def exemplar(kind):
    if kind == "scales":
        from scipy.spatial import cKDTree

        ex = gb._suite_exemplar("scales")
        return ex, float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
    return gb._suite_exemplar("hex_lattice", nx=8, ny=8), 12.0


def bend_at(flow, pts, h):
    """|grad theta| at pts (central differences of the doubled angle, step h), as
    flow14v_where's."""
    def z2(p):
        v = np.asarray(flow(p), dtype=float)
        z = (v[:, 0] + 1j * v[:, 1]) / np.maximum(np.hypot(v[:, 0], v[:, 1]), 1e-300)
        return z * z
    gx = (z2(pts + [h, 0]) - z2(pts - [h, 0])) / (2 * h)
    gy = (z2(pts + [0, h]) - z2(pts - [0, h])) / (2 * h)
    z = z2(pts)
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
    log = []
    orig = fr._regrow

    def rec(g, patch, target, rep, orig=orig, log=log, af=af, sp=sp):
        xy = g.pos[patch]
        k = bend_at(af, xy, sp / 4) * sp
        r = np.hypot(*xy.T) / sp
        v = np.asarray(af(xy.mean(0)[None]), float)[0]
        nrm = np.array([-v[1], v[0]]) / np.hypot(*v)
        w = float(np.ptp(xy @ nrm)) / sp
        sh0, far0 = _six_share(g), interior_score(g)[1]
        orig(g, patch, target, rep)
        e = dict(size=len(patch), r=[round(float(r.min()), 2), round(float(r.max()), 2)], k_mean=round(float(k.mean()), 4),
                 w_across=round(w, 2), rows_need=round(float(k.mean()) * w * w / 2, 2), share0=round(sh0, 4), share1=round(_six_share(g), 4), far0=far0, far1=interior_score(g)[1],
                 n_after=len(g.order))
        log.append(e)

    fr._regrow = rec
    t0 = time.process_time()
    out = grow(ex, region=region, mode="flow", flow=af, rng=a.rng, start=s)
    dt = time.process_time() - t0
    fr._regrow = orig
    inner = region.distance_to_boundary(out.xy) > 2 * sp
    x0, y0, x1, y1 = region.bounds
    grid = np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0].reshape(2, -1).T
    d = gb.lattice_defects(out.xy, sp, inner, grid)
    v = af(out.xy)
    dd = np.degrees(np.mod(out.rotation - np.arctan2(v[:, 1], v[:, 0]), np.pi / 3))
    off = np.minimum(dd, 60 - dd)
    r = dict(six=round(gb.hex_share(out.xy, sp, inner), 4), n=len(out), off12=int((off > 12).sum()), off_mean=round(float(off.mean()), 2), cpu=round(dt, 1), attempts=log, **d)
    res[case] = r
    print(case, json.dumps(r), flush=True)
    np.savez(f"/tmp/flow15/{case.replace(':', '_').replace(',', '-')}.npz", xy=out.xy, rot=out.rotation)
if a.json:
    json.dump(res, open(a.json, "w"), indent=1)

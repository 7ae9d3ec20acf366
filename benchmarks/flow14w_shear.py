"""flow14w: why the worst held-out flow cases (issue 14 point 2) keep one sheared patch,
and why no pass after the growth repairs it. Per case (``kind:n:start`` as
``benchmarks/flow14v_where.py``):

- ``stages``: the interior six share (``benchmarks/grow.py``'s ``hex_share``), holes
  and largest defect group after the growth alone (the passes after it off), after
  the refills (holes, network and band passes off), after the stretch insertions, and
  with every pass (the default);
- ``birth``: the interior bonds of the growth alone at 1.15-1.4 spacings, their length
  when the later of their two elements was placed (a growth stopped there with
  ``count``), and how many steps apart their two elements were placed;
- ``families``: the interior Delaunay bonds (under 1.4 spacings) of the full output by
  direction against the field (0, 60, 120 degrees): mean length and share over 1.15;
- ``lag``: the lattice's six-fold bond phase and each element's rotation less the
  field's angle (degrees, wrapped to +-30), at six and non-six interior sites, and the
  share of elements turned more than 9.5 degrees (the frame's limit
  ``flow_max_turn`` is 10);
- ``shear``: each band ``_flow_shear.reshape_shear`` fits (free elements; gap points
  before/after; six sites before/after; elements moved: 0 = sent back);
- ``densify``: each round of ``_flow_densify.densify`` ("c" the fit's closest pair and
  the new point's nearest element in spacings, then "P" placed / "p" no room; a round
  with no "P" after its "c" was not tried: a pair nearer than ``flow_densify_close``);
- ``--variants``: the six share with GrowParams changed, e.g. ``mt15`` (the frame's
  limit 15 degrees), ``bend25``/``bend100`` (``flow_bend``), ``w10`` (shear window 1).

    PYTHONPATH=src python benchmarks/flow14w_shear.py [--json F] [--cases ...] [--variants mt15,...]
"""
import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import grow as gb

import strew.grow._flow_densify as fd
import strew.grow._flow_shear as fs
from strew import Region
from strew.fields import flow_field
from strew.grow import analyze
from strew.grow._growth import GrowParams, grow_reference

ap = argparse.ArgumentParser()
ap.add_argument("--json", default="")
ap.add_argument("--cases", default="hex:24:22,2;hex:20:18,2;hex:16:14,2;scales:16:14,2;hex:24:c")
ap.add_argument("--variants", default="")
a = ap.parse_args()

STAGES = {
    "grow": dict(flow_fill_min=None, flow_close_min=None, flow_hole_min=None),
    "refill": dict(flow_hole_min=None),
    "stretch": dict(flow_shear_min=None, flow_net_rounds=None),
    "full": dict(),
}
VARIANTS = {
    "mt15": dict(flow_max_turn=math.pi / 12), "mt5": dict(flow_max_turn=math.pi / 36),
    "bend25": dict(flow_bend=0.25), "bend100": dict(flow_bend=1.0), "w10": dict(flow_shear_window=1.0),
    "dmin60": dict(flow_densify_min=0.60),
}

# the passes' logs
LOG: dict[str, list] = {"shear": [], "densify": []}
_band, _six, _far, _fit, _put = fs._reshape_band, fs._six, fs._far, fd._fit, fd._put


def band(g, els, fb, src, dst, off, gap=0.7):
    rec = dict(free=int(fb.sum()), far=[], six=[])

    def six(g_, sites):
        v = _six(g_, sites)
        rec["six"].append(v)
        return v

    def far(g_, grid, r):
        v = _far(g_, grid, r)
        rec["far"].append(int(v.sum()))
        return v

    fs._six, fs._far = six, far
    try:
        rec["moved"] = _band(g, els, fb, src, dst, off, gap)
    finally:
        fs._six, fs._far = _six, _far
    LOG["shear"].append(rec)
    return rec["moved"]


def fit(g, pts0, cs, held):
    from scipy.spatial import cKDTree

    pts = _fit(g, pts0, cs, held)
    n = len(pts0)
    t = cKDTree(pts[:n])
    LOG["densify"].append("c%.2f/%.2f" % (t.query(pts[:n][~held], 2)[0][:, 1].min() / g.l, t.query(pts[n : n + 1])[0][0] / g.l))
    return pts


def put(g, x, y):
    r = _put(g, x, y)
    LOG["densify"].append("P" if r else "p")
    return r


fs._reshape_band, fd._fit, fd._put = band, fit, put


def exemplar(kind):
    from scipy.spatial import cKDTree

    if kind == "scales":
        ex = gb._suite_exemplar("scales")
        return ex, float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
    return gb._suite_exemplar("hex_lattice", nx=8, ny=8), 12.0


def delaunay_bonds(xy, sp):
    from scipy.spatial import Delaunay

    s = Delaunay(xy).simplices
    e = np.unique(np.sort(np.r_[s[:, [0, 1]], s[:, [1, 2]], s[:, [0, 2]]], axis=1), axis=0)
    ln = np.hypot(*(xy[e[:, 1]] - xy[e[:, 0]]).T) / sp
    return e[ln < 1.4], ln[ln < 1.4]


def six_ok(xy, sp):
    from scipy.spatial import cKDTree

    t = cKDTree(xy)
    hi = np.asarray(t.query_ball_point(xy, 1.15 * sp, return_length=True)) - 1
    lo = np.asarray(t.query_ball_point(xy, 0.85 * sp, return_length=True)) - 1
    return (hi == 6) & (lo == 0)


th = np.linspace(0, np.pi / 2, 30)
res = {}
for case in a.cases.split(";"):
    kind, n, st = case.split(":")
    n = int(n)
    ex, sp = exemplar(kind)
    ref = analyze(ex)
    aa = n * sp
    region = Region.rectangle(aa, aa)
    af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
    s = None if st == "c" else tuple(float(v) * sp for v in st.split(","))
    x0, y0, x1, y1 = region.bounds
    grid = np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0].reshape(2, -1).T

    def run(ref=ref, region=region, af=af, s=s, **kw):
        return grow_reference(ref, GrowParams(region=region, mode="flow", flow=af, start=s, **kw), rng=1)

    def row(out, region=region, sp=sp, grid=grid):
        inner = region.distance_to_boundary(out.xy) > 2 * sp
        d = gb.lattice_defects(out.xy, sp, inner, grid)
        return dict(n=len(out), six=round(gb.hex_share(out.xy, sp, inner), 4), holes=d["holes"], largest=d["largest_defect_group"])

    r: dict = {"stages": {}}
    outs = {}
    for stg, kw in STAGES.items():
        LOG["shear"].clear()
        LOG["densify"].clear()
        outs[stg] = run(**kw)
        r["stages"][stg] = row(outs[stg])
        if stg == "full":
            r["shear"] = list(LOG["shear"])
            r["densify"] = " ".join(LOG["densify"])
    # stretched bonds at birth (the growth alone: its output's order is the placement order)
    xy = outs["grow"].xy
    e, ln = delaunay_bonds(xy, sp)
    mid = (xy[e[:, 0]] + xy[e[:, 1]]) / 2
    inner_b = region.distance_to_boundary(mid) > 2 * sp
    hot = inner_b & (ln > 1.15)
    born = e.max(1)
    then, cuts = [], sorted({int(c) for c in np.quantile(born[hot], [0.25, 0.5, 0.75, 1.0])}) if hot.any() else []
    for c in cuts:
        snap = run(count=c + 1, **STAGES["grow"]).xy
        m = hot & (born > (cuts[cuts.index(c) - 1] if cuts.index(c) else -1)) & (born <= c)
        then += (np.hypot(*(snap[e[m, 1]] - snap[e[m, 0]]).T) / sp).tolist()
    then = np.asarray(then)
    r["birth"] = dict(stretched=int(hot.sum()), len_final_mean=round(float(ln[hot].mean()), 3) if hot.any() else None,
                      len_at_birth_mean=round(float(then.mean()), 3) if len(then) else None,
                      share_over_115_at_birth=round(float((then > 1.15).mean()), 3) if len(then) else None,
                      order_gap_q=[float(v) for v in np.quantile((e[:, 1] - e[:, 0])[hot], [0.1, 0.5, 0.9])] if hot.any() else None,
                      order_gap_all_q=[float(v) for v in np.quantile((e[:, 1] - e[:, 0])[inner_b], [0.1, 0.5, 0.9])])
    # bond families and the lattice's lag, full output
    out = outs["full"]
    xy = out.xy
    e, ln = delaunay_bonds(xy, sp)
    d = xy[e[:, 1]] - xy[e[:, 0]]
    mid = (xy[e[:, 0]] + xy[e[:, 1]]) / 2
    inner_b = region.distance_to_boundary(mid) > 2 * sp
    v = np.asarray(af(mid), dtype=float)
    rel = np.degrees(np.mod(np.arctan2(d[:, 1], d[:, 0]) - np.arctan2(v[:, 1], v[:, 0]), np.pi))
    fam = np.round(rel / 60).astype(int) % 3
    r["families"] = {str(60 * k): dict(n=int((inner_b & (fam == k)).sum()), mean=round(float(ln[inner_b & (fam == k)].mean()), 3),
                                       over_115=round(float((ln[inner_b & (fam == k)] > 1.15).mean()), 3)) for k in range(3)}
    ang = np.arctan2(d[:, 1], d[:, 0])
    z = np.zeros(len(xy), complex)
    np.add.at(z, e[:, 0], np.exp(6j * ang))
    np.add.at(z, e[:, 1], np.exp(6j * ang))
    vf = np.asarray(af(xy), dtype=float)
    fa = np.arctan2(vf[:, 1], vf[:, 0])
    lat = np.degrees(np.angle(np.exp(6j * (np.angle(z) / 6 - fa))) / 6)
    rot = np.degrees(np.mod(out.rotation - fa + np.pi / 6, np.pi / 3) - np.pi / 6)
    ok = six_ok(xy, sp)
    inner = region.distance_to_boundary(xy) > 2 * sp
    r["lag"] = {nm: dict(n=int(m.sum()), lattice_mean=round(float(lat[m].mean()), 1), lattice_abs=round(float(np.abs(lat[m]).mean()), 1),
                         rotation_mean=round(float(rot[m].mean()), 1), at_limit=round(float((np.abs(rot[m]) > 9.5).mean()), 2))
                for nm, m in (("six", inner & ok), ("non_six", inner & ~ok))}
    r["variants"] = {vn: row(run(**VARIANTS[vn])) for vn in a.variants.split(",") if vn}
    res[case] = r
    print(case, json.dumps(r), flush=True)
if a.json:
    json.dump(res, open(a.json, "w"), indent=1)

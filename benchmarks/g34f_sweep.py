"""g34f: held-out flow cases (``benchmarks/flow14p_heldout.py``'s quarter circles) with
GrowParams fields set, printing per case the interior six share, holes, and the lattice's
turn from the field (``tests/grow/test_grow_flow_turn.py``'s bond misalignment: median and
90th percentile, degrees; the issue's target is about 12 / 18) and the element frames'
largest turn from the field (mod 60).

    PYTHONPATH=src python benchmarks/g34f_sweep.py [--cases hex:16:c;scales:16:2,2;...|n16|all] [--set NAME=V ...] [--json F]

``n16``: both exemplars over 16 spacings, all five starts; ``all``: the 30 cases.
"""

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))

import grow as gb  # noqa: E402

from strew import Region  # noqa: E402
from strew.fields import flow_field  # noqa: E402
from strew.grow import _growth  # noqa: E402
from strew.grow import grow  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--cases", default="n16")
ap.add_argument("--set", nargs="*", default=[])
ap.add_argument("--json", default="")
a = ap.parse_args()


def starts(n):
    return ["c", "2,2", f"{n - 2},{n - 2}", f"2,{n - 2}", f"{n - 2},2"]


if a.cases in ("n16", "all"):
    sizes = (16,) if a.cases == "n16" else (16, 20, 24)
    cases = [f"{k}:{n}:{s}" for k in ("hex", "scales") for n in sizes for s in starts(n)]
else:
    cases = a.cases.split(";")
over = {}
for kv in a.set:
    k, v = kv.split("=")
    over[k] = eval(v, {"inf": math.inf, "None": None, "pi": math.pi})
if over:
    orig_init = _growth.GrowParams.__init__

    def init(self, *args, **kw):
        orig_init(self, *args, **kw)
        for k, v in over.items():
            object.__setattr__(self, k, v)

    _growth.GrowParams.__init__ = init
    print("set GrowParams", over)

EX = {}


def exemplar(kind):
    if kind not in EX:
        if kind == "scales":
            ex = gb._suite_exemplar("scales")
            EX[kind] = ex, float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
        else:
            EX[kind] = gb._suite_exemplar("hex_lattice", nx=8, ny=8), 12.0
    return EX[kind]


def phase(pts, which, sp):
    t = cKDTree(pts)
    out = []
    for i in which:
        d = pts[[j for j in t.query_ball_point(pts[i], 1.15 * sp) if j != i]] - pts[i]
        out.append(np.exp(6j * np.arctan2(d[:, 1], d[:, 0])).sum())
    return np.angle(np.asarray(out)) / 6


res = {}
for case in cases:
    kind, n, st = case.split(":")
    n = int(n)
    ex, sp = exemplar(kind)
    aa = n * sp
    region = Region.rectangle(aa, aa)
    th = np.linspace(0, np.pi / 2, 30)
    af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
    s = None if st == "c" else tuple(float(v) * sp for v in st.split(","))
    t0 = time.process_time()
    out = grow(ex, region=region, mode="flow", flow=af, rng=1, start=s)
    dt = time.process_time() - t0
    xy = np.asarray(out.xy)
    inner = region.distance_to_boundary(xy) > 2 * sp
    x0, y0, x1, y1 = region.bounds
    grid = np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0].reshape(2, -1).T
    d = gb.lattice_defects(xy, sp, inner, grid)
    idx = np.flatnonzero(inner)
    e_in = np.flatnonzero(ex.region.distance_to_boundary(ex.xy) > 1.5 * sp)
    phi0 = np.angle(np.exp(6j * phase(np.asarray(ex.xy), e_in, sp)).sum()) / 6
    v = np.asarray(af(xy[idx]), dtype=float)
    mis = phase(xy, idx, sp) - phi0 - np.arctan2(v[:, 1], v[:, 0])
    mis = np.abs(np.degrees((mis + np.pi / 6) % (np.pi / 3) - np.pi / 6))
    vf = np.asarray(af(xy), dtype=float)
    fr = np.degrees(np.mod(np.asarray(out.rotation) - np.arctan2(vf[:, 1], vf[:, 0]), np.pi / 3))
    res[case] = dict(n=len(out), six=float(gb.hex_share(xy, sp, inner)), holes=int(d["holes"]), lat_med=float(np.median(mis)),
                     lat_p90=float(np.quantile(mis, 0.9)), frame_max=float(np.minimum(fr, 60 - fr)[inner].max()), cpu=dt)
    r = res[case]
    print(f"{case:16s} n {r['n']:4d} six {r['six']:.4f} holes {r['holes']} lattice med {r['lat_med']:5.1f} p90 {r['lat_p90']:5.1f}"
          f" frame max {r['frame_max']:5.1f} cpu {dt:.0f}", flush=True)
for kind in ("hex", "scales"):
    rs = [r for c, r in res.items() if c.startswith(kind + ":")]
    if rs:
        print(f"{kind}: cases {len(rs)} six mean {np.mean([r['six'] for r in rs]):.4f} holes {sum(r['holes'] for r in rs)}"
              f" lattice med {np.mean([r['lat_med'] for r in rs]):.1f} p90 {np.mean([r['lat_p90'] for r in rs]):.1f}"
              f" (cases with p90 <= 18: {sum(r['lat_p90'] <= 18 for r in rs)})")
if a.json:
    Path(a.json).write_text(json.dumps({"set": a.set, "rows": res}, indent=1))

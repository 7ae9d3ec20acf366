"""flow14x: six share of the worst held-out flow cases (issue 14 point 2) with GrowParams
changed: ``k=v`` pairs (floats; ``None``), after the growth alone and with every pass.

    PYTHONPATH=src python benchmarks/flow14x_screen.py [--cases ...] [--grow] [k=v ...]
"""
import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import grow as gb  # noqa: E402

from strew import Region  # noqa: E402
from strew.fields import flow_field  # noqa: E402
from strew.grow import analyze  # noqa: E402
from strew.grow._growth import GrowParams, grow_reference  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--cases", default="hex:24:22,2;hex:20:18,2;hex:16:14,2;scales:16:14,2;hex:24:c")
ap.add_argument("--grow", action="store_true", help="also the growth alone")
ap.add_argument("--json", default="")
ap.add_argument("kv", nargs="*")
a = ap.parse_args()
kw = {k: (None if v == "None" else float(v)) for k, v in (s.split("=") for s in a.kv)}


def exemplar(kind):
    from scipy.spatial import cKDTree

    if kind == "scales":
        ex = gb._suite_exemplar("scales")
        return ex, float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
    return gb._suite_exemplar("hex_lattice", nx=8, ny=8), 12.0


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
    r = {}
    stages = {"grow": dict(flow_fill_min=None, flow_close_min=None, flow_hole_min=None), "full": {}} if a.grow else {"full": {}}
    for stg, extra in stages.items():
        t0 = time.process_time()
        out = grow_reference(ref, GrowParams(region=region, mode="flow", flow=af, start=s, **kw, **extra), rng=1)
        dt = time.process_time() - t0
        inner = region.distance_to_boundary(out.xy) > 2 * sp
        d = gb.lattice_defects(out.xy, sp, inner, grid)
        r[stg] = dict(n=len(out), six=round(gb.hex_share(out.xy, sp, inner), 4), holes=d["holes"], cpu=round(dt, 1))
    res[case] = r
    print(case, json.dumps(r), flush=True)
print("SUM", round(sum(r["full"]["six"] for r in res.values()), 4))
if a.json:
    json.dump(dict(kw={k: v for k, v in kw.items()}, cases=res), open(a.json, "w"), indent=1)

"""g25f: held-out flow cases (flow14p_heldout's, as flow17_screen.py) with grow
parameters set (``--param NAME=V``, passed to ``grow``) and the growth seed chosen
(``--rng``), constants of ``_flow_regrow`` or of another ``strew.grow`` module
(``--set [MODULE.]NAME=V``), for screening (issue 14 point 2); also the elements across the region's edge and the
lattice's turn from the field (``misalign_deg_p90`` of ``benchmarks/grow.py``).

    PYTHONPATH=src python benchmarks/g25f_screen.py [--cases all|hex|scales|hex:16:2,14;...] [--param NAME=V ...] [--rng 1] [--json F]
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

ap = argparse.ArgumentParser()
ap.add_argument("--json", default="")
ap.add_argument("--cases", default="hex:16:2,14;scales:16:2,2")
ap.add_argument("--set", nargs="*", default=[])
ap.add_argument("--param", nargs="*", default=[])
ap.add_argument("--rng", type=int, default=1)
a = ap.parse_args()
for kv in a.set:
    k, v = kv.split("=")
    mod = fr
    if "." in k:  # MODULE.NAME: a constant of strew.grow.MODULE
        import importlib

        m, k = k.split(".")
        mod = importlib.import_module("strew.grow." + m)
    setattr(mod, k, type(getattr(mod, k))(eval(v)))
    print("set", mod.__name__, k, getattr(mod, k))
PARAMS = {k: eval(v) for k, v in (kv.split("=") for kv in a.param)}
print("params", PARAMS, "rng", a.rng)
EX = {}


def exemplar(kind):
    if kind not in EX:
        if kind == "scales":
            from scipy.spatial import cKDTree

            ex = gb._suite_exemplar("scales")
            EX[kind] = ex, float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
        else:
            EX[kind] = gb._suite_exemplar("hex_lattice", nx=8, ny=8), 12.0
    return EX[kind]


cases = a.cases.split(";")
if a.cases in ("all", "hex", "scales"):
    kinds = ["hex", "scales"] if a.cases == "all" else [a.cases]
    cases = [
        f"{k}:{n}:{s}"
        for k in kinds
        for n in (16, 20, 24)
        for s in ("c", "2,2", f"{n - 2},{n - 2}", f"2,{n - 2}", f"{n - 2},2")
    ]
th = np.linspace(0, np.pi / 2, 30)
res = {}
for case in cases:
    kind, n, st = case.split(":")
    n = int(n)
    ex, sp = exemplar(kind)
    aa = n * sp
    region = Region.rectangle(aa, aa)
    af = flow_field(
        [np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)]
    )
    s = None if st == "c" else tuple(float(v) * sp for v in st.split(","))
    t0 = time.process_time()
    out = grow(ex, region=region, mode="flow", flow=af, rng=a.rng, start=s, **PARAMS)
    dt = time.process_time() - t0
    inner = region.distance_to_boundary(out.xy) > 2 * sp
    x0, y0, x1, y1 = region.bounds
    grid = (
        np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0]
        .reshape(2, -1)
        .T
    )
    d = gb.lattice_defects(out.xy, sp, inner, grid)
    across = int(
        (
            ~np.asarray(
                region.contains_geometry(out.geometry, tolerance=1e-9), dtype=bool
            )
        ).sum()
    )
    res[case] = dict(
        n=len(out),
        six=gb.hex_share(out.xy, sp, inner),
        cpu=dt,
        across=across,
        **d,
        **gb.field_misalignment(ex, out.xy, sp, inner, af),
    )
    print(
        f"{case:16s} n={len(out)} six={res[case]['six']:.4f} holes={d['holes']} lg={d['largest_defect_group']} iso={d['isolated_defect_share']:.2f} across={across} p90={res[case]['misalign_deg_p90']:.1f} cpu={dt:.1f}",
        flush=True,
    )
print("SUM", round(sum(r["six"] for r in res.values()), 4))
if a.json:
    with open(a.json, "w") as f:
        json.dump(res, f, indent=1)

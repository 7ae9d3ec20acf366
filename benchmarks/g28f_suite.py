"""g28f: the suite's own flow cases (``benchmarks/grow.py --structure --flow-only``'s 12
rows, same regions, fields, starts and rng) one by one, with constants of ``strew.grow``
modules set (``--set MODULE.NAME=V``), printing each row's six share and holes
(``grow.hex_share``, ``grow.lattice_defects``) and the wall time; for splitting the
across-first order's loss into order vs frame bound (issue 14 point 2).

    PYTHONPATH=src python benchmarks/g28f_suite.py [--only 0,3,...] [--set _objects.FLOW_ORDER_ALONG=1.0 _flow_holes.HOLE_FRAME=inf] [--bound-always] [--rng 1] [--json F]
"""

import argparse
import importlib
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import grow as gb

ap = argparse.ArgumentParser()
ap.add_argument("--json", default="")
ap.add_argument("--only", default="")
ap.add_argument("--rng", type=int, default=1, help="the growth's seed (the suite's: 1)")
ap.add_argument("--set", nargs="*", default=[])
ap.add_argument("--bound-always", action="store_true",
                help="the frame bound (_flow_holes._frame_ok / move_ok) in every flow growth, whatever the order")
a = ap.parse_args()
for kv in a.set:
    k, v = kv.split("=")
    m, k = k.split(".")
    mod = importlib.import_module("strew.grow." + m)
    setattr(mod, k, float(eval(v, {"inf": math.inf})))
    print("set", mod.__name__, k, getattr(mod, k))

from scipy.spatial import cKDTree

if a.bound_always:
    from strew.grow import _objects as _ob

    _ob._Objects.flow_across_first = lambda self: self.mode_code == 2 and self.tile is None and self.p.flow is not None

from strew import Region
from strew.fields import flow_field
from strew.grow import grow


def turning(deg, w):
    def field(p):
        ang = np.radians(deg) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(ang), np.sin(ang)]

    return field


def cases():
    """(label, exemplar, spacing, region, field, start) of the suite's flow rows, in its order."""
    ex = gb._suite_exemplar("hex_lattice", nx=8, ny=8)
    sp = 12.0
    th = np.linspace(0, np.pi / 2, 30)
    out = []
    for deg in (60.0, 90.0):
        w, h = 30 * sp, 20 * sp
        out.append((f"turning {deg:.0f} deg 30 sp", ex, sp, Region.rectangle(w, h), turning(deg, w), None))
    w, h = 24 * sp, 16 * sp
    t = np.linspace(0, w, 30)
    waves = [np.c_[t, h * (0.3 + 0.05 * np.sin(2 * np.pi * t / w))], np.c_[t, h * (0.7 + 0.05 * np.sin(2 * np.pi * t / w + 0.5))]]
    out.append(("two wavy strokes", ex, sp, Region.rectangle(w, h), flow_field(waves), None))
    out.append(("quarter-circle strokes", ex, sp, Region.rectangle(30 * sp, 30 * sp),
                flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (10 * sp, 25 * sp)]), None))
    for f in (1.0, 1.5):
        w, h = 30 * sp * f, 20 * sp * f
        starts = [(w / 2, 2 * sp), (2 * sp, h - 2 * sp)] if f == 1.0 else [None]
        for st in starts:
            where = "centre" if st is None else f"start {st[0] / sp:.0f},{st[1] / sp:.0f}"
            out.append((f"turning 90 {30 * f:.0f}x{20 * f:.0f} {where}", ex, sp, Region.rectangle(w, h), turning(90.0, w), st))
        aa = 30 * sp * f
        af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
        starts = [(aa - 2 * sp, aa - 2 * sp), (2 * sp, 2 * sp)] if f == 1.0 else [None]
        for st in starts:
            where = "centre" if st is None else f"start {st[0] / sp:.0f},{st[1] / sp:.0f}"
            out.append((f"qc {30 * f:.0f}x{30 * f:.0f} {where}", ex, sp, Region.rectangle(aa, aa), af, st))
    scales = gb._suite_exemplar("scales")
    s_sp = float(np.median(cKDTree(scales.xy).query(scales.xy, 7)[0][:, 1:]))
    w, h = 30 * s_sp, 20 * s_sp
    out.append(("scales turning 90", scales, s_sp, Region.rectangle(w, h), turning(90.0, w), None))
    out.append(("scales qc", scales, s_sp, Region.rectangle(30 * s_sp, 30 * s_sp),
                flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (10 * s_sp, 25 * s_sp)]), None))
    return out


only = {int(s) for s in a.only.split(",")} if a.only else None
rows = []
from strew.grow import _objects

for i, (label, ex, sp, region, field, st) in enumerate(cases()):
    if only is not None and i not in only:
        continue
    t0 = time.process_time()
    out = grow(ex, region=region, mode="flow", flow=field, rng=a.rng, start=st)
    cpu = time.process_time() - t0
    xy = out.xy
    inner = region.distance_to_boundary(xy) > 2 * sp
    x0, y0, x1, y1 = region.bounds
    g = np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0].reshape(2, -1).T
    six = float(gb.hex_share(xy, sp, inner))
    holes = int(gb.lattice_defects(xy, sp, inner, g)["holes"])
    r = {"i": i, "label": label, "n": len(out), "six": six, "holes": holes, "cpu_s": cpu}
    rows.append(r)
    print(f"{i:2d} {label:32s} n {len(out):4d} six {six:.4f} holes {holes} cpu {cpu:.0f}s", flush=True)
print("sum", round(sum(r["six"] for r in rows), 4), "holes", sum(r["holes"] for r in rows))
if a.json:
    Path(a.json).write_text(json.dumps({"set": a.set, "bound_always": a.bound_always, "rng": a.rng, "rows": rows}, indent=1))

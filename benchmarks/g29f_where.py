"""g29f: where the across-first order loses six-neighbour elements on the suite's quarter-circle
centre rows (issue 14 point 2): grows one row of ``benchmarks/g28f_suite.py`` with the given
``--set`` constants and saves the output's xy (creation order) to ``--npz``; with ``--report``
prints, for each saved growth (map: one character a spacing, the creation quintile of each non-six element), the inner non-six elements binned by radius from the field's
centre (the quarter circles' origin) and by angle from the start's radius.

    PYTHONPATH=src python benchmarks/g29f_where.py --row 3 [--set _objects.FLOW_ORDER_ALONG=1.0] --npz F
    python benchmarks/g29f_where.py --report F1 F2 ...
"""

import argparse
import importlib
import math
import sys
from pathlib import Path

import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("--row", type=int, default=3)
ap.add_argument("--rng", type=int, default=1)
ap.add_argument("--qc", type=float, default=0.0, help="instead of --row: the suite's quarter-circle field (strokes at a/3, 5a/6) in an a x a square, a = QC spacings, hex exemplar, centre start")
ap.add_argument("--set", nargs="*", default=[])
ap.add_argument("--npz", default="")
ap.add_argument("--report", nargs="*", default=None)
a = ap.parse_args()
sys.path.insert(0, str(Path(__file__).resolve().parent))


def six_mask(xy, sp):
    from scipy.spatial import cKDTree

    t = cKDTree(xy)
    hi = np.array([len(t.query_ball_point(p, 1.15 * sp)) - 1 for p in xy])
    lo = np.array([len(t.query_ball_point(p, 0.85 * sp)) - 1 for p in xy])
    return (hi == 6) & (lo == 0)


if a.report is not None:
    for f in a.report:
        d = np.load(f)
        xy, sp, aa, st = d["xy"], float(d["sp"]), float(d["aa"]), d["start"]
        inner = (xy.min(1) > 2 * sp) & (xy.max(1) < aa - 2 * sp)
        six = six_mask(xy, sp)
        r = np.hypot(xy[:, 0], xy[:, 1]) / sp
        phi = np.degrees(np.arctan2(xy[:, 1], xy[:, 0])) - math.degrees(math.atan2(st[1], st[0]))
        rs = math.hypot(*st) / sp
        bad = inner & ~six
        print(f, "n", len(xy), "inner", inner.sum(), "six", round(float(six[inner].mean()), 4), "start r", round(rs, 1))
        rb = np.arange(0, 45, 5)
        print("  radius bins (sp):      ", " ".join(f"{b:>5d}" for b in rb[:-1]))
        print("  non-six / inner       :", " ".join(f"{int(bad[(r >= b) & (r < b + 5)].sum()):2d}/{int(inner[(r >= b) & (r < b + 5)].sum()):3d}"[-6:].rjust(5) for b in rb[:-1]))
        ab = [(-50, -30), (-30, -15), (-15, -5), (-5, 5), (5, 15), (15, 30), (30, 50)]
        print("  angle from start's radius bins:", " ".join(f"{lo}..{hi}" for lo, hi in ab))
        print("  non-six / inner       :", " ".join(f"{int(bad[(phi >= lo) & (phi < hi)].sum())}/{int(inner[(phi >= lo) & (phi < hi)].sum())}" for lo, hi in ab))
        # the edges the streamlines cross (x = 0, y = 0: the field there along the edge's normal)
        # vs the edges they run along (x = a, y = a)
        near = np.minimum(xy[:, 0], xy[:, 1]) < 5 * sp
        print("  non-six within 5 sp of the edges the streamlines cross (x=0, y=0):", f"{int(bad[near].sum())}/{int(inner[near].sum())}",
              " elsewhere:", f"{int(bad[~near].sum())}/{int(inner[~near].sum())}")
        # creation order: quintiles of the output's index
        q = np.array_split(np.arange(len(xy)), 5)
        print("  non-six by creation quintile:", " ".join(f"{int(bad[i].sum())}/{int(inner[i].sum())}" for i in q))
        # map, one character a spacing, y up: the creation quintile (1-5) of each inner non-six element
        qi = np.zeros(len(xy), int)
        for k, i in enumerate(q):
            qi[i] = k + 1
        m = int(round(aa / sp))
        grid = [["."] * m for _ in range(m)]
        for i in np.where(bad)[0]:
            grid[min(int(xy[i, 1] / sp), m - 1)][min(int(xy[i, 0] / sp), m - 1)] = str(qi[i])
        print("\n".join("  " + "".join(r) for r in grid[::-1]))
    sys.exit()

for kv in a.set:
    k, v = kv.split("=")
    m, k = k.split(".")
    mod = importlib.import_module("strew.grow." + m)
    setattr(mod, k, float(eval(v, {"inf": math.inf})))
sys.argv = [sys.argv[0]]
src = (Path(__file__).resolve().parent / "g28f_suite.py").read_text()
ns = {"__file__": str(Path(__file__).resolve().parent / "g28f_suite.py")}
exec(compile(src[: src.index("only = ")], "g28f_suite.py", "exec"), ns)  # (its cases(), none run)
label, ex, sp, region, field, st = ns["cases"]()[a.row if not a.qc else 3]
if a.qc:
    aa = a.qc * sp
    th = np.linspace(0, np.pi / 2, 30)
    region = ns["Region"].rectangle(aa, aa)
    field = ns["flow_field"]([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
    label, st = f"qc {a.qc:g} centre", None
x0, y0, x1, y1 = region.bounds
start = np.array(st if st is not None else (0.5 * (x0 + x1), 0.5 * (y0 + y1)))
out = ns["grow"](ex, region=region, mode="flow", flow=field, rng=a.rng, start=st)
print(label, "n", len(out))
np.savez(a.npz, xy=np.asarray(out.xy), sp=sp, aa=x1 - x0, start=start)

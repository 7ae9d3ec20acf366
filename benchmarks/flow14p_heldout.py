"""flow14p: held-out flow cases (issue 14 point 2), not tuned on: the hexagonal lattice
grown along the two-quarter-circle field over squares of 16, 20 and 24 spacings,
from the centre and from each corner (2 spacings in) (``--scales``: the scales
exemplar instead); the interior six-neighbour
share (``benchmarks/grow.py``'s ``six_nbr_share``), holes and CPU s per case.

    PYTHONPATH=src python benchmarks/flow14p_heldout.py [--json F]

Compare two trees by running it with each on PYTHONPATH.
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
from strew.grow import grow  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--json", default="")
ap.add_argument("--scales", action="store_true", help="the scales exemplar (its spacing: the median distance to six nearest)")
a = ap.parse_args()
if a.scales:
    from scipy.spatial import cKDTree

    ex = gb._suite_exemplar("scales")
    sp = float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
else:
    ex = gb._suite_exemplar("hex_lattice", nx=8, ny=8)
    sp = 12.0
th = np.linspace(0, np.pi / 2, 30)
res = {}
for n in (16, 20, 24):
    aa = n * sp
    region = Region.rectangle(aa, aa)
    af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
    for st in (None, (2, 2), (n - 2, n - 2), (2, n - 2), (n - 2, 2)):
        s = None if st is None else (st[0] * sp, st[1] * sp)
        t0 = time.process_time()
        out = grow(ex, region=region, mode="flow", flow=af, rng=1, start=s)
        dt = time.process_time() - t0
        inner = region.distance_to_boundary(out.xy) > 2 * sp
        x0, y0, x1, y1 = region.bounds
        grid = np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0].reshape(2, -1).T
        d = gb.lattice_defects(out.xy, sp, inner, grid)
        name = f"qc{n}_{'c' if st is None else '%d,%d' % st}"
        res[name] = dict(n=len(out), six=gb.hex_share(out.xy, sp, inner), holes=d["holes"], cpu=dt)
        print(f"{name:12s} n={len(out)} six={res[name]['six']:.4f} holes={d['holes']} cpu={dt:.1f}", flush=True)
print("SUM", round(sum(r["six"] for r in res.values()), 4))
if a.json:
    json.dump(res, open(a.json, "w"), indent=1)

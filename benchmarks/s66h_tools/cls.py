# Helper s66h analysis of the npz files benchmarks/s66h_stages_h4.py writes to /tmp/s66h (run that first, --cap 0 and 1).
import sys

import numpy as np

sys.path.insert(0, "benchmarks")
from scipy.spatial import Delaunay, cKDTree


def circ(xy, size):
    tri = Delaunay(xy); p = xy[tri.simplices]
    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    d = 2 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    a2, b2, c2 = (a * a).sum(1), (b * b).sum(1), (c * c).sum(1)
    ux = (a2 * (b[:, 1] - c[:, 1]) + b2 * (c[:, 1] - a[:, 1]) + c2 * (a[:, 1] - b[:, 1])) / d
    uy = (a2 * (c[:, 0] - b[:, 0]) + b2 * (a[:, 0] - c[:, 0]) + c2 * (b[:, 0] - a[:, 0])) / d
    r = np.hypot(ux - a[:, 0], uy - a[:, 1])
    ins = (ux - r >= 0) & (ux + r <= size) & (uy - r >= 0) & (uy + r <= size)
    return r[ins], tri.simplices[ins]
THR = 48.03
for v in sys.argv[1:]:
  for c in (0, 1):
    row = []
    for s in range(1, 7):
        z = np.load(f"/tmp/s66h/h4s{v}_cap{c}_s{s}.npz"); fin = z["final"]; g = z["0_growth"]
        fin = fin[(fin[:, 0] >= 0) & (fin[:, 0] <= 1050) & (fin[:, 1] >= 0) & (fin[:, 1] <= 1050)]
        fromg = cKDTree(g[:, :2]).query(fin[:, :2])[0] < 1e-6
        r, simp = circ(fin[:, :2], 1050)
        ng = fromg[simp].sum(1)
        q = np.quantile(r, 0.95)
        big = r > THR
        kinds = fin[simp, 2].astype(int)
        nd = (kinds == 0).sum(1)
        row.append(f"s{s} q95 {q:.1f} circles {len(r)} big {big.sum()} [allgrowth {np.sum(big & (ng == 3))} mixed {np.sum(big & (ng > 0) & (ng < 3))} alllater {np.sum(big & (ng == 0))}] later-share elems {1 - fromg.mean():.2f} discs {np.sum(fin[:, 2] == 0)}")
    print(f"h4s{v} cap{c}:\n  " + "\n  ".join(row))

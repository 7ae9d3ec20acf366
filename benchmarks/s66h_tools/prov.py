# Helper s66h analysis of the npz files benchmarks/s66h_stages_h4.py writes to /tmp/s66h (run that first, --cap 0 and 1).
import numpy as np
import shapely
from scipy.spatial import Voronoi, cKDTree

fr = shapely.box(0, 0, 1050, 1050)
def cells(pts):
    # Voronoi cell areas clipped to the frame (mirror points to close the diagram)
    m = np.r_[pts, pts * [-1, 1], pts * [1, -1], np.c_[2100 - pts[:, 0], pts[:, 1]], np.c_[pts[:, 0], 2100 - pts[:, 1]]]
    vor = Voronoi(m)
    out = np.zeros(len(pts))
    for i in range(len(pts)):
        reg = vor.regions[vor.point_region[i]]
        if -1 in reg or not reg: out[i] = np.nan; continue
        out[i] = shapely.Polygon(vor.vertices[reg]).intersection(fr).area
    return out
import sys

CAPS = [int(x) for x in sys.argv[2].split(",")] if len(sys.argv) > 2 else [0, 1]
for v in [int(x) for x in sys.argv[1].split(",")] if len(sys.argv) > 1 else (9, 12):
  for c in CAPS:
    rows = []
    for s in range(1, 7):
        z = np.load(f"/tmp/s66h/h4s{v}_cap{c}_s{s}.npz"); fin = z["final"]; g = z["0_growth"]
        fin = fin[(fin[:, 0] >= 0) & (fin[:, 0] <= 1050) & (fin[:, 1] >= 0) & (fin[:, 1] <= 1050)]
        disc = fin[fin[:, 2] == 0, :2]
        fromg = cKDTree(g[:, :2]).query(disc)[0] < 1e-6
        a = cells(disc)
        ag, al = np.nansum(a[fromg]), np.nansum(a[~fromg])
        rows.append(f"s{s}: growth discs {fromg.sum()} area {ag/1e4:.1f}e4 -> {fromg.sum()/ag*1e4:.3f}/1e4 | later discs {(~fromg).sum()} area {al/1e4:.1f}e4 -> {(~fromg).sum()/max(al,1)*1e4:.3f}/1e4")
    print(f"h4s{v} cap{c}\n  " + "\n  ".join(rows))

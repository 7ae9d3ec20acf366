# Helper s66h analysis of the npz files benchmarks/s66h_stages_h4.py writes to /tmp/s66h (run that first, --cap 0 and 1).
import sys

import numpy as np

sys.path.insert(0, "benchmarks")
import matplotlib; matplotlib.use("Agg")
import matplotlib.pyplot as plt
import shapely
from matplotlib.patches import Circle
from s66h_stages_h4 import circles
from scipy.spatial import cKDTree

out, thr = sys.argv[1], float(sys.argv[2]); files = sys.argv[3:]
fig, axs = plt.subplots(1, len(files), figsize=(7 * len(files), 7)); axs = np.atleast_1d(axs)
for ax, f in zip(axs, files):
    z = np.load(f); g = z["0_growth"]; fin = z["final"]
    fr = shapely.box(0, 0, 1050, 1050)
    d, _ = cKDTree(g[:, :2]).query(fin[:, :2])
    fromg = d < 1e-6
    k = fin[:, 2].astype(int)
    for p, fg in zip(fin[k == 0, :2], fromg[k == 0]): ax.add_patch(Circle(p, 14, color="0.3" if fg else "tab:blue"))
    ax.scatter(*fin[(k == 1) & fromg, :2].T, s=3, c="k"); ax.scatter(*fin[(k == 1) & ~fromg, :2].T, s=3, c="tab:blue")
    c = circles(fin[:, :2], fr)
    for x, y, r in c[c[:, 2] > thr]: ax.add_patch(Circle((x, y), r, fill=False, ec="r", lw=0.6))
    gd = g[(g[:, 2] == 0)]
    ax.set_xlim(-100, 1150); ax.set_ylim(-100, 1150); ax.set_aspect("equal")
    ax.plot([0, 1050, 1050, 0, 0], [0, 0, 1050, 1050, 0], "g-", lw=0.5)
    ax.set_title(f"{f.split('/')[-1]}: grey/black = from growth, blue = later passes; red circles > {thr}", fontsize=8)
fig.tight_layout(); fig.savefig(out, dpi=110)

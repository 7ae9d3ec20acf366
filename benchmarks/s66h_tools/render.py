# Helper s66h analysis of the npz files benchmarks/s66h_stages_h4.py writes to /tmp/s66h (run that first, --cap 0 and 1).
import sys

import numpy as np

sys.path.insert(0, "benchmarks")
import matplotlib; matplotlib.use("Agg")
import matplotlib.pyplot as plt
import shapely
from matplotlib.patches import Circle
from s66h_stages_h4 import circles


def draw(ax, a, size, thr, title):
    xy, k = a[:, :2], a[:, 2].astype(int)
    fr = shapely.box(0, 0, size, size)
    ins = shapely.contains_xy(fr, xy[:, 0], xy[:, 1]); xy, k = xy[ins], k[ins]
    for p in xy[k == 0]: ax.add_patch(Circle(p, 14, color="0.3"))
    ax.scatter(*xy[k == 1].T, s=3, c="k")
    c = circles(xy, fr)
    for x, y, r in c[c[:, 2] > thr]: ax.add_patch(Circle((x, y), r, fill=False, ec="r", lw=0.6))
    ax.set_xlim(0, size); ax.set_ylim(0, size); ax.set_aspect("equal"); ax.set_title(title, fontsize=8)
args = sys.argv[1:]
out = args[0]; thr = float(args[1]); items = args[2:]
fig, axs = plt.subplots(1, len(items) // 3, figsize=(7 * len(items) // 3, 7))
axs = np.atleast_1d(axs)
for ax, (f, key, size) in zip(axs, zip(items[::3], items[1::3], items[2::3])):
    a = np.load(f)[key] if f.endswith(".npz") else np.load(f)
    draw(ax, a, float(size), thr, f"{f.split('/')[-1]} {key} circles > {thr}")
fig.tight_layout(); fig.savefig(out, dpi=110)

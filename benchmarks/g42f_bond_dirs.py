"""g42f: the direction of the stretched bonds (Delaunay, 1.15-1.6 spacings, both ends
interior) of a grown held-out flow case relative to the field at their middle (degrees,
folded to 0-90: 0 along the field's rows), from the arrays benchmarks/g42f_where.py saves.

    PYTHONPATH=src python benchmarks/g42f_bond_dirs.py /tmp/g42f/out_hex_16_2_14.npy hex 16
"""
import sys
import numpy as np
from scipy.spatial import Delaunay
from strew import Region
from strew.fields import flow_field

xy = np.load(sys.argv[1]); kind = sys.argv[2]; n = int(sys.argv[3])
if kind == "scales":
    sys.path.insert(0, "benchmarks"); import grow as gb
    from scipy.spatial import cKDTree
    ex = gb._suite_exemplar("scales"); sp = float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
else:
    sp = 12.0
aa = n * sp; th = np.linspace(0, np.pi / 2, 30)
af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
inner = Region.rectangle(aa, aa).distance_to_boundary(xy) > 2 * sp
tri = Delaunay(xy)
e = np.unique(np.sort(np.r_[tri.simplices[:, [0, 1]], tri.simplices[:, [1, 2]], tri.simplices[:, [0, 2]]], axis=1), axis=0)
e = e[inner[e[:, 0]] & inner[e[:, 1]]]
d = xy[e[:, 1]] - xy[e[:, 0]]; ln = np.hypot(*d.T) / sp
f = np.asarray(af(0.5 * (xy[e[:, 0]] + xy[e[:, 1]])))
ang = np.degrees(np.arccos(np.clip(np.abs((d * f).sum(1)) / (np.hypot(*d.T) * np.hypot(*f.T)), 0, 1)))
for lo, hi in ((0.85, 1.15), (1.15, 1.6)):
    m = (ln > lo) & (ln < hi)
    print(f"bonds {lo}-{hi}: {m.sum():4d}  angle to field hist (0-15,15-45,45-75,75-90):",
          np.histogram(ang[m], [0, 15, 45, 75, 90])[0])

"""g42f: the interior Delaunay five- and seven-neighbour sites of a grown held-out flow
case (arrays from benchmarks/g42f_where.py): how many fives have a seven among their
neighbours (a 5-7 dislocation core) and how many fives touch another five.

    python benchmarks/g42f_cores.py /tmp/g42f/out_hex_16_2_14.npy 12.0 16
"""
import sys
import numpy as np
from scipy.spatial import Delaunay
from strew import Region

xy = np.load(sys.argv[1]); sp = float(sys.argv[2]); n = int(sys.argv[3])
inner = Region.rectangle(n * sp, n * sp).distance_to_boundary(xy) > 2 * sp
tri = Delaunay(xy); ind, nb = tri.vertex_neighbor_vertices
deg = np.diff(ind)
# a Delaunay bond longer than 1.3 spacings (across a square cell) is not counted
nbrs = [[j for j in nb[ind[i]:ind[i + 1]] if np.hypot(*(xy[j] - xy[i])) < 1.3 * sp] for i in range(len(xy))]
cnt = np.array([len(v) for v in nbrs])
five = np.flatnonzero(inner & (cnt == 5)); seven = np.flatnonzero(inner & (cnt == 7))
print("interior", inner.sum(), "fives", len(five), "sevens", len(seven), "other", (inner & (cnt != 6) & (cnt != 5) & (cnt != 7)).sum())
print("fives with a seven beside", sum(any(cnt[j] == 7 for j in nbrs[i]) for i in five),
      "fives beside a five", sum(any(cnt[j] == 5 and inner[j] for j in nbrs[i]) for i in five),
      "fives with a seven or a 4 beside", sum(any(cnt[j] >= 7 or cnt[j] <= 4 for j in nbrs[i]) for i in five))

# the cores' Burgers vectors (the 5->7 bond turned by 90 degrees, one spacing) and the
# dipoles among them: two cores within 3 spacings whose Burgers vectors are opposite
# (within 30 degrees): a pair that cancels, needed by no turn of the lattice
cores = []
for i in five:
    for j in nbrs[i]:
        if cnt[j] == 7:
            v = xy[j] - xy[i]; cores.append((0.5 * (xy[i] + xy[j]), np.array([-v[1], v[0]]) / np.hypot(*v)))
            break
P = np.array([c[0] for c in cores]).reshape(-1, 2); B = np.array([c[1] for c in cores]).reshape(-1, 2)
used = set(); dip = 0
for a in range(len(P)):
    if a in used:
        continue
    for b in range(a + 1, len(P)):
        if b not in used and np.hypot(*(P[a] - P[b])) < 3 * sp and B[a] @ B[b] < -np.cos(np.radians(30)):
            used |= {a, b}; dip += 1; break
print("cores", len(P), "net |sum b|", round(float(np.hypot(*B.sum(0))) if len(B) else 0.0, 2), "dipoles within 3 spacings", dip)

# each core: where (spacings; polar about the field's centre, the origin) and the angle of its
# Burgers vector to the field's direction there (+-180: the sign along the rows)
if len(sys.argv) > 4:
    from strew.fields import flow_field
    th = np.linspace(0, np.pi / 2, 30); aa = n * sp
    af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
    f = np.asarray(af(P)) if len(P) else np.zeros((0, 2))
    for (x, y), b, fd in sorted(zip(P / sp, B, f), key=lambda t: np.arctan2(t[0][1], t[0][0])):
        a = np.degrees(np.arctan2(fd[0] * b[1] - fd[1] * b[0], fd @ b))
        print(f"  core at ({x:5.1f},{y:5.1f}) r {np.hypot(x, y):5.1f} phi {np.degrees(np.arctan2(y, x)):5.1f}  b to field {a:7.1f}")

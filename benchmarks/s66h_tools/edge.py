# Helper s66h analysis of the npz files benchmarks/s66h_stages_h4.py writes to /tmp/s66h (run that first, --cap 0 and 1).
import numpy as np

for v in (9, 12):
  for c in (0, 1):
    rows = []
    for s in range(1, 7):
        z = np.load(f"/tmp/s66h/h4s{v}_cap{c}_s{s}.npz")
        keys = [k for k in z.files if k != "final"]
        last = z[keys[-1]]; fin = z["final"]
        def inside(a, m=0):
            return (a[:, 0] >= m) & (a[:, 0] <= 1050 - m) & (a[:, 1] >= m) & (a[:, 1] <= 1050 - m)
        d = last[last[:, 2] == 0]
        e = np.minimum(np.minimum(d[:, 0], 1050 - d[:, 0]), np.minimum(d[:, 1], 1050 - d[:, 1]))
        g = z["0_growth"]; gd = g[g[:, 2] == 0]
        ge = np.minimum(np.minimum(gd[:, 0], 1050 - gd[:, 0]), np.minimum(gd[:, 1], 1050 - gd[:, 1]))
        rows.append(f"s{s}: discs centre in frame {np.sum(e >= 0)} of them within 14.4 of edge {np.sum((e >= 0) & (e < 14.4))} -> final discs {np.sum(fin[:, 2] == 0)}; interior (>=14.4) {np.sum(e >= 14.4)} | growth: interior {np.sum(ge >= 14.4)} edge {np.sum((ge >= 0) & (ge < 14.4))}")
    print(f"h4s{v} cap{c}\n  " + "\n  ".join(rows))

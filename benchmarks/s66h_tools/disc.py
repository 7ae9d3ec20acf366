# Helper s66h analysis of the npz files benchmarks/s66h_stages_h4.py writes to /tmp/s66h (run that first, --cap 0 and 1).
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from cls import circ

for v in (9, 12):
  ex = None
  for c in (0, 1):
    rows = []
    for s in range(1, 7):
        fin = np.load(f"/tmp/s66h/h4s{v}_cap{c}_s{s}.npz")["final"]
        fin = fin[(fin[:, 0] >= 0) & (fin[:, 0] <= 1050) & (fin[:, 1] >= 0) & (fin[:, 1] <= 1050)]
        disc = fin[fin[:, 2] == 0, :2]
        r, _ = circ(disc, 1050)
        ra, _ = circ(fin[:, :2], 1050)
        rows.append(f"s{s}: all q95 {np.quantile(ra, .95):.1f} n {len(fin)} discs {len(disc)} dots/disc {(len(fin)-len(disc))/len(disc):.2f} | disc-only circles q50/q90/q95/max {np.round(np.quantile(r, [.5, .9, .95, 1]), 1)}")
    print(f"h4s{v} cap{c}\n  " + "\n  ".join(rows))

"""Helper g44r: the hard-core test's shape statistics over the survey of
``benchmarks/g44r_core_survey.py``: floor (q10 / least - 1), tail (q90 / q10 - 1) and
floor over tail, per exemplar under the spread test, with the generator's kind (dart
throw or lattice), the old test (floor <= HARD_CORE_FLOOR - 1) and the new one (floor
<= HARD_CORE_SHAPE x tail), both with the tail test, and the margins of each.

    PYTHONPATH=src python benchmarks/g44r_core_stats.py SURVEY.npz [--all]
"""
import sys

import numpy as np

THROWS = {"stripes", "stones", "two_sizes", "three_sizes", "clusters", "sparse_voids", "sticks"}
npz = np.load(sys.argv[1])
rows = []
for key in npz.files:
    nn = npz[key]
    cls, label = key.split(":")
    lo, q10, q90 = float(nn.min()), float(np.quantile(nn, 0.1)), float(np.quantile(nn, 0.9))
    floor, tail = q10 / lo - 1, q90 / q10 - 1
    ratio = floor / tail if tail > 0 else np.inf
    old = floor <= 0.015 and tail >= 0.1 - 1e-12
    new = tail >= 0.1 - 1e-12 and floor <= 0.1 * tail
    rows.append((cls, label, len(nn), 100 * nn.std() / nn.mean(), 100 * floor, 100 * tail, ratio, cls in THROWS, old, new))
rows.sort(key=lambda r: (r[6], r[0], r[1]))
show = "--all" in sys.argv
print("class         label    n     cv%   floor%   tail%  floor/tail throw hard(old) hard(new)")
for r in rows:
    if show or r[5] >= 8.0:
        print(f"{r[0]:13s} {r[1]:7s} {r[2]:4d} {r[3]:6.2f} {r[4]:7.3f} {r[5]:7.2f} {r[6]:10.4f}   {int(r[7])}      {int(r[8])}         {int(r[9])}")
R = np.array([(r[4], r[5], r[6]) for r in rows])
thr = np.array([r[7] for r in rows])
hard_old = np.array([r[8] for r in rows])
hard_new = np.array([r[9] for r in rows])
print(f"\n{len(rows)} exemplars under the spread test ({thr.sum()} from dart-throwing generators)")
print(f"old and new tests differ on {int(np.sum(hard_old != hard_new))}: {[rows[i][:2] for i in np.flatnonzero(hard_old != hard_new)]}")
print(f"read as hard-core (new): {[r[:2] for r in rows if r[9]]}")
t = R[:, 1] >= 10.0 - 1e-9
hc = t & (R[:, 2] <= 0.1)
# margins: with the tail test, the hard-core group (floor/tail <= 0.1) and the lattices beside it
if not hc.any():
    sys.exit(0)  # no hard-core exemplar here: no margins to print
print("\nwith a tail of 10 % or more:")
for name, col in (("floor %", 0), ("floor/tail", 2)):
    a, b = R[hc, col].max(), R[t & ~hc, col].min()
    print(f"  {name:10s}: hard-core <= {a:.4f}, lattices >= {b:.4f}, ratio of the two {b / a:.3f}")
a, b = R[hc, 1].min(), R[~t & (R[:, 2] <= 0.1), 1].max()
print(f"  tail %     : hard-core >= {a:.3f}, under 10 % with floor/tail <= 0.1: <= {b:.3f}, ratio {a / b:.3f}")
a, b = R[hc, 1].min(), R[~t & (R[:, 0] <= 1.5), 1].max()
print(f"  tail % (old): hard-core >= {a:.3f}, under 10 % with floor <= 1.5 %: <= {b:.3f}, ratio {a / b:.3f}")

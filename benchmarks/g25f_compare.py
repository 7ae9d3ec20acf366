"""g25f: two screens of the held-out flow cases (``benchmarks/g25f_screen.py --json``)
side by side: each case's six-neighbour share, holes and lattice turn (p90), and per
exemplar the sum and mean of the shares, the worst, how many rose and fell, and holes.

    python benchmarks/g25f_compare.py BASE.json NEW.json
"""

import json
import sys


def _load(path: str) -> dict:
    with open(path) as f:
        return json.load(f)


a, b = _load(sys.argv[1]), _load(sys.argv[2])
for kind in ("hex", "scales"):
    ks = [k for k in b if k.startswith(kind + ":") and k in a]
    if not ks:
        continue
    for k in ks:
        x, y = a[k], b[k]
        print(
            f"{k:16s} {x['six']:.4f} -> {y['six']:.4f} ({y['six'] - x['six']:+.4f}) holes {x['holes']} -> {y['holes']}"
            f" p90 {x.get('misalign_deg_p90', float('nan')):.1f} -> {y.get('misalign_deg_p90', float('nan')):.1f}"
            f" across {x.get('across', 0)} -> {y.get('across', 0)}"
        )
    sa, sb = sum(a[k]["six"] for k in ks), sum(b[k]["six"] for k in ks)
    up = sum(b[k]["six"] > a[k]["six"] + 1e-9 for k in ks)
    dn = sum(b[k]["six"] < a[k]["six"] - 1e-9 for k in ks)
    print(
        f"{kind}: {len(ks)} cases, sum {sa:.3f} -> {sb:.3f}, mean {sa / len(ks):.4f} -> {sb / len(ks):.4f},"
        f" worst {min(a[k]['six'] for k in ks):.4f} -> {min(b[k]['six'] for k in ks):.4f}, higher {up} lower {dn},"
        f" holes {sum(a[k]['holes'] for k in ks)} -> {sum(b[k]['holes'] for k in ks)}"
    )

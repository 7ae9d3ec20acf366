"""The untiled vase's flowers by panel size (issue 19.4, vas19x): does every panel grow its
grid of flowers?

``PYTHONPATH=TREE/src python benchmarks/vas19x_sizes.py [--sides 160:400:8] [--rects] [--seeds 1] [--json F]``

For each square panel (and with ``--rects`` the rectangles 200 x H and 264 x H, H =
160..400 step 12) ``grow_ornament("vase", W x H, rng=SEED, min_radius=5)`` (the vines'
phase in full, its threshold is 5; the hooks' phase cut short): the flowers, the flowers
per 10^4 area units, and the flowers against the grid points whose flower fits inside the
panel (vase.GRID, vase.FLOWER_RADIUS). At d67a7c3 the panels whose centre (the seed) lies
on the grid grew none: 264, 308, 352.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sides", default="160:400:8", help="a:b:step or a comma list")
    ap.add_argument("--rects", action="store_true")
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    import numpy as np

    import strew
    from strew.ornament import grow_ornament
    from strew.ornament.patterns import vase

    if ":" in args.sides:
        a, b, st = (int(v) for v in args.sides.split(":"))
        sides = list(range(a, b + 1, st))
    else:
        sides = [int(v) for v in args.sides.split(",")]
    sizes = [(s, s) for s in sides]
    if args.rects:
        sizes += [(w, h) for w in (200, 264) for h in range(160, 401, 12)]

    def fit(n: float) -> int:
        return sum(1 for i in range(64) if vase.FLOWER_RADIUS <= i * vase.GRID <= n - vase.FLOWER_RADIUS)

    out = {}
    for seed in [int(v) for v in args.seeds.split(",")]:
        for w, h in sizes:
            t0 = time.process_time()
            arr = grow_ornament("vase", strew.Region.rectangle(w, h), rng=seed, min_radius=5.0)
            cnt = dict(zip(arr.kinds, np.bincount(np.asarray(arr.kind), minlength=len(arr.kinds)).tolist()))
            fl = cnt.get("lotus", 0) + cnt.get("peony", 0)
            pts = fit(w) * fit(h)
            row = {"flowers": fl, "vines": cnt.get("vine", 0), "grid_points": pts, "per_1e4": 1e4 * fl / (w * h),
                   "of_grid": fl / pts, "cpu_s": time.process_time() - t0}
            out[f"{w}x{h}_s{seed}"] = row
            print(f"{w}x{h} s{seed}: flowers {fl} ({row['per_1e4']:.2f} per 1e4), of {pts} grid points {row['of_grid']:.3f}",
                  flush=True)
    bad = [k for k, r in out.items() if r["of_grid"] < 0.9]
    ratios = [r["of_grid"] for r in out.values()]
    print(f"{len(out)} panels; below 0.9 of their grid points: {bad}; of_grid min {min(ratios):.3f} max {max(ratios):.3f}")
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    main()

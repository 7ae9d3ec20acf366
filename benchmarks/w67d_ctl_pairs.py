"""The untiled hierarchy control of hie15_make.py --untiled (seeded at the tiled world's four first-phase seed
points, rng = seed) again, saving each row's element and parent ids so that a twig pairs with its flower (one
rule success: the flower's element id is the twig's + 1, same parent). Checks x, y against the stored control.

``python benchmarks/w67d_ctl_pairs.py --tiles 32,33 [--seed 19] [--ref w67dctl]`` -> results/w67d_ctlpairs_sS_TT.npz
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--ref", default="w67dctl")
    args = ap.parse_args()
    from hie15_make import tiled_seed_points

    import strew
    from strew.ornament import grow_ornament

    for tile in [float(v) for v in args.tiles.split(",")]:
        side = 4 * tile
        arr = grow_ornament("hierarchy", strew.Region.rectangle(side, side), rng=args.seed, seeds=tiled_seed_points(tile))
        x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
        ref = HERE / "results" / f"orn19m_{args.ref}_s{args.seed}_T{tile:g}.npz"
        same = None
        if ref.exists():
            z = np.load(ref)
            same = bool(np.array_equal(z["x"], x) and np.array_equal(z["y"], y))
        np.savez_compressed(HERE / "results" / f"w67d_ctlpairs_s{args.seed}_T{tile:g}.npz", x=x, y=y,
                            kind=np.asarray(arr.kind), kinds=np.array(list(arr.kinds)),
                            element=np.asarray(arr["element"], np.int64), parent=np.asarray(arr["parent"], np.int64))
        print(f"T{tile:g}: {len(x)} el, equal to {ref.name}: {same}", flush=True)


if __name__ == "__main__":
    main()

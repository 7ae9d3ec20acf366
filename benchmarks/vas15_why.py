"""Why the vines' phase calls of a tiled vase world's later tiles fail (issue 19.4, vas15).

``PYTHONPATH=src python benchmarks/vas15_why.py TAG --tiles T [--seed S] [--untiled]`` grows the
world and records every call of ``vase.grow_vine``: the tile, the goal (x, y, radius), the
parent's type and whether it is a context element, the grid point chosen (or none) and the
outcome: 0 success, 1 no free grid point within reach, 2 the grid point too far from the goal,
3 the flower hits an element or leaves the panel, 4 the vine too short, 5 the vine hits an
element or leaves the panel. Saved to ``benchmarks/results/vas15_why_<TAG>_T<T>.npz``.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tag")
    ap.add_argument("--tiles", type=float, required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--untiled", action="store_true")
    args = ap.parse_args()
    import strew
    import strew.tiles as T
    from strew.ornament.patterns import vase as V

    cur = {"tile": -1}
    orig_rng = T.tile_rng

    def tile_rng(seed, index):
        cur["tile"] = int(index)
        return orig_rng(seed, index)

    T.tile_rng = tile_rng
    rows: list = []
    orig = V.grow_vine
    ptypes = ["seed", "vine", "lotus", "peony"]

    def grow_vine(ctx, parent, start, tangent, depth):
        g, rho = ctx.goal.center, ctx.goal.radius
        found = V._free_grid_point(ctx, g, start)
        far = float(np.hypot(*(g - start)))
        if found is None and far > V.REACH - V.GRID:
            found = V._free_grid_point(ctx, start + (V.REACH - V.GRID) / far * (g - start), start)
        why, ij = -1, (-99, -99)
        if found is None:
            why = 1
        else:
            _, ij, p = found
            if float(np.hypot(*(p - g))) > rho + 0.5 * V.GRID or float(np.hypot(*(p - start))) > V.REACH:
                why = 2
        r = orig(ctx, parent, start, tangent, depth)
        if r:
            why = 0
        elif why < 0:
            why = 5  # 3, 4 folded in: the flower or the vine
        rows.append((cur["tile"], float(g[0]), float(g[1]), float(rho), ptypes.index(parent.type), bool(getattr(parent, "context", False)),
                     ij[0], ij[1], why, float(start[0]), float(start[1])))
        return r

    V.grow_vine = grow_vine
    side = 4 * args.tiles
    if args.untiled:
        from strew.ornament import grow_ornament

        grow_ornament("vase", strew.Region.rectangle(side, side), rng=args.seed)
    else:
        T.tiled("ornament", "vase", (side, side), tile_size=args.tiles, seed=args.seed)
    a = np.array(rows, float)
    path = RES / f"vas15_why_{args.tag}_T{args.tiles:g}.npz"
    np.savez_compressed(path, rows=a, meta=np.array([side, args.tiles, args.seed]))
    print(f"{len(a)} grow_vine calls -> {path.name}; outcomes {np.bincount(a[:, 8].astype(int), minlength=6).tolist()}")


if __name__ == "__main__":
    main()

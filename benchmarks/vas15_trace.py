"""Every vine of a tiled vase world and of its untiled control, traced (issue 19.4, vas15).

``PYTHONPATH=src python benchmarks/vas15_trace.py make --tag TAG --tiles T [--seed S] [--untiled]``
grows the world as ``benchmarks/orn19m_willow.py make --pattern vase`` does and saves to
``benchmarks/results/vas15_<tag>_T<T>.npz`` every vine a run grew: its Bézier points, the
grid point of the flower it delivered (i, j), its parent's type and whether the parent was a
context element (a finished neighbour's), the tile that grew it, and whether the world kept
it (a tile's ``_keep_groups``); per run the order of the vines' successes.

``benchmarks/vas15_cross.py`` reads them.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def make(args) -> None:
    import strew.tiles as T
    from strew.ornament.patterns import vase

    cur = {"tile": -1}
    grown: list = []  # (tile, p0x, p0y, p1.., p3y, fi, fj, parent type, parent context, depth)
    kept_keys: set = set()
    all_keys: set = set()
    orig_rng = T.tile_rng

    def tile_rng(seed, index):
        cur["tile"] = int(index)
        return orig_rng(seed, index)

    T.tile_rng = tile_rng
    orig_vine = vase.grow_vine
    ptypes = ["seed", "vine", "lotus", "peony"]

    def grow_vine(ctx, parent, start, tangent, depth):
        n0 = len(ctx.state.flowers)
        r = orig_vine(ctx, parent, start, tangent, depth)
        if r and len(ctx.state.flowers) > n0:
            ij = ctx.state.flowers[-1]
            # the vine is the last child placed: find it among the context's new children
            grown.append((cur["tile"], float(start[0]), float(start[1]), ij[0], ij[1], ptypes.index(parent.type),
                          bool(getattr(parent, "context", False)), depth, float(ctx.goal.center[0]), float(ctx.goal.center[1]),
                          float(ctx.goal.radius)))
        return r

    vase.grow_vine = grow_vine
    orig_keep = T._keep_groups

    def key(pts):
        return tuple(np.round(np.asarray(pts, float).ravel()[:2], 6))

    def vine_keys(arr, mask):
        out = []
        recs = arr["ornament_proxies"]
        for i in np.flatnonzero(mask):
            for rec in recs[i] or ():
                if rec[0] == "vine":
                    out.append((int(arr["tile_index"][i]) if "tile_index" in arr.columns else cur["tile"], key(dict(rec[4][0])["points"])))
        return out

    def keep_groups(arr, keep, t, job, links):
        k = orig_keep(arr, keep, t, job, links)
        for tk in vine_keys(arr, np.ones(len(arr), bool)):
            all_keys.add(tk)
        for tk in vine_keys(arr, k):
            kept_keys.add(tk)
        return k

    T._keep_groups = keep_groups
    if args.halo:
        # a halo other than the default (a quarter tile): the world's call, with it
        plain = T.tiled

        def tiled_halo(*a, **k):
            return plain(*a, halo=args.halo, **k)

        T.tiled = tiled_halo
    # the world itself, saved as orn19m_willow.py make saves it (tag vas15_TAG)
    import orn19m_willow

    orn19m_willow.make(argparse.Namespace(set=args.set, tiles=f"{args.tiles:g}", untiled=args.untiled, pattern="vase", seed=args.seed,
                                          tag=f"vas15_{args.tag}", overlaps=args.overlaps))
    g = np.array([row[:10] for row in grown], float) if grown else np.zeros((0, 10))
    gr = np.array([row[10] for row in grown], float)
    # kept: by the vine's start point and tile (a tiled run); every vine of the untiled run
    kept = np.ones(len(g), bool)
    if not args.untiled:
        ks = {(t, k) for t, k in kept_keys}
        kept = np.array([(int(r[0]), key(r[1:3])) in ks for r in g], bool)
        # sanity: every grown vine is one _keep_groups saw
        seen = {(t, k) for t, k in all_keys}
        miss = sum((int(r[0]), key(r[1:3])) not in seen for r in g)
        print(f"vines grown {len(g)}, seen by _keep_groups {len(all_keys)}, unmatched {miss}, kept {int(kept.sum())}")
    side = 4 * args.tiles
    path = RES / f"vas15_{args.tag}_T{args.tiles:g}.npz"
    np.savez_compressed(path, g=g, goal_r=gr, kept=kept, meta=np.array([side, args.tiles, args.seed]))
    print(f"-> {path.name}: {len(g)} vines, kept {int(kept.sum())}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    m = sub.add_parser("make")
    m.add_argument("--tag", required=True)
    m.add_argument("--tiles", type=float, required=True)
    m.add_argument("--seed", type=int, default=1)
    m.add_argument("--untiled", action="store_true")
    m.add_argument("--overlaps", action="store_true")
    m.add_argument("--halo", type=float, default=None)
    m.add_argument("--set", action="append", default=[], help="NAME=VALUE: a module constant of strew.tiles or strew.ornament._context")
    args = ap.parse_args()
    make(args)


if __name__ == "__main__":
    main()

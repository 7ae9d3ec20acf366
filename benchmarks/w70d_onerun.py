"""Diagnostic (issue 19 point 4, helper w70d): a tiled world's vine structure, the later phases grown over it in ONE
untiled run. ``PYTHONPATH=SRC:benchmarks python benchmarks/w70d_onerun.py --tag TAG --tiles 40,... [--set NAME=VALUE]``
runs the tiled hierarchy world (seed 19, 4 x 4 tiles; _VINES_FIRST's sweep 0 recorded per tile), takes every tile's
first-sweep result (the vines, as kept) as the context of one grow_ornament run over the whole world with the phases
after the first (flowers, leaves, fillers; rng seed 19), and saves vines + that run as
benchmarks/results/orn19m_TAG_s19_TT.npz (the format of orn19m_willow.make, no dropped rows): if its border twigs
equal the tiled world's, the second sweep's tiling loses nothing and the twig shares are the vine structure's."""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--tag", required=True)
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--set", action="append", default=[])
    args = ap.parse_args()
    import orn19m_willow as W
    import strew
    import strew.ornament as O
    import strew.tiles as T
    from strew.arrangement import concat

    sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))
    from world_stats import overlapping_pairs

    for kv in args.set:
        name, _, val = kv.partition("=")
        setattr(T, name, type(getattr(T, name))(val))
    assert T._VINES_FIRST
    firsts: list = []
    orig = T._combine

    def combine(t, first, later):
        firsts.append(first)
        return orig(t, first, later)

    T._combine = combine
    for tile in [float(v) for v in args.tiles.split(",")]:
        firsts.clear()
        side = 4 * tile
        t0 = time.process_time()
        T.tiled("ornament", "hierarchy", (side, side), tile_size=tile, seed=19)
        vines = concat(T._harmonize([f for f in firsts if len(f)]))
        later = O.grow_ornament("hierarchy", strew.Region.rectangle(side, side), context=vines, rng=19, _tiled=True, _phases=(1, 4))
        pub = [a.without_columns(*[c for c in a.columns if c.startswith("ornament_")]) for a in (vines, later)]
        arr = concat(T._harmonize(pub))
        cpu = time.process_time() - t0
        ovl = int(overlapping_pairs(arr))
        kinds = list(arr.kinds)
        path = HERE / "results" / f"orn19m_{args.tag}_s19_T{tile:g}.npz"
        np.savez_compressed(path, x=np.asarray(arr.x, float), y=np.asarray(arr.y, float), kind=np.asarray(arr.kind), kinds=np.array(kinds),
                            tile=np.full(len(arr), -1), group=np.full(len(arr), -1), chord=W._chord(arr), goal_r=np.full(len(arr), np.nan),
                            dx=np.zeros(0), dy=np.zeros(0), dkind=np.zeros(0, np.int64), dtile=np.zeros(0, np.int64),
                            meta=np.array([side, tile, tile / 4, cpu]), overlaps=ovl)
        print(f"{args.tag} T {tile:g}: {len(vines)} vines-sweep rows + {len(later)} one-run rows = {len(arr):,} el, overlaps {ovl}, "
              f"{cpu:.1f} CPU s -> {path.name}", flush=True)


if __name__ == "__main__":
    main()

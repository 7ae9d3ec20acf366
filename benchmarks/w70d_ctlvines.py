"""Diagnostic (issue 19 point 4, helper w70d), the converse of w70d_onerun.py: the untiled control's vine structure
(one vines-phase run over the whole world from the tiled world's four seed points, hie15_make's control), each tile
given the control's vines it owns as its sweep-0 result, then the tiled second sweep of _VINES_FIRST (every later
phase, tile by tile, all keep rules). ``PYTHONPATH=SRC:benchmarks python benchmarks/w70d_ctlvines.py --tag TAG --tiles
40,...`` saves benchmarks/results/orn19m_TAG_s19_TT.npz (orn19m_willow.make's format, no dropped rows): if its border
twigs equal the control's, a tiled sweep 1 on the control's vines loses nothing."""
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
    args = ap.parse_args()
    import orn19m_willow as W
    from hie15_make import tiled_seed_points

    import strew
    import strew.ornament as O
    import strew.tiles as T

    sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))
    from world_stats import overlapping_pairs

    T._VINES_FIRST = 1
    orig = T.run_tile
    state: dict = {}

    def run_tile(job, t, *nb, vines=None):
        if job.sweep != 0:
            return orig(job, t, *nb, vines=vines)
        v = state["vines"]
        own = T._owner(np.asarray(v.x, float), np.asarray(v.y, float), job) == t.index
        return v.select(own).replace(meta={"tile": t.index}, region=None)

    T.run_tile = run_tile
    for tile in [float(s) for s in args.tiles.split(",")]:
        side = 4 * tile
        t0 = time.process_time()
        v = O.grow_ornament("hierarchy", strew.Region.rectangle(side, side), rng=19, seeds=tiled_seed_points(tile), _tiled=True, _phases=(0, 1))
        state["vines"] = v.replace(region=None)
        arr = T.tiled("ornament", "hierarchy", (side, side), tile_size=tile, seed=19)
        arr = arr.without_columns(*[c for c in arr.columns if c.startswith("ornament_")])
        cpu = time.process_time() - t0
        ovl = int(overlapping_pairs(arr))
        kinds = list(arr.kinds)
        path = HERE / "results" / f"orn19m_{args.tag}_s19_T{tile:g}.npz"
        np.savez_compressed(path, x=np.asarray(arr.x, float), y=np.asarray(arr.y, float), kind=np.asarray(arr.kind), kinds=np.array(kinds),
                            tile=np.asarray(arr["tile"]), group=np.full(len(arr), -1), chord=W._chord(arr), goal_r=np.full(len(arr), np.nan),
                            dx=np.zeros(0), dy=np.zeros(0), dkind=np.zeros(0, np.int64), dtile=np.zeros(0, np.int64),
                            meta=np.array([side, tile, tile / 4, cpu]), overlaps=ovl)
        print(f"{args.tag} T {tile:g}: {len(v)} control vines-phase rows; tiled world {len(arr):,} el, overlaps {ovl}, {cpu:.1f} CPU s -> {path.name}", flush=True)


if __name__ == "__main__":
    main()

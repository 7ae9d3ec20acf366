"""The vase's flower grid points left without a flower (issue 19.4, vaf16).

``python benchmarks/vaf16_holes.py world NPZ [NPZ ...] [--json F]`` reads saved worlds
(``benchmarks/results/orn19m_*.npz``, as ``orn19m_willow.py make --pattern vase`` and
``vas15_trace.py make`` write them) and lists every grid point (vase.GRID) whose flower fits
in the world and that holds no lotus or peony, with its distance to the nearest tile seed
(the centre of the tile's region with its halo, clipped to the world; the world's centre
untiled).

``PYTHONPATH=TREE/src python benchmarks/vaf16_holes.py panel SIDE [SIDE ...] [--seed S]``
grows untiled square panels (the vines' phase, min_radius 5, as vas19x_sizes.py) and lists
the same, with the distance to the seed (the panel's centre), and the panel's digest
(spi19p_identity.digest) to compare two trees.

At f1671ca a grid point within MIN_VINE of a seed stayed empty: untiled 221 / 225 / 227 /
229.2 (seed 0.7 / 3.5 / 4.9 / 6.5 from (5, 5)), 264 (the seed on (6, 6)); tiled T60 s1
(7, 7) (5.66 from tile 10's seed), T72 s1 (2, 2), (2, 8), (8, 2), (8, 8) (1.41 / 4.12 /
4.12 / 5.66 from a tile's seed).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
GRID, FR = 22.0, 6.0


def _holes(fx, fy, side, seeds):
    have = {(round(a / GRID), round(b / GRID)) for a, b in zip(fx, fy)}
    pts = [i for i in range(int(side // GRID) + 2) if FR <= i * GRID <= side - FR]
    out = []
    for i in pts:
        for j in pts:
            if (i, j) not in have:
                d = float(np.min(np.hypot(seeds[:, 0] - i * GRID, seeds[:, 1] - j * GRID)))
                out.append([i, j, round(d, 2)])
    return len(pts) ** 2, out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mode", choices=["world", "panel"])
    ap.add_argument("items", nargs="+")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    res = {}
    if args.mode == "world":
        for p in args.items:
            z = np.load(p, allow_pickle=False)
            side, tile = float(z["meta"][0]), float(z["meta"][1])
            kinds = [str(k) for k in z["kinds"]]
            fl = np.isin(z["kind"], [kinds.index("lotus"), kinds.index("peony")])
            tiled = tile < side
            # a tile's seed: the centre of its region, the tile grown by the halo and clipped
            # to the world (edge tiles' seeds lie halo / 2 in from the tile's centre); an
            # untiled world's seed is its centre
            if tiled:
                n, h = round(side / tile), float(z["meta"][2])
                c = [(max(0.0, a * tile - h) + min(side, (a + 1) * tile + h)) / 2 for a in range(n)]
                seeds = np.array([(a, b) for a in c for b in c])
            else:
                seeds = np.array([[side / 2, side / 2]])
            tot, h = _holes(z["x"][fl], z["y"][fl], side, seeds)
            res[Path(p).name] = {"grid_points": tot, "flowers": int(fl.sum()), "holes": h}
            print(f"{Path(p).name}: {tot} grid points, {int(fl.sum())} flowers, no flower at {h} (i, j, to a tile's seed)",
                  flush=True)
    else:
        from spi19p_identity import digest

        import strew
        from strew.ornament import grow_ornament

        for s in args.items:
            side = float(s)
            arr = grow_ornament("vase", strew.Region.rectangle(side, side), rng=args.seed, min_radius=5.0)
            kinds = list(arr.kinds)
            fl = np.isin(np.asarray(arr.kind), [kinds.index("lotus"), kinds.index("peony")])
            xy = np.asarray(arr.xy)[fl]
            tot, h = _holes(xy[:, 0], xy[:, 1], side, np.array([[side / 2, side / 2]]))
            dg = digest(arr)
            res[f"{s}_s{args.seed}"] = {"grid_points": tot, "flowers": int(fl.sum()), "holes": h, "digest": dg}
            print(f"{s} s{args.seed}: {tot} grid points, {int(fl.sum())} flowers, no flower at {h} (i, j, to the seed) {dg}",
                  flush=True)
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()

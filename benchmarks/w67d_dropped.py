"""What the tiles drop near the inner borders, by kind and signed distance (issue 19.4 point 4, helper w67d).

``python benchmarks/w67d_dropped.py --tiled w67dM --control w67dctl --tiles ... [--seed 19]``
orn19m_willow.make records every row a tile's keep-rule drops (dx, dy, dkind, dtile). Per 1 s bin of the signed
distance (negative: the earlier tile's side), pooled over worlds: the tiled world's count per kind, the control's,
and the rows dropped there by the tile on the earlier side (the finished tile: dtile's own unit is that side's).
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
    ap = argparse.ArgumentParser()
    ap.add_argument("--tiled", default="w67dM")
    ap.add_argument("--control", default="w67dctl")
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    args = ap.parse_args()
    import orn19m_willow as W

    edges = np.arange(-3.0, 3.01, 1.0)
    kinds = None
    acc = None
    for tile in args.tiles.split(","):
        pt, pc = (RES / f"orn19m_{t}_s{args.seed}_T{tile}.npz" for t in (args.tiled, args.control))
        if not (pt.exists() and pc.exists()):
            continue
        w, c = W._world(pt), W._world(pc)
        kinds = w["kinds"]
        nk = len(kinds)
        if acc is None:
            acc = np.zeros((6, len(edges) - 1, nk))
        bw, bc = np.digitize(w["sd"], edges) - 1, np.digitize(c["sd"], edges) - 1
        # the dropped rows' signed distance in the tiled world's s
        bd = np.digitize(w["dsd"], edges) - 1
        dt = np.asarray(np.load(pt)["dtile"], np.int64)
        i, j = dt % 4, dt // 4
        dph = (j % 2) * 2 + i % 2
        ui, uj = w["dunit"] % 4, w["dunit"] // 4
        uph = (uj % 2) * 2 + ui % 2
        pl = np.asarray(w["placer"], np.int64)
        pph = ((pl // 4) % 2) * 2 + (pl % 4) % 2
        eph = ((w["unit"] // 4) % 2) * 2 + (w["unit"] % 4) % 2
        by_earlier, by_later = pph < eph, pph > eph  # placed by a tile that ran before / after the one it lies in
        own_side = dt == w["dunit"]  # dropped by the tile they lie in
        earlier = dph < uph  # dropped by a tile that ran before the one they lie in
        for k in range(len(edges) - 1):
            acc[0, k] += np.bincount(w["kind"][w["inside"] & (bw == k)], minlength=nk)
            acc[1, k] += np.bincount(c["kind"][c["inside"] & (bc == k)], minlength=nk)
            acc[4, k] += np.bincount(w["kind"][w["inside"] & (bw == k) & by_earlier], minlength=nk)
            acc[5, k] += np.bincount(w["kind"][w["inside"] & (bw == k) & by_later], minlength=nk)
            m = w["dinside"] & (bd == k) & (w["dkind"] >= 0)
            acc[2, k] += np.bincount(w["dkind"][m & own_side], minlength=nk)
            acc[3, k] += np.bincount(w["dkind"][m & earlier], minlength=nk)
    print(f"kinds {kinds}; per 1 s bin of signed distance (negative: the finished tile's side)")
    for k in range(len(edges) - 1):
        print(f"  [{edges[k]:+.0f},{edges[k + 1]:+.0f})  tiled {acc[0, k].astype(int)}  control {acc[1, k].astype(int)}"
              f"  dropped by the tile they lie in {acc[2, k].astype(int)}  by an earlier tile (its halo) {acc[3, k].astype(int)}"
              f"  | tiled rows placed by an earlier tile {acc[4, k].astype(int)}, by a later tile {acc[5, k].astype(int)}")


if __name__ == "__main__":
    main()

"""Tiled hierarchy worlds: density per kind by signed distance to the inner borders, and who
placed it (issue 19.4, helper wld17).

``python benchmarks/wld17_profile.py TAG[,TAG...] [--tiles 48,52,56,60,64,68] [--seed 1]``
reads ``benchmarks/results/orn19m_TAG_sS_TT.npz`` (benchmarks/hie15_make.py) and prints,
per bin of 0.5 s (s the world's mean spacing; negative on the finished side, 2 x 2 phases),
the density of every element and of each kind against the world's interior (at least 3 s
from every inner border), pooled over the tile sizes; for a tiled world also the density
of the elements placed by the tile that holds them (``own``) and by a neighbour's run
through its halo (``other``).
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
    ap.add_argument("tags")
    ap.add_argument("--tiles", default="48,52,56,60,64,68")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    from orn19m_willow import _world

    edges = np.arange(-3.0, 3.001, 0.5)
    nb = len(edges) - 1
    for tag in args.tags.split(","):
        cnt = area = ic = None
        ia = 0.0
        own = np.zeros(nb)
        oth = np.zeros(nb)
        kinds: list[str] = []
        for tile in args.tiles.split(","):
            w = _world(RES / f"orn19m_{tag}_s{args.seed}_T{float(tile):g}.npz")
            kinds = w["kinds"]
            nk = len(kinds)
            if cnt is None:
                cnt, area, ic = np.zeros((nb, nk + 1)), np.zeros(nb), np.zeros(nk + 1)
            ins = w["inside"]
            b = np.digitize(w["sd"], edges) - 1
            gb = np.digitize(w["gsd"], edges) - 1
            for k in range(nb):
                s = ins & (b == k) & (w["d"] < 3)
                cnt[k, 0] += s.sum()
                cnt[k, 1:] += np.bincount(w["kind"][s], minlength=nk)
                own[k] += (s & ~w["other"]).sum()
                oth[k] += (s & w["other"]).sum()
                area[k] += ((gb == k) & (w["gd"] < 3)).sum() * w["garea"]
            i = ins & (w["d"] >= 3)
            ic[0] += i.sum()
            ic[1:] += np.bincount(w["kind"][i], minlength=nk)
            ia += (w["gd"] >= 3).sum() * w["garea"]
        print(f"== {tag}: density / interior's by signed distance (s); columns all, {', '.join(kinds)}, own, other")
        for k in range(nb):
            r = (cnt[k] / area[k]) / (ic / ia)
            po = own[k] / area[k] / (ic[0] / ia)
            pt = oth[k] / area[k] / (ic[0] / ia)
            print(f"  {edges[k]:+.1f}..{edges[k + 1]:+.1f} " + " ".join(f"{v:5.2f}" for v in r) + f"  | {po:5.2f} {pt:5.2f}")


if __name__ == "__main__":
    main()

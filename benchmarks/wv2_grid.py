"""The vase's flower grid in a world of benchmarks/hie15_make.py (helper wv2, issue 19.4):
how many grid points (spacing vase.GRID, in the world; those a flower of radius
FLOWER_RADIUS fits at inside it) hold a lotus or peony centred within 0.5 of them, the
missing ones (i, j), flowers off the grid, and the vines and flowers per world.

``PYTHONPATH=src python benchmarks/wv2_grid.py TAG_sS_TT [TAG_sS_TT ...]`` (worlds
benchmarks/results/orn19m_TAG_sS_TT.npz)
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from strew.ornament.patterns import vase

RES = Path(__file__).resolve().parent / "results"


def main() -> None:
    for name in sys.argv[1:]:
        d = np.load(RES / f"orn19m_{name}.npz")
        kinds = [str(k) for k in d["kinds"]]
        side = 4 * float(name.rsplit("_T", 1)[1])
        kk = np.asarray(d["kind"])
        fl = np.isin(kk, [kinds.index("lotus"), kinds.index("peony")])
        fx, fy = np.asarray(d["x"])[fl], np.asarray(d["y"])[fl]
        g = np.arange(0.0, side + 1e-9, vase.GRID)
        pts = [(i, j) for i, x in enumerate(g) for j, y in enumerate(g)
               if vase.FLOWER_RADIUS <= x <= side - vase.FLOWER_RADIUS and vase.FLOWER_RADIUS <= y <= side - vase.FLOWER_RADIUS]
        held, missing = 0, []
        for i, j in pts:
            if (np.hypot(fx - g[i], fy - g[j]) < 0.5).any():
                held += 1
            else:
                missing.append((i, j))
        gi, gj = np.round(fx / vase.GRID), np.round(fy / vase.GRID)
        off = int((np.hypot(fx - gi * vase.GRID, fy - gj * vase.GRID) >= 0.5).sum())
        print(f"{name}: flowers {int(fl.sum())}, grid points held {held}/{len(pts)}, missing {missing}, off grid {off}, "
              f"vines {int((kk == kinds.index('vine')).sum())}, elements {len(kk)}, overlaps {int(d['overlaps'])}")


if __name__ == "__main__":
    main()

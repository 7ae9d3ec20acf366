"""The vines phase's successful tries near the inner borders: the phase-0 tiles' runs (no context) against the
untiled control (issue 19.4 point 4, helper w67d).

``python benchmarks/w67d_vinetries.py --tiled w67dM --control w67dctl --tiles ... [--seed 19]``
hie15_make.py's tries (results/hie15_tries_TAG_sS_TT.npz). Per 1 s bin of the signed distance of the circle's
centre to the nearest inner border (negative: the earlier tile's side): successes, their mean circle radius (s)
and mean rank in the run's vines phase (0 first, 1 last). Tiled: the runs without context only (the four
phase-0 tiles, each grown alone over its tile and halo; the borders in reach are all with later tiles).
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
    from orn19m_willow import _sd

    edges = np.arange(-3.0, 3.01, 1.0)
    for tag, ctxless in ((args.tiled, True), (args.control, False)):
        acc = np.zeros((len(edges) - 1, 3))
        for tile in args.tiles.split(","):
            p = RES / f"hie15_tries_{tag}_s{args.seed}_T{tile}.npz"
            w = RES / f"orn19m_{tag}_s{args.seed}_T{tile}.npz"
            if not (p.exists() and w.exists()):
                continue
            z, zw = np.load(p), np.load(w)
            side, T, _halo, _ = zw["meta"]
            s = side / np.sqrt(len(zw["x"]))
            num = z["num"]
            m = (num[:, 0] == list(z["phases"]).index("vines")) & (num[:, 7] > 0)
            if ctxless:
                m &= num[:, 6] == 0
            x, y = num[:, 1], num[:, 2]
            _, sd = _sd(x, y, side, T)
            sd = sd / s
            b = np.digitize(sd, edges) - 1
            for run in np.unique(num[m, 5]):
                q = np.flatnonzero(m & (num[:, 5] == run))
                rank = np.linspace(0, 1, len(q)) if len(q) > 1 else np.zeros(len(q))
                for k in range(len(edges) - 1):
                    sel = b[q] == k
                    acc[k] += [sel.sum(), num[q[sel], 3].sum() / s, rank[sel].sum()]
        print(f"\n{tag}{' (phase-0 runs)' if ctxless else ''}: vines-phase successes by signed distance (s)")
        for k in range(len(edges) - 1):
            n = max(acc[k, 0], 1)
            print(f"  [{edges[k]:+.0f},{edges[k + 1]:+.0f})  n {acc[k, 0]:5.0f}  mean r {acc[k, 1] / n:.2f} s  mean rank {acc[k, 2] / n:.2f}")


if __name__ == "__main__":
    main()

"""Each kind's density per area by signed distance to the nearest inner border, tiled variants over the untiled
control, same worlds and lines (issue 19.4 point 4, helper w67d): no interior is needed.

``python benchmarks/w67d_bins.py --control w67dctl --variants w67dM,w67dP --tiles ... [--seed 19] [--step 0.5]``
Negative distances: the earlier (finished) tile's side (orn19m_willow._sd); the world's edge band left out.
Pooled counts; 95 % bootstrap over tile sizes for the ratio to the control.
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
    ap.add_argument("--control", default="w67dctl")
    ap.add_argument("--variants", default="w67dM")
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--step", type=float, default=0.5)
    ap.add_argument("--boot", type=int, default=2000)
    args = ap.parse_args()
    import orn19m_willow as W

    tags = [args.control, *args.variants.split(",")]
    edges = np.r_[-np.inf, np.arange(-3.0, 3.0 + 1e-9, args.step), np.inf]
    C = []  # (worlds, tags, bins, 1 + kinds): area, counts per kind
    kinds = None
    for tile in args.tiles.split(","):
        ps = [RES / f"orn19m_{t}_s{args.seed}_T{tile}.npz" for t in tags]
        if not all(p.exists() for p in ps):
            continue
        rows = []
        for p in ps:
            w = W._world(p)
            kinds = w["kinds"]
            nk = len(kinds)
            # the control's lattice uses the control's own s: use the first world's s for every variant of a size
            b = np.digitize(w["sd"], edges) - 1
            gb = np.digitize(w["gsd"], edges) - 1
            a = np.zeros((len(edges) - 1, 1 + nk))
            for k in range(len(edges) - 1):
                m = w["inside"] & (b == k)
                a[k, 0] = (gb == k).sum() * w["garea"]
                a[k, 1:] = np.bincount(w["kind"][m], minlength=nk)
            rows.append(a)
        C.append(rows)
    C = np.array(C)
    n = len(C)
    picks = np.random.default_rng(0).integers(0, n, (args.boot, n))
    print(f"{n} tile sizes; kinds {kinds}; bins of sd in s (own world's s); density ratio variant / control [95 %]")
    labels = ["all", *kinds]

    def dens(A):  # (tags, bins, 1 + k) -> (tags, bins, 1 + k) densities (all, per kind)
        tot = A[..., 1:].sum(-1, keepdims=True)
        return np.concatenate([tot, A[..., 1:]], -1) / A[..., :1]

    est = dens(C.sum(0))
    bt = np.array([dens(C[k].sum(0)) for k in picks])
    for j, t in enumerate(tags[1:], start=1):
        print(f"\n{t} / {args.control}")
        print("  bin (s)        " + " ".join(f"{lab:>22s}" for lab in labels))
        for k in range(len(edges) - 1):
            lo_, hi_ = edges[k], edges[k + 1]
            cells = []
            for li in range(len(labels)):
                r = est[j, k, li] / est[0, k, li]
                lo, hi = np.nanpercentile(bt[:, j, k, li] / bt[:, 0, k, li], [2.5, 97.5])
                cells.append(f"{r:6.3f} [{lo:5.2f},{hi:5.2f}]")
            print(f"  [{lo_:+5.1f},{hi_:+5.1f}) " + " ".join(f"{c:>22s}" for c in cells))


if __name__ == "__main__":
    main()

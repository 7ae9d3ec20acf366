"""w69d: who placed the vines near an inner border in a tiled hierarchy world (issue 19.4 point 4).

``python benchmarks/w69d_who.py --variants w67dM,w69dV,... --tiles 32,34,...`` (worlds of hie15_make, seed 19):
per 1 s bin of signed distance (orn19m_willow._sd, negative on the finished tile's side; s the world's mean
spacing; the world's edge band left out as in _world), the vines pooled over tile sizes and the share of them kept
by a tile other than the one whose rectangle holds their centre (the neighbour across the border grew them).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--variants", required=True)
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--kind", default="vine")
    args = ap.parse_args()
    from orn19m_willow import _sd

    edges = np.arange(-3, 4)
    for tag in args.variants.split(","):
        n = np.zeros(len(edges) - 1)
        other = np.zeros(len(edges) - 1)
        for t in args.tiles.split(","):
            z = np.load(HERE / "results" / f"orn19m_{tag}_s19_T{t}.npz", allow_pickle=False)
            side, tile, halo, _ = z["meta"]
            x, y = z["x"], z["y"]
            s = 1.0 / np.sqrt(len(x) / side**2)
            margin = max(halo, 3.0 * s)
            ok = (x >= margin) & (x <= side - margin) & (y >= margin) & (y <= side - margin)
            kinds = list(z["kinds"])
            ok &= z["kind"] == kinds.index(args.kind)
            _, sd = _sd(x, y, side, tile)
            owner = (np.clip(np.floor(y / tile), 0, 3) * 4 + np.clip(np.floor(x / tile), 0, 3)).astype(np.int64)
            b = np.digitize(sd / s, edges) - 1
            for k in range(len(edges) - 1):
                m = ok & (b == k)
                n[k] += m.sum()
                other[k] += (m & (z["tile"] != owner)).sum()
        cells = "  ".join(f"[{edges[k]:+d},{edges[k + 1]:+d}) {int(n[k]):5d} {other[k] / max(n[k], 1):.2f}" for k in range(len(edges) - 1))
        print(f"{tag:10s} {args.kind}s (count, share kept by the neighbour across): {cells}")


if __name__ == "__main__":
    main()

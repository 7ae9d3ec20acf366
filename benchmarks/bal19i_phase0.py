"""Phase-0 tiles of a tiled synth world alone (no context): each size class's share by
distance to the tile's border, against the tile's interior, for the modes of synth's
tile-only balance switch (``_grow.BALANCE_TILE``; helper bal19i, issue 19 point 4).

The world is ``benchmarks/worlds_strips.py``'s (2640 x 2640, tiles 440, default halo);
its inner phase-0 tiles (columns and rows 2 and 4) run as :func:`strew.tiles.run_tile`
runs them, with no neighbour. A kept element's distance to the nearest border of its
tile, in spacings ``s`` (positive inside), is binned; a class's share in a bin is
divided by its share beyond 6 s; 95 % interval: 1,000 bootstrap resamples of the tiles.
``python benchmarks/bal19i_phase0.py --modes off,cut,count,edge --seeds 1,2,3 --out F``.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

BINS = [(-2.0, 0.0), (0.0, 1.0), (1.0, 2.0), (2.0, 3.0), (3.0, 6.0)]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--modes", default="off,cut,count,edge")
    ap.add_argument("--seeds", default="1,2,3")
    ap.add_argument("--exemplar", default="three_sizes")
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    import strew.synth._grow as G
    from strew.tiles import _Job, plan, run_tile
    from strew_testing import fidelity_suite

    ex = fidelity_suite().make_exemplar(args.exemplar)
    side, tsize = 2640.0, 440.0
    tiles, nx, ny = plan((side, side), tsize)
    inner = [t for t in tiles if t.phase == 0 and t.i in (2, 4) and t.j in (2, 4)]
    out = {"command": " ".join(sys.argv), "modes": {}}
    for mode in args.modes.split(","):
        G.BALANCE_TILE = "" if mode == "off" else mode
        t0 = time.process_time()
        per = []  # per tile: (bins + interior, classes) counts
        names = None
        for seed in [int(v) for v in args.seeds.split(",")]:
            job = _Job("synth", ex, {"measure": False}, (side, side), tsize / 4.0, seed, (tsize, tsize), (nx, ny), False)
            for t in inner:
                arr = run_tile(job, t)
                names = list(arr.kinds)
                x0, y0, x1, y1 = t.rect
                d = np.minimum.reduce([arr.x - x0, x1 - arr.x, arr.y - y0, y1 - arr.y])
                inside = d >= 0
                s = 1.0 / np.sqrt(inside.sum() / (tsize * tsize))
                ds = d / s
                kind = np.asarray(arr.kind, np.int64)
                rows = [np.bincount(kind[(ds >= lo) & (ds < hi)], minlength=len(names)) for lo, hi in BINS]
                rows.append(np.bincount(kind[ds >= 6.0], minlength=len(names)))
                per.append(np.array(rows, float))
        P = np.array(per)  # (tiles, bins + 1, classes)
        rng = np.random.default_rng(0)

        def ratio(Q):
            tot = Q.sum(axis=0)
            share = tot / np.maximum(tot.sum(axis=1, keepdims=True), 1)
            return share[:-1] / share[-1]

        r = ratio(P)
        boot = np.array([ratio(P[rng.integers(0, len(P), len(P))]) for _ in range(1000)])
        lo, hi = np.percentile(boot, [2.5, 97.5], axis=0)
        cpu = time.process_time() - t0
        print(f"mode {mode!r}: {len(P)} tiles, {cpu:.0f} CPU s; share / share beyond 6 s [95 %]")
        for b, (a, z) in enumerate(BINS):
            print(f"  {a:+.0f}..{z:+.0f} s  " + "  ".join(f"{names[k]} {r[b, k]:.3f} [{lo[b, k]:.3f}, {hi[b, k]:.3f}]" for k in range(len(names))), flush=True)
        out["modes"][mode] = {"tiles": len(P), "bins": BINS, "kinds": names, "ratio": r.tolist(), "lo": lo.tolist(), "hi": hi.tolist(), "cpu_s": cpu}
    Path(args.out).write_text(json.dumps(out, indent=1) + "\n")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()

"""The twig share's double ratio split into its four factors (issue 19 point 4, helper w70d): absolute densities
tiled / control (pooled over the tile sizes given) of twigs and of all elements in the strip (|d| < w s) and in the
interior (own3: |d| >= 3 s; rest: |d| >= w s); share ratio = (strip twig / strip all) / (interior twig / interior all).
``python benchmarks/w70d_split.py --variants w67dM,w69dVK0O --tiles 32,34,... [--kinds twig,flower,vine]``"""
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
    ap.add_argument("--variants", required=True)
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--kinds", default="twig,flower,vine")
    ap.add_argument("--seed", type=int, default=19)
    args = ap.parse_args()
    import orn19m_willow as W
    import w70d_canon

    w70d_canon.install()
    from w60d_bias import counts

    tags = [args.control, *args.variants.split(",")]
    acc = {}
    kinds = None
    for tile in args.tiles.split(","):
        ps = [RES / f"orn19m_{t}_s{args.seed}_T{tile}.npz" for t in tags]
        if not all(p.exists() for p in ps):
            continue
        for t, p in zip(tags, ps):
            w = W._world(p)
            kinds = w["kinds"]
            for interior, width in (("own3", 2.0), ("rest", 1.0)):
                acc.setdefault((t, interior, width), 0)
                acc[(t, interior, width)] = acc[(t, interior, width)] + counts(w, width, interior)
    nk = len(kinds)
    for interior, width in (("own3", 2.0), ("rest", 1.0)):
        print(f"\n{interior} +-{width:g} s: tiled / control, absolute density (per area)")
        c = acc[(args.control, interior, width)]
        for t in tags[1:]:
            v = acc[(t, interior, width)]
            sa, ia = v[0] / c[0], v[1] / c[1]
            line = f"  {t:10s} all: strip {v[2] / c[2] / sa:.3f} interior {v[3] / c[3] / ia:.3f}"
            for k in args.kinds.split(","):
                j = kinds.index(k)
                ss, ii = v[4 + j] / c[4 + j] / sa, v[4 + nk + j] / c[4 + nk + j] / ia
                share = (ss / (v[2] / c[2] / sa)) / (ii / (v[3] / c[3] / ia))
                line += f" | {k}: strip {ss:.3f} interior {ii:.3f} share {share:.3f}"
            print(line)


if __name__ == "__main__":
    main()

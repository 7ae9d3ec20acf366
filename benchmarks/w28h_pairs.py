"""Each flower and its twig (one success of hierarchy's flower_on_twig) by distance to the
nearest inner border, tiled against the untiled control (issue 19.4, helper w28h).

``python benchmarks/w28h_pairs.py TILED:CONTROL [...] --tiles 40,44,48,52,56 [--seed 19]``

A flower's twig is the twig whose centre lies nearest the flower's (orn19m worlds keep no
parent column; checked against the tiled worlds' own groups, numbered per tile, the
share matched right is printed). Per band of the flower's |d| / s (s the mean spacing;
orn19m_willow._world): the flowers, the share whose twig lies nearer the border than the
flower (the success points away from it), the twig's mean |d|, and the counts of twigs and
flowers in the band.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def pairs(f: Path, W) -> tuple[np.ndarray, float]:
    w = W._world(f)
    z = np.load(f)
    k = w["kinds"]
    fl = np.flatnonzero(w["kind"] == k.index("flower"))
    tw = np.flatnonzero(w["kind"] == k.index("twig"))
    d2 = (w["x"][fl, None] - w["x"][tw]) ** 2 + (w["y"][fl, None] - w["y"][tw]) ** 2
    j = tw[np.argmin(d2, axis=1)]
    right = np.nan
    if (z["group"] >= 0).any():
        key = list(zip(z["tile"].tolist(), z["group"].tolist()))
        right = float(np.mean([key[a] == key[b] for a, b in zip(fl, j)]))
    return np.c_[w["d"][fl], w["d"][j], w["inside"][fl]], right


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pairs", nargs="+")
    ap.add_argument("--tiles", default="40,44,48,52,56")
    ap.add_argument("--seed", type=int, default=19)
    args = ap.parse_args()
    import orn19m_willow as W

    acc: dict = {"tiled": [], "control": []}
    rights = []
    for pr in args.pairs:
        tt, ct = pr.split(":")
        for tile in args.tiles.split(","):
            p, q = RES / f"orn19m_{tt}_s{args.seed}_T{tile}.npz", RES / f"orn19m_{ct}_s{args.seed}_T{tile}.npz"
            if not (p.exists() and q.exists()):
                continue
            a, r = pairs(p, W)
            acc["tiled"].append(a)
            rights.append(r)
            acc["control"].append(pairs(q, W)[0])
    print(f"nearest twig = the flower's own (tiled groups): {np.nanmean(rights):.3f}")
    for name, v in acc.items():
        v = np.concatenate(v)
        v = v[v[:, 2] > 0]
        print(name)
        for lo, hi in ((0, 1), (1, 2), (2, 3), (3, np.inf)):
            m = (v[:, 0] >= lo) & (v[:, 0] < hi)
            tin = ((v[:, 1] >= lo) & (v[:, 1] < hi)).sum()
            print(f"  flower |d| {lo}..{hi}: flowers {m.sum():4d}, twig nearer the border {np.mean(v[m, 1] < v[m, 0]):.2f}, "
                  f"twig |d| mean {np.mean(v[m, 1][np.isfinite(v[m, 1])]):.2f}, twigs centred in the band {tin}")


if __name__ == "__main__":
    main()

"""Paired double ratio for several tiled variants against one untiled control (issue 19.4 point 4, helper w67d).

``python benchmarks/w67d_judge.py --control w67dctl --variants w67dM,w67dP --tiles 32,32.5,... [--seed 19]
[--boot 4000] [--json F]``

For each tile size: the tiled worlds of every variant and the untiled control (hie15_make.py; the control one run
seeded at the tiled world's four first-phase seed points) measured on the same lines with
benchmarks/w60d_bias.counts (strip |d| < w s against the interior: ``own3`` |d| >= 3 s, ``rest`` every other
centre). Per variant: strip/interior pooled over worlds (counts summed) and the double ratio variant / control;
per variant after the first: its double ratio over the first's (paired). 95 % percentile intervals from one
bootstrap over tile sizes (a draw takes the same worlds for every variant and the control). Overlaps per world.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--control", default="w67dctl")
    ap.add_argument("--variants", default="w67dM,w67dP")
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--boot", type=int, default=4000)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    import orn19m_willow as W
    from w60d_bias import counts, ratios

    tags = args.variants.split(",")
    worlds = []
    for tile in args.tiles.split(","):
        ps = [RES / f"orn19m_{t}_s{args.seed}_T{tile}.npz" for t in [args.control, *tags]]
        if not all(p.exists() for p in ps):
            print(f"T{tile}: missing {[p.name for p in ps if not p.exists()]}: skipped")
            continue
        worlds.append((tile, [W._world(p) for p in ps], [int(np.load(p)["overlaps"]) for p in ps], [len(np.load(p)["x"]) for p in ps]))
    kinds = worlds[0][1][0]["kinds"]
    nk = len(kinds)
    labels = ["density"] + [f"{k}_share" for k in kinds]
    n = len(worlds)
    print(f"{n} tile sizes: {', '.join(w[0] for w in worlds)}")
    print("elements " + ", ".join(f"{t} {sum(w[3][i] for w in worlds)}" for i, t in enumerate([args.control, *tags])))
    print("overlaps " + ", ".join(f"{t} {sum(w[2][i] for w in worlds)}" for i, t in enumerate([args.control, *tags])))
    picks = np.random.default_rng(0).integers(0, n, (args.boot, n))
    out: dict = {"tiles": [w[0] for w in worlds], "kinds": kinds, "control": args.control, "variants": tags,
                 "elements": {w[0]: w[3] for w in worlds}, "overlaps": {w[0]: w[2] for w in worlds}, "measures": {}}
    for interior in ("own3", "rest"):
        for width in (2.0, 1.0):
            A = np.array([[counts(wv, width, interior) for wv in w[1]] for w in worlds])  # (n, 1 + v, m)
            est = np.array([ratios(A[:, j].sum(0), nk) for j in range(A.shape[1])])
            boot = np.array([[ratios(A[k, j].sum(0), nk) for j in range(A.shape[1])] for k in picks])
            key = f"{interior}_{width:g}s"
            res: dict = {}
            print(f"\n{key}: strip / interior pooled; variant / control (double ratio) [95 % over tile sizes]")
            for li, lab in enumerate(labels):
                row = {"control": float(est[0, li])}
                line = f"  {lab:13s} control {est[0, li]:.3f}"
                for j, t in enumerate(tags, start=1):
                    d = est[j, li] / est[0, li]
                    lo, hi = np.nanpercentile(boot[:, j, li] / boot[:, 0, li], [2.5, 97.5])
                    row[t] = float(est[j, li])
                    row[f"{t}/control"] = [float(d), float(lo), float(hi)]
                    line += f" | {t} {est[j, li]:.3f} /ctl {d:.3f} [{lo:.3f}, {hi:.3f}]"
                    if j > 1:
                        r = est[j, li] / est[1, li]
                        lo, hi = np.nanpercentile(boot[:, j, li] / boot[:, 1, li], [2.5, 97.5])
                        row[f"{t}/{tags[0]}"] = [float(r), float(lo), float(hi)]
                        line += f" /{tags[0]} {r:.3f} [{lo:.3f}, {hi:.3f}]"
                res[lab] = row
                print(line)
            out["measures"][key] = res
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")
        print(f"wrote {args.json}")


if __name__ == "__main__":
    main()

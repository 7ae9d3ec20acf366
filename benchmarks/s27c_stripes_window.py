"""Helper s27c (issue 13 point 2): what stripes' failing 50x window is made of (seed 3,
window (3,0) nn[bar>bar]): counts per kind and bar-to-bar nearest-neighbour deciles in the
window, over all windows of the map, and in the exemplar.

    PYTHONPATH=src python benchmarks/s27c_stripes_window.py [--name stripes] [--seed 3] [--window 3,0] [--kind bar]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--name", default="stripes")
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--window", default="3,0")
    ap.add_argument("--kind", default="bar")
    a = ap.parse_args()
    ex = fidelity_suite().make_exemplar(a.name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
    out = synthesize(ex, region, rng=a.seed, measure=False)
    rep = fidelity(ex, out, region, eq5=False)
    L = rep.local
    S = np.asarray(L["score"], float)
    i, j = (int(v) for v in a.window.split(","))
    side, step = float(L["window"]), float(L["step"])
    print(f"n={len(out)} exemplar n={len(ex)} (x50 = {50 * len(ex)}); map {S.shape}, side {side:.1f} step {step:.1f}, x0 {L['x0']:.1f} y0 {L['y0']:.1f}")

    def stats(arr, box):
        names = np.asarray(arr.kind_names)
        xy = arr.xy
        inside = (xy[:, 0] >= box[0]) & (xy[:, 0] < box[2]) & (xy[:, 1] >= box[1]) & (xy[:, 1] < box[3])
        kinds = {k: int(((names == k) & inside).sum()) for k in np.unique(names)}
        p = xy[names == a.kind]
        d, _ = cKDTree(p).query(p, k=2)
        m = inside[names == a.kind]
        return kinds, np.quantile(d[m, 1], np.linspace(0.1, 0.9, 9)) if m.sum() > 2 else None

    k, q = stats(ex, (x0, y0, x1, y1))
    print("exemplar", k, np.round(q, 2))
    rows = []
    for (ii, jj), s in np.ndenumerate(S):
        if not np.isfinite(s):
            continue
        bx, by = L["x0"] + jj * step, L["y0"] + ii * step
        k, q = stats(out, (bx, by, bx + side, by + side))
        rows.append((ii, jj, s, k, q))
        if (ii, jj) == (i, j) or s > 0.9:
            print(f"window ({ii},{jj}) score {s:.3f} {L['worst_metric'][ii][jj]} {k} {np.round(q, 2)}")
    cnt = np.array([sum(r[3].values()) for r in rows])
    bars = np.array([r[3].get(a.kind, 0) for r in rows])
    med = np.array([r[4][4] for r in rows if r[4] is not None])
    print(f"windows: elements {cnt.mean():.1f} sd {cnt.std():.1f}; {a.kind} {bars.mean():.1f} sd {bars.std():.1f}; {a.kind} nn median {med.mean():.2f} sd {med.std():.2f}")


if __name__ == "__main__":
    main()

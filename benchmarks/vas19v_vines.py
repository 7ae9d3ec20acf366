"""Vines in the border strips of a tiled vase world against its untiled control (issue 19.4, vas19v).

``python benchmarks/vas19v_vines.py TILED CONTROL [--width 1]`` reads the worlds of
``benchmarks/orn19m_willow.py make --pattern vase --tag TILED --tiles T`` (and ``--tag CONTROL
--untiled``) and prints, per tile size, the vines whose centre lies within ``width`` s of an
inner border (the world's edge band left out, as vas19s_compare.py): how many on the finished
(earlier) side and on the later side, in half-spacing bins, which tile placed them (the tile
holding the centre or the finished neighbour), and their goal radius (the empty circle their
rule success grew into); the flowers' phase against the strips (grid points of spacing
vase.GRID within the strips).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def _mean(a: np.ndarray) -> float:
    a = a[np.isfinite(a)]
    return float(a.mean()) if len(a) else float("nan")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tiled")
    ap.add_argument("control")
    ap.add_argument("--width", type=float, default=1.0)
    args = ap.parse_args()
    from orn19m_willow import _world

    for p in sorted(RES.glob(f"orn19m_{args.tiled}_T*.npz")):
        T = p.name.rsplit("_T", 1)[1][:-4]
        q = RES / f"orn19m_{args.control}_T{T}.npz"
        if not q.exists():
            continue
        print(f"T {T}")
        for name, path in (("tiled", p), ("control", q)):
            w = _world(path)
            z = np.load(path)
            k = w["kinds"].index("vine")
            v = (w["kind"] == k) & w["inside"]
            near = v & (w["d"] < args.width)
            gr = z["goal_r"]
            bins = np.arange(-args.width, args.width + 1e-9, 0.5)
            h = np.histogram(w["sd"][near], bins)[0]
            other = w["other"][near]
            print(f"  {name}: vines {int(v.sum())}, in +-{args.width:g} s {int(near.sum())}; by signed distance (s) "
                  + " ".join(f"{a:+.1f}..{b:+.1f}:{c}" for a, b, c in zip(bins[:-1], bins[1:], h))
                  + f"; placed by another tile than the centre's: {int(other.sum())}; goal r mean {_mean(gr[near]):.2f} (all vines {_mean(gr[v]):.2f})")
            for i in np.flatnonzero(near):
                print(f"     vine x {w['x'][i]:7.2f} y {w['y'][i]:7.2f} sd {w['sd'][i]:+.2f} s, unit {w['unit'][i]} placer {w['placer'][i]} goal r {gr[i]:.2f}")
            # flowers in the strips
            fl = np.isin(w["kind"], [w["kinds"].index(n) for n in ("lotus", "peony")]) & w["inside"]
            print(f"  {name}: flowers {int(fl.sum())}, in +-{args.width:g} s {int((fl & (w['d'] < args.width)).sum())}")
            if name == "tiled":
                print(f"  tiled: dropped rows {deep_drops(path)}")



def deep_drops(path: Path) -> dict:
    """The rows a tiled world's tiles grew and dropped (orn19m_willow.py's cut), by their
    distance to the nearest later tile (higher phase, the 2 x 2 order) in halos: those at a
    halo or more lie beyond every later tile's region, a hole no tile refills."""
    z = np.load(path)
    side, tile, halo, _ = z["meta"]
    n = int(round(side / tile))
    dx, dy, dt = z["dx"], z["dy"], z["dtile"].astype(int)
    d = np.full(len(dx), np.inf)
    for t in np.unique(dt):
        i, j = t % n, t // n
        ph = (j % 2) * 2 + i % 2
        m = dt == t
        for dj in (-1, 0, 1):
            for di in (-1, 0, 1):
                a, b = i + di, j + dj
                if not (di or dj) or not (0 <= a < n and 0 <= b < n) or (b % 2) * 2 + a % 2 <= ph:
                    continue
                x0, y0, x1, y1 = a * tile, b * tile, (a + 1) * tile, (b + 1) * tile
                e = np.hypot(np.maximum(np.maximum(x0 - dx[m], dx[m] - x1), 0), np.maximum(np.maximum(y0 - dy[m], dy[m] - y1), 0))
                d[m] = np.minimum(d[m], e)
    deep = d >= halo
    kinds = [str(k) for k in z["kinds"]]
    out = dict(dropped=int(len(dx)), deep=int(deep.sum()), halo=float(halo),
               deep_by_tile={int(t): int((deep & (dt == t)).sum()) for t in np.unique(dt[deep])},
               deep_by_kind={kinds[k]: int((deep & (z["dkind"] == k)).sum()) for k in np.unique(z["dkind"][deep]) if k >= 0})
    return out


if __name__ == "__main__":
    main()

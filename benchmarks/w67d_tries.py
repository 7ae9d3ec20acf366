"""The flowers phase's tries near the inner borders, tiled against the untiled control (issue 19.4 point 4, w67d).

``python benchmarks/w67d_tries.py --tiled w67dM --control w67dctl --tiles 32.5,34,... [--seed 19]``

hie15_make.py writes every empty circle a run tries (results/hie15_tries_TAG_sS_TT.npz: phase, centre, circle
radius r, the radius the rule saw (goal_r: raised by a finished neighbour's handed-over circle,
strew.ornament._engine._handed_over), run, context, ok, first kind placed). Only the tries whose circle
centre lies in the world's kept part (orn19m_willow._world's edge band left out) and inside its tile's own
rectangle... no: a tile's region reaches a halo past its border, so a try counts where its centre lies,
whichever run made it. Per 0.5 s bin of the signed distance to the nearest inner border (negative: the
earlier tile's side): tries, twig successes, their mean r and goal_r (s), share raised.
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

    edges = np.arange(-3.0, 3.01, 0.5)
    for tag in (args.tiled, args.control):
        acc = np.zeros((len(edges) - 1, 6))
        far = np.zeros(6)
        for tile in args.tiles.split(","):
            p = RES / f"hie15_tries_{tag}_s{args.seed}_T{tile}.npz"
            w = RES / f"orn19m_{tag}_s{args.seed}_T{tile}.npz"
            if not (p.exists() and w.exists()):
                continue
            z, zw = np.load(p), np.load(w)
            side, T, halo, _ = zw["meta"]
            s = side / np.sqrt(len(zw["x"]))
            margin = max(halo, 3 * s)
            num = z["num"]
            ph = list(z["phases"]).index("flowers")
            kinds = list(z["first_kinds"])
            twig = kinds.index("twig") if "twig" in kinds else -99
            m = (num[:, 0] == ph)
            x, y = num[:, 1], num[:, 2]
            m &= (x >= margin) & (x <= side - margin) & (y >= margin) & (y <= side - margin)
            # a later tile's try over ground its finished neighbour kept counts too: the world's tries
            d, sd = _sd(x, y, side, T)
            d, sd = d / s, sd / s
            ok_t = (z["first"] == twig) & (num[:, 7] > 0)
            b = np.digitize(sd, edges) - 1
            for k in range(len(edges) - 1):
                q = m & (b == k)
                acc[k] += [q.sum(), (q & ok_t).sum(), num[q & ok_t, 3].sum() / s, num[q & ok_t, 4].sum() / s,
                           (q & ok_t & (num[:, 4] > num[:, 3] + 1e-9)).sum(), (q & (num[:, 6] > 0)).sum()]
            q = m & (d >= 3)
            far += [q.sum(), (q & ok_t).sum(), num[q & ok_t, 3].sum() / s, num[q & ok_t, 4].sum() / s,
                    (q & ok_t & (num[:, 4] > num[:, 3] + 1e-9)).sum(), (q & (num[:, 6] > 0)).sum()]
        print(f"\n{tag}: flowers-phase tries by signed distance (s); twig successes; r, goal_r in s; raised share; tries by a run with context")
        for k in range(len(edges) - 1):
            a = acc[k]
            n = max(a[1], 1)
            print(f"  [{edges[k]:+.1f},{edges[k + 1]:+.1f})  tries {a[0]:5.0f}  twigs {a[1]:4.0f}  ok-rate {a[1] / max(a[0], 1):.2f}"
                  f"  r {a[2] / n:.2f}  goal_r {a[3] / n:.2f}  raised {a[4] / n:.2f}  ctx-run {a[5] / max(a[0], 1):.2f}")
        a = far
        n = max(a[1], 1)
        print(f"  |d|>=3       tries {a[0]:5.0f}  twigs {a[1]:4.0f}  ok-rate {a[1] / max(a[0], 1):.2f}  r {a[2] / n:.2f}  goal_r {a[3] / n:.2f}"
              f"  raised {a[4] / n:.2f}  ctx-run {a[5] / max(a[0], 1):.2f}")


if __name__ == "__main__":
    main()

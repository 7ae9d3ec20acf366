"""Where the tiled hierarchy worlds' border strips lose twigs and gain flowers (issue 19.4 point 4, helper w67d).

``python benchmarks/w67d_probe.py TILED:CONTROL --tiles 32,33,... [--seed 19]``

Worlds as benchmarks/w60d_bias.py (orn19m_TAG_sS_TT.npz). A twig and its flower are one rule success
(hierarchy's flower_on_twig), so their counts are equal in any world: a strip short of twigs and rich in
flowers holds the flowers of successes whose twig centre lies outside it. This prints, pooled over worlds,
by the signed distance to the nearest inner border (negative: the earlier tile's side, orn19m_willow._sd)
in 0.5 s bins: each kind's density per area / the world's |d| >= 3 s density (twig, flower), the mean
twig-to-flower centre distance of the flowers there (in s; tiled worlds only: the pairs by (placer, group)), the flowers' mean goal radius, and the share of
flowers placed by the tile on the other side of the border (tiled: the placer is the tile that ran the rule).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))

EDGES = np.arange(-3.0, 3.01, 0.5)


def rows(w: dict, z) -> dict:
    kinds = w["kinds"]
    ti, fi = kinds.index("twig"), kinds.index("flower")
    k, g, pl = w["kind"], w["group"], w["placer"]
    tw = np.flatnonzero(k == ti)
    fl = np.flatnonzero(k == fi)
    gt = {(int(pl[i]), int(g[i])): i for i in tw}  # group ids are numbered per tile
    pair = np.array([gt.get((int(pl[i]), int(g[i])), -1) for i in fl])
    ok = pair >= 0
    fl, pair = fl[ok], pair[ok]
    dist = np.hypot(w["x"][fl] - w["x"][pair], w["y"][fl] - w["y"][pair]) / w["s"]
    return {"fl": fl, "tw": pair, "dist": dist}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("pair")
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    args = ap.parse_args()
    import orn19m_willow as W

    for tag in args.pair.split(":"):
        acc = {}
        ref = np.zeros(3)
        for tile in args.tiles.split(","):
            p = RES / f"orn19m_{tag}_s{args.seed}_T{tile}.npz"
            if not p.exists():
                print(f"{tag} T{tile}: missing")
                continue
            w = W._world(p)
            z = np.load(p)
            kinds = w["kinds"]
            ti, fi = kinds.index("twig"), kinds.index("flower")
            r = rows(w, z)
            ins = w["inside"]
            # the grid's signed distance: recompute from the lattice (gsd)
            far = w["gd"] >= 3.0
            ref += [((w["kind"] == ti) & ins & (w["d"] >= 3)).sum(), ((w["kind"] == fi) & ins & (w["d"] >= 3)).sum(), far.sum() * w["garea"]]
            b_el = np.digitize(w["sd"], EDGES) - 1
            b_g = np.digitize(w["gsd"], EDGES) - 1
            fl, tw = r["fl"], r["tw"]
            other = (w["placer"][fl] >= 0) & (w["placer"][fl] != w["unit"][fl])
            gr = z["goal_r"][fl]
            for b in range(len(EDGES) - 1):
                a = acc.setdefault(b, np.zeros(8))
                a[0] += ((w["kind"] == ti) & ins & (b_el == b)).sum()
                a[1] += ((w["kind"] == fi) & ins & (b_el == b)).sum()
                a[2] += (b_g == b).sum() * w["garea"]
                m = ins[fl] & (b_el[fl] == b)
                a[3] += m.sum()
                a[4] += r["dist"][m].sum()
                a[5] += np.nansum(gr[m])
                a[6] += other[m].sum()
                # flowers here whose twig centre lies in another bin farther from the border
                a[7] += (m & (np.abs(w["sd"][tw]) > np.abs(w["sd"][fl]))).sum()
        dt, df = ref[0] / ref[2], ref[1] / ref[2]
        print(f"\n{tag}: tiles {args.tiles}; |d| >= 3 s: twig {ref[0]:.0f}, flower {ref[1]:.0f}")
        print("  sd bin (s)      twig/far flower/far  n_fl  twig-flower(s)  goal_r  placed-by-other  twig-farther")
        for b in sorted(acc):
            a = acc[b]
            n = max(a[3], 1)
            print(f"  [{EDGES[b]:+.1f},{EDGES[b + 1]:+.1f})  {a[0] / a[2] / dt:8.3f} {a[1] / a[2] / df:8.3f}  {a[3]:5.0f}  {a[4] / n:8.2f}"
                  f"  {a[5] / n:8.2f}  {a[6] / n:8.2f}  {a[7] / n:8.2f}")


if __name__ == "__main__":
    main()

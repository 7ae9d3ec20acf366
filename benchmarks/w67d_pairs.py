"""Twig-flower pairs at the tile borders of the tiled hierarchy worlds against the untiled control (issue 19.4
point 4, helper w67d).

``python benchmarks/w67d_pairs.py --tiled w67dM --tiles 32,33 [--seed 19]``

A twig and its flower are one success of hierarchy's flower_on_twig (equal counts in any world), so a strip
short of twigs and rich in flowers holds flowers whose twig centre lies outside it. Tiled: pairs by
(placer tile, ``group``) (ornament_group, numbered per tile); control: results/w67d_ctlpairs_sS_TT.npz (flower element = twig element + 1, same
parent; benchmarks/w67d_ctl_pairs.py). Pooled over the worlds, for the flowers and twigs in the +-2 s and
+-1 s strips (orn19m_willow._world's lines and edge band) and in the |d| >= 3 s interior: how many, the
twig-to-flower centre distance (s), |cos| of that vector with the border's normal, and the share of the
strip's flowers whose twig lies outside the strip (and of its twigs whose flower does); tiled also the
share placed by the tile across the border.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def normal_cos(x, y, vx, vy, tile):
    lines = np.arange(1, 4) * tile
    dx = np.min(np.abs(x[:, None] - lines), axis=1)
    dy = np.min(np.abs(y[:, None] - lines), axis=1)
    n = np.hypot(vx, vy)
    n[n == 0] = 1
    return np.where(dx <= dy, np.abs(vx) / n, np.abs(vy) / n)


def stats(w, fl, tw, placer_other=None):
    out = {}
    d = w["d"]
    ins = w["inside"]
    s = w["s"]
    vx, vy = w["x"][fl] - w["x"][tw], w["y"][fl] - w["y"][tw]
    dist = np.hypot(vx, vy) / s
    cos = normal_cos(w["x"][fl], w["y"][fl], vx, vy, w["tile"])
    # towards the border: |d| of the twig minus |d| of the flower (s), for the pairs with a row within 3 s,
    # by the flower's side (negative sd: the earlier tile's) in 1 s bins of the flower's sd
    sdf = w["sd"][fl]
    dd = d[tw] - d[fl]
    both = ins[fl] & ins[tw]
    out["toward"] = {b: dd[both & (sdf >= b) & (sdf < b + 1)].tolist() for b in range(-3, 3)}
    for name, wd in (("2s", 2.0), ("1s", 1.0), ("int3", None)):
        if wd is None:
            mf, mt = ins[fl] & (d[fl] >= 3), ins[tw] & (d[tw] >= 3)
            out[name] = {"nf": int(mf.sum()), "nt": int(mt.sum()), "dist": dist[mf].tolist(), "cos": cos[mf].tolist()}
            continue
        mf = ins[fl] & (d[fl] < wd)
        mt = ins[tw] & (d[tw] < wd)
        out[name] = {"nf": int(mf.sum()), "nt": int(mt.sum()), "dist": dist[mf].tolist(), "cos": cos[mf].tolist(),
                         "f_twig_out": int((mf & ~(d[tw] < wd)).sum()), "t_flower_out": int((mt & ~(d[fl] < wd)).sum()),
                         "other": None if placer_other is None else int(placer_other[mf].sum())}
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--tiled", default="w67dM")
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    args = ap.parse_args()
    import orn19m_willow as W

    acc: dict = {"tiled": [], "control": []}
    for tile in args.tiles.split(","):
        pt = RES / f"orn19m_{args.tiled}_s{args.seed}_T{tile}.npz"
        pc = RES / f"w67d_ctlpairs_s{args.seed}_T{tile}.npz"
        pr = RES / f"orn19m_w67dctl_s{args.seed}_T{tile}.npz"
        if not (pt.exists() and pc.exists() and pr.exists()):
            print(f"T{tile}: missing")
            continue
        w = W._world(pt)
        k = w["kind"]
        ti, fi = w["kinds"].index("twig"), w["kinds"].index("flower")
        g = w["group"]
        pl = w["placer"]
        tw_of = {(int(pl[i]), int(g[i])): i for i in np.flatnonzero(k == ti)}  # group ids are per tile
        fl = np.flatnonzero(k == fi)
        tw = np.array([tw_of.get((int(pl[i]), int(g[i])), -1) for i in fl])
        fl, tw = fl[tw >= 0], tw[tw >= 0]
        other = (w["placer"][fl] >= 0) & (w["placer"][fl] != w["unit"][fl])
        acc["tiled"].append(stats(w, fl, tw, other))
        c = W._world(pr)
        z = np.load(pc)
        el, par = z["element"], z["parent"]
        kinds = [str(v) for v in z["kinds"]]
        kc = z["kind"]
        row = {int(e): i for i, e in enumerate(el)}
        flc = np.flatnonzero(kc == kinds.index("flower"))
        twc = np.array([row.get(int(el[i]) - 1, -1) for i in flc])
        ok = (twc >= 0)
        ok[ok] = (kc[twc[ok]] == kinds.index("twig")) & (par[twc[ok]] == par[flc[ok]])
        acc["control"].append(stats(c, flc[ok], twc[ok]))
    print(f"tiled {args.tiled} vs control, tiles {args.tiles}, seed {args.seed}")
    for name in ("2s", "1s", "int3"):
        for world in ("tiled", "control"):
            L = acc[world]
            nf = sum(a[name]["nf"] for a in L)
            nt = sum(a[name]["nt"] for a in L)
            dist = np.concatenate([a[name]["dist"] for a in L]) if L else np.zeros(0)
            cos = np.concatenate([a[name]["cos"] for a in L]) if L else np.zeros(0)
            line = (f"  {name:5s} {world:8s} flowers {nf:4d} twigs {nt:4d} (t/f {nt / max(nf, 1):.3f})  twig-flower {dist.mean():.2f} s"
                    f"  |cos normal| {cos.mean():.3f} (share > 0.7: {(cos > 0.7).mean():.2f})")
            if name != "int3":
                fo = sum(a[name]["f_twig_out"] for a in L)
                to = sum(a[name]["t_flower_out"] for a in L)
                line += f"  flowers with twig out {fo / max(nf, 1):.2f}, twigs with flower out {to / max(nt, 1):.2f}"
                if world == "tiled":
                    line += f", flowers placed across {sum(a[name]['other'] for a in L) / max(nf, 1):.2f}"
            print(line)
    print("pairs by the flower's signed distance to the border (s; negative: the earlier tile's side): mean |d| twig - |d| flower"
          " (s; > 0: the flower nearer the border than its twig), n")
    for b in range(-3, 3):
        cells = []
        for world in ("tiled", "control"):
            v = np.concatenate([a["toward"][b] for a in acc[world]])
            cells.append(f"{world} {v.mean():+.3f} (n {len(v)})")
        print(f"  [{b:+d},{b + 1:+d}) " + "   ".join(cells))


if __name__ == "__main__":
    main()

"""The vines that cross a tile border, tiled vase world against its untiled control (issue 19.4, vas15).

``python benchmarks/vas15_cross.py TILED:CONTROL[:T] [...] [--halo H] [--json F]`` reads the worlds of
``benchmarks/vas15_trace.py make --tag TILED --tiles T`` (and ``--tag CONTROL --untiled``; with ``:T`` only tile size T)
and prints, pooled over the pairs:

- per world and strip (+-1 s, +-2 s; vas19s_compare.py's lines, the world's edge band left out)
  the vines in the strip, tiled / control, and each world's own vine share in the strip
  against its own interior (is the control's strip richer in vines than its interior?), and
  the strip's vines within 25 units of the world's centre (the control's seed);
- per inner border line (x or y = T, 2 T, 3 T; pooled over x and y) the vines crossing it (the
  vine's start and its flower on different sides), split by direction: from the finished
  (earlier, the 2 x 2 order's even tile column / row) side to the later side, or back; and
  how many of those lie in the +-1 s and +-2 s strips.

Each traced vine is matched to its row of the world (orn19m_willow.py's npz) by its chord's
midpoint (an assignment, all rows matched). ``--halo H`` measures every world with the edge
band of halo H (a world grown with another halo than its control's).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def _world(tag: str, T: str, halo: float | None) -> dict:
    from orn19m_willow import _world as world

    p = RES / f"orn19m_vas15_{tag}_T{T}.npz"
    if halo is not None:
        z = dict(np.load(p))
        m = z["meta"].copy()
        m[2] = halo
        z["meta"] = m
        p = RES / f"_vas15_tmp_{tag}_T{T}.npz"
        np.savez(p, **z)
        try:
            return world(p)
        finally:
            p.unlink()
    return world(p)


def load(tag: str, T: str, halo: float | None = None) -> dict:
    """The world's vines, each with its trace (start, flower's grid point, parent, tile)."""
    from scipy.optimize import linear_sum_assignment

    from strew.ornament.patterns.vase import GRID

    w = _world(tag, T, halo)
    k = w["kinds"].index("vine")
    v = np.flatnonzero(w["kind"] == k)
    z = np.load(RES / f"vas15_{tag}_T{T}.npz")
    g = z["g"][z["kept"]]
    mx, my = (g[:, 3] * GRID + g[:, 1]) / 2, (g[:, 4] * GRID + g[:, 2]) / 2
    d = np.hypot(w["x"][v][:, None] - mx[None], w["y"][v][:, None] - my[None])
    r, c = linear_sum_assignment(d)
    assert len(r) == len(v) == len(g), (len(r), len(v), len(g))
    return {"w": w, "sd": w["sd"][v][r], "d": w["d"][v][r], "x": w["x"][v][r], "y": w["y"][v][r], "inside": w["inside"][v][r], "g": g[c], "T": float(T)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pairs", nargs="+")
    ap.add_argument("--halo", type=float, default=None)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    from vas19x_pool import _counts, _ratios

    from strew.ornament.patterns.vase import GRID

    tot: dict = {}
    lines: dict = {}
    per: dict = {}
    for pr in args.pairs:
        tt, ct, *only = pr.split(":")
        for p in sorted(RES.glob(f"vas15_{tt}_T*.npz")):
            T = p.name.rsplit("_T", 1)[1][:-4]
            if only and T != only[0]:
                continue
            if not (RES / f"vas15_{ct}_T{T}.npz").exists():
                continue
            row = []
            for name, tag in (("tiled", tt), ("control", ct)):
                o = load(tag, T, args.halo if name == "tiled" else None)
                w = o["w"]
                vk = w["kinds"].index("vine")
                c0 = w["side"] / 2
                cen = np.hypot(o["x"] - c0, o["y"] - c0) < 25
                for wd in (1.0, 2.0):
                    cnt = _counts(w, wd)
                    a = tot.setdefault((name, wd), np.zeros_like(cnt))
                    a += cnt
                    sv = o["inside"] & (o["d"] < wd)
                    row.append(f"{name} +-{wd:g}s {int(cnt[4 + vk])} (near the centre {int((sv & cen).sum())}) own share {_ratios(cnt, len(w['kinds']))[1 + vk]:.3f}")
                g = o["g"]
                # grid points in the panel that hold no flower (a vine delivers every flower)
                n = int((w["side"] - 6.0) // GRID)
                have = {(int(a), int(b)) for a, b in g[:, 3:5]}
                holes = [(i, j) for i in range(1, n + 1) for j in range(1, n + 1) if (i, j) not in have]
                row.append(f"{name} grid points without a flower {holes}")
                fx, fy, sx, sy = g[:, 3] * GRID, g[:, 4] * GRID, g[:, 1], g[:, 2]
                for b in (1, 2, 3):
                    L = b * o["T"]
                    for s_, f_ in ((sx, fx), (sy, fy)):
                        cr = (s_ - L) * (f_ - L) < 0
                        fin = np.floor(s_ / o["T"]).astype(int) % 2 == 0  # the start on the finished side
                        s1, s2 = np.abs(o["sd"]) < 1, np.abs(o["sd"]) < 2
                        key = (name, f"{b} T")
                        v = lines.setdefault(key, np.zeros(6, int))
                        v += [(cr & fin).sum(), (cr & ~fin).sum(), (cr & fin & s1).sum(), (cr & ~fin & s1).sum(), (cr & fin & s2).sum(), (cr & ~fin & s2).sum()]
            print(f"{pr} T{T}: " + "; ".join(row))
            per[f"{pr} T{T}"] = row
    out: dict = {"pairs": args.pairs, "halo": args.halo, "per_world": per, "pooled": {}, "crossing": {}}
    for wd in (1.0, 2.0):
        t, c = tot[("tiled", wd)], tot[("control", wd)]
        rt, rc = _ratios(t, 5), _ratios(c, 5)
        out["pooled"][f"{wd:g}s"] = {"vines_tiled_control": [int(t[4]), int(c[4])], "own_vine_share_tiled_control": [float(rt[1]), float(rc[1])],
                                     "tiled_over_control": dict(zip(["density", "vine", "hook", "lotus", "peony", "teardrop"], (rt / rc).tolist()))}
        print(f"pooled +-{wd:g} s: vines tiled {int(t[4])} control {int(c[4])}; own strip / interior vine share tiled {rt[1]:.3f} control {rc[1]:.3f}; "
              f"tiled / control vine {rt[1] / rc[1]:.3f} density {rt[0] / rc[0]:.3f} hook {rt[2] / rc[2]:.3f} teardrop {rt[5] / rc[5]:.3f} "
              f"lotus {rt[3] / rc[3]:.3f} peony {rt[4] / rc[4]:.3f}")
    print("vines crossing each inner border line (x and y pooled): finished -> later, later -> finished | of those in +-1 s | in +-2 s")
    for (name, ln), v in sorted(lines.items(), key=lambda kv: (kv[0][1], kv[0][0] != "tiled")):
        print(f"  {ln:4s} {name:8s}: {v[0]:3d} {v[1]:3d} | {v[2]:3d} {v[3]:3d} | {v[4]:3d} {v[5]:3d}")
        out["crossing"][f"{ln} {name}"] = v.tolist()
    if args.json:
        import json

        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")
        print(f"wrote {args.json}")


if __name__ == "__main__":
    main()

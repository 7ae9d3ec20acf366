"""Tiled against untiled control by signed distance to the nearest inner border, pooled over
worlds (issue 19.4, helper w28h): where a kind is short or in excess.

``python benchmarks/w28h_profile.py TILED:CONTROL [TILED:CONTROL ...] --tiles 40,44,48 [--seed 19]
[--kinds vine,twig,flower,leaf] [--width 0.5] [--shift 0.5]``

Worlds ``benchmarks/results/orn19m_TAG_sS_TT.npz`` (benchmarks/hie15_make.py). Per bin of
signed distance d / s (s the world's mean spacing; negative on the earlier, finished
tile's side; orn19m_willow._world), pooled counts of each kind per unit area in the tiled
worlds and the controls, each divided by its own interior (|d| >= 3 s) density of that
kind, and the ratio tiled / control with its Poisson count. A last row: the bins within
+-1 s and +-2 s together. ``--shift F`` measures at lines moved by F tiles from the borders
(F = 0.5: through the tiles' middles, where no seam lies): what the worlds' own layout (the
seeds at the first-phase tiles' centres, hie15_make) puts there.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def _shifted(sd0, shift):
    def _sd(x, y, side, tile):  # the lines (and the tile parity) moved by shift * tile
        return sd0(x - shift * tile, y - shift * tile, side, tile)

    return _sd


def _pool(args, W, edges):
    nb = len(edges) - 1
    acc = {"t": None, "c": None}
    kinds = None
    used = []
    for pr in args.pairs:
        tt, ct = pr.split(":")
        for tile in args.tiles.split(","):
            p, q = RES / f"orn19m_{tt}_s{args.seed}_T{tile}.npz", RES / f"orn19m_{ct}_s{args.seed}_T{tile}.npz"
            if not (p.exists() and q.exists()):
                continue
            used.append(f"{tt}/{ct} T{tile}")
            for key, f in (("t", p), ("c", q)):
                w = W._world(f)
                kinds = kinds or w["kinds"]
                nk = len(kinds)
                ins = w["inside"]
                b = np.where(w["d"] >= 3.0, nb, np.clip(np.digitize(w["sd"], edges) - 1, 0, nb - 1))
                gb = np.where(w["gd"] >= 3.0, nb, np.clip(np.digitize(w["gsd"], edges) - 1, 0, nb - 1))
                cnt = np.zeros((nb + 1, nk))
                np.add.at(cnt, (b[ins], w["kind"][ins]), 1)
                area = np.bincount(gb, minlength=nb + 1) * w["garea"]
                a = acc[key]
                acc[key] = (cnt, area) if a is None else (a[0] + cnt, a[1] + area)
    return acc, kinds, used


def _strip(acc, edges, wd):
    """(tiled, control) per kind: strip density / interior density; and for all kinds."""
    nb = len(edges) - 1
    m = np.flatnonzero((np.abs(edges[:-1]) < wd - 1e-9) & (np.abs(edges[1:]) <= wd + 1e-9))
    out = []
    for key in ("t", "c"):
        c, a = acc[key]
        k = (c[m].sum(0) / a[m].sum()) / (c[nb] / a[nb])
        tot = (c[m].sum() / a[m].sum()) / (c[nb].sum() / a[nb])
        out.append((k, tot))
    return out


def null(args, W, sd0) -> None:
    """Tiled / control at lines where no seam lies (moved by 0.25-0.75 tiles): the spread of
    the statistic from the worlds' own layout and counts, against its value at the seams."""
    edges = np.arange(-3.0, 3.0 + 1e-9, args.width)
    rows = {}
    for sh in [0.0] + [round(v, 2) for v in np.arange(0.25, 0.751, 0.05)]:
        W._sd = _shifted(sd0, sh) if sh else sd0
        acc, kinds, used = _pool(args, W, edges)
        rows[sh] = {wd: _strip(acc, edges, wd) for wd in (1.0, 2.0)}
    W._sd = sd0
    print(f"{len(used)} world pairs: {', '.join(used)}")
    for wd in (1.0, 2.0):
        print(f"+-{wd:g}s: tiled/control of the share (kind ratio / density ratio); shift 0 = the seams")
        print("shift  density " + " ".join(f"{k:>7s}" for k in kinds))
        vals = []
        for sh, r in rows.items():
            (kt, tt), (kc, tc) = r[wd]
            share = (kt / tt) / (kc / tc)
            if sh:
                vals.append(np.concatenate([[tt / tc], share]))
            print(f"{sh:5.2f}  {tt / tc:7.3f} " + " ".join(f"{v:7.3f}" for v in share))
        v = np.array(vals)
        print("null mean/sd " + f"{v[:, 0].mean():.3f}/{v[:, 0].std():.3f} " + " ".join(f"{a:.2f}/{b:.2f}" for a, b in zip(v[:, 1:].mean(0), v[:, 1:].std(0))))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pairs", nargs="+")
    ap.add_argument("--tiles", default="40,44,48")
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--kinds", default="vine,twig,flower,leaf,quote")
    ap.add_argument("--width", type=float, default=0.5)
    ap.add_argument("--null", action="store_true", help="the +-1 s / +-2 s ratios at lines moved by 0.25-0.75 tiles")
    ap.add_argument("--shift", type=float, default=0.0, help="measure at lines moved by this fraction of the tile (no seam there)")
    args = ap.parse_args()
    import orn19m_willow as W

    sd0 = W._sd
    if args.null:
        null(args, W, sd0)
        return
    if args.shift:
        W._sd = _shifted(sd0, args.shift)

    edges = np.arange(-3.0, 3.0 + 1e-9, args.width)
    nb = len(edges) - 1
    acc = {"t": None, "c": None}
    kinds = None
    used = []
    for pr in args.pairs:
        tt, ct = pr.split(":")
        for tile in args.tiles.split(","):
            p, q = RES / f"orn19m_{tt}_s{args.seed}_T{tile}.npz", RES / f"orn19m_{ct}_s{args.seed}_T{tile}.npz"
            if not (p.exists() and q.exists()):
                continue
            used.append(f"{tt}/{ct} T{tile}")
            for key, f in (("t", p), ("c", q)):
                w = W._world(f)
                kinds = kinds or w["kinds"]
                nk = len(kinds)
                ins = w["inside"]
                # bins 0..nb-1 by sd, nb: interior (d >= 3)
                b = np.where(w["d"] >= 3.0, nb, np.clip(np.digitize(w["sd"], edges) - 1, 0, nb - 1))
                gb = np.where(w["gd"] >= 3.0, nb, np.clip(np.digitize(w["gsd"], edges) - 1, 0, nb - 1))
                cnt = np.zeros((nb + 1, nk))
                np.add.at(cnt, (b[ins], w["kind"][ins]), 1)
                area = np.bincount(gb, minlength=nb + 1) * w["garea"]
                a = acc[key]
                acc[key] = (cnt, area) if a is None else (a[0] + cnt, a[1] + area)
    print(f"{len(used)} world pairs: {', '.join(used)}")
    sel = [kinds.index(k) for k in args.kinds.split(",") if k in kinds]
    (ct, at), (cc, ac) = acc["t"], acc["c"]
    dt, dc = ct / at[:, None], cc / ac[:, None]
    rt, rc = dt / dt[nb], dc / dc[nb]
    print("bin d/s       " + "".join(f"{kinds[k]:>26s}" for k in sel))
    print("              " + "".join(f"{'tiled ctl  t/c  (nt/nc)':>26s}" for _ in sel))
    for i in range(nb):
        row = f"{edges[i]:+.1f}..{edges[i + 1]:+.1f}  "
        for k in sel:
            row += f"  {rt[i, k]:5.2f} {rc[i, k]:5.2f} {rt[i, k] / rc[i, k]:5.2f} ({int(ct[i, k]):3d}/{int(cc[i, k]):3d})"
        print(row)
    for wd in (1.0, 2.0):
        m = np.flatnonzero((np.abs(edges[:-1]) < wd - 1e-9) & (np.abs(edges[1:]) <= wd + 1e-9))
        row = f"+-{wd:g}s          "
        for k in sel:
            st, sc = ct[m, k].sum() / at[m].sum() / dt[nb, k], cc[m, k].sum() / ac[m].sum() / dc[nb, k]
            n1, n2 = ct[m, k].sum(), cc[m, k].sum()
            err = np.sqrt(1 / max(n1, 1) + 1 / max(n2, 1))
            row += f"  {st:5.2f} {sc:5.2f} {st / sc:5.2f}+-{err * st / sc:4.2f}"
        print(row)
    print(f"interior counts tiled {ct[nb].astype(int).tolist()} control {cc[nb].astype(int).tolist()}")


if __name__ == "__main__":
    main()

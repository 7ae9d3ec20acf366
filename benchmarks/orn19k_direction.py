"""Which way ornament flowers grow near tile borders (issue 19.4, helper orn19k).

Reads the worlds of ``benchmarks/orn19f_profile.py make`` (``results/orn19f_<tag>_T*.npz``)
and prints, pooled over each tag's worlds, by signed distance to the nearest inner border
(half-spacing bins, negative on the earlier tile's side, as orn19f_profile.py):

- ``dir``: the mean of each flower-phase stem's unit vector (parent flower -> child
  flower) projected on the border normal pointing into the LATER tile (+1: every stem
  grows straight into the later tile; 0: no preferred direction);
- ``off/s``: the mean offset stem midpoint -> child flower on that normal, in spacings;
- the stems' leaf share (a leaf: the element two after the stem, same parent) and their
  share shorter than 8 units, and the leaf share split by ``dir`` (stems growing into the
  later tile, > 0.5, against the others).

An untiled world (``make --untiled``) gets the same lines: the control.

Run: ``python benchmarks/orn19k_direction.py main13 [unt ...] [--out F]``.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
BINS = np.arange(-3.0, 3.01, 0.5)


def _world(path: Path) -> dict:
    z = np.load(path, allow_pickle=False)
    side, tile, halo, _ = z["meta"]
    kinds = [str(k) for k in z["kinds"]]
    x, y, kind = z["x"], z["y"], z["kind"]
    n = len(x)
    s = 1.0 / np.sqrt(n / side**2)
    margin = max(halo, 3.0 * s)
    inside = (x >= margin) & (x <= side - margin) & (y >= margin) & (y <= side - margin)
    lines = np.arange(1, 4) * tile
    ix = np.argmin(np.abs(x[:, None] - lines), axis=1)
    iy = np.argmin(np.abs(y[:, None] - lines), axis=1)
    dx = np.abs(x - lines[ix])
    dy = np.abs(y - lines[iy])
    d = np.minimum(dx, dy) / s
    col, row = np.floor(x / tile).astype(np.int64), np.floor(y / tile).astype(np.int64)
    vert = dx <= dy
    sgn = np.where(vert, np.where(col % 2 == 0, -1.0, 1.0), np.where(row % 2 == 0, -1.0, 1.0))
    sd = sgn * d
    # the border normal pointing into the later tile: away from the line on the later
    # side, towards it on the earlier side
    nx = np.where(vert, sgn * np.sign(x - lines[ix]), 0.0)
    ny = np.where(vert, 0.0, sgn * np.sign(y - lines[iy]))
    el, par, tl = z["element"], z["parent"], z["tile"]
    k_stem, k_leaf, k_flower = kinds.index("stem"), kinds.index("leaf"), kinds.index("flower")
    # element numbers restart in each tile's run: keyed by (tile, element, parent)
    pos = {(int(t), int(e), int(p)): i for i, (t, e, p) in enumerate(zip(tl, el, par))}
    stems = np.flatnonzero((kind == k_stem) & z["flowers_phase"] & inside)
    fl = np.array([pos.get((int(tl[i]), int(el[i]) + 1, int(par[i])), -1) for i in stems], np.int64)
    ok = fl >= 0
    ok[ok] &= kind[fl[ok]] == k_flower
    stems, fl = stems[ok], fl[ok]
    vx, vy = x[fl] - x[stems], y[fl] - y[stems]
    ln = np.hypot(vx, vy)
    ln[ln == 0] = 1.0
    proj = (vx * nx[stems] + vy * ny[stems])
    lk = [(int(tl[i]), int(el[i]) + 2, int(par[i])) for i in stems]
    lf = np.array([q in pos and kind[pos[q]] == k_leaf for q in lk], bool)
    b = np.digitize(sd[stems], BINS) - 1
    b[d[stems] >= BINS[-1]] = len(BINS) - 1
    return dict(b=b, dir=proj / ln, off=proj / s, leaf=lf, short=z["stem_len"][stems] <= 8.0, s=s)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tags", nargs="+")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    out = {}
    for tag in args.tags:
        paths = sorted(RES.glob(f"orn19f_{tag}_T*.npz"))
        if not paths:
            print(f"{tag}: no worlds")
            continue
        ws = [_world(p) for p in paths]
        cat = {k: np.concatenate([w[k] for w in ws]) for k in ("b", "dir", "off", "leaf", "short")}
        print(f"\n== {tag}: {len(ws)} worlds; flower-phase stems by signed distance (s), normal into the later tile")
        print("  bin           stems    dir   off/s   leaf  short  leaf(dir>.5)  leaf(dir<=.5)")
        rows = {}
        for bi in range(len(BINS)):
            lab = f"{BINS[bi]:+g}..{BINS[bi + 1]:+g}" if bi < len(BINS) - 1 else f"|d|>{BINS[-1]:g}"
            m = cat["b"] == bi
            n = int(m.sum())
            if not n:
                continue
            fwd = m & (cat["dir"] > 0.5)
            rest = m & ~(cat["dir"] > 0.5)
            r = dict(stems=n, dir=float(cat["dir"][m].mean()), off=float(cat["off"][m].mean()), leaf=float(cat["leaf"][m].mean()),
                     short=float(cat["short"][m].mean()), leaf_fwd=float(cat["leaf"][fwd].mean()) if fwd.any() else float("nan"),
                     leaf_rest=float(cat["leaf"][rest].mean()) if rest.any() else float("nan"), n_fwd=int(fwd.sum()))
            rows[lab] = r
            print(f"  {lab:12s} {n:6d} {r['dir']:+.3f} {r['off']:+.3f}  {r['leaf']:.3f}  {r['short']:.3f}   {r['leaf_fwd']:.3f} ({r['n_fwd']})   {r['leaf_rest']:.3f}")
        out[tag] = rows
    if args.out:
        Path(args.out).write_text(json.dumps(out, indent=1))
        print(f"wrote {args.out}")


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--quick":
        print("orn19k_direction: skipped (needs worlds from orn19f_profile.py make)")
        sys.exit(3)
    main()

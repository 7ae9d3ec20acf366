"""Ornament vase across tile borders: the flowers' grid against the strips (issue 19.4).

Reads the worlds that ``benchmarks/orn19m_willow.py make --pattern vase --tag TAG
--tiles T [--untiled]`` saved (``benchmarks/results/orn19m_<tag>_T<T>.npz``) and prints,
for each tag and tile size:

- the flowers' (lotus, peony) positions modulo the grid spacing (vase.GRID) in world
  coordinates: whether every tile's flowers lie on one world lattice (the grid continues
  across each border) or on a lattice of its own;
- the occupancy of the lattice's points by flowers by distance to the nearest inner
  border (grid rows 0, 1, 2, >= 3 away), and the border lines' phase against the lattice
  (``T mod GRID``): a border line on a lattice row puts a row of flowers in the strips;
- ``--png OUT``: a render of the region about an inner corner of the tiles (2 x 2 tiles'
  corner at (2T, 2T)), flowers as discs of their radius, the rest as points.

``python benchmarks/vas19s_grid.py TAG [TAG ...] [--png OUT]``
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"


def _load(path: Path) -> dict:
    z = np.load(path, allow_pickle=False)
    side, tile, halo, cpu = z["meta"]
    kinds = [str(k) for k in z["kinds"]]
    return dict(x=z["x"], y=z["y"], kind=z["kind"], kinds=kinds, tile=float(tile), side=float(side), halo=float(halo),
                placer=z["tile"])


def grid_report(w: dict, grid: float) -> dict:
    kinds = w["kinds"]
    fl = np.isin(w["kind"], [kinds.index(k) for k in ("lotus", "peony") if k in kinds])
    fx, fy = w["x"][fl], w["y"][fl]
    res = {"flowers": int(fl.sum())}
    # residuals against the world lattice
    rx = (fx + 0.5 * grid) % grid - 0.5 * grid
    ry = (fy + 0.5 * grid) % grid - 0.5 * grid
    res["off_lattice"] = int(np.sum((np.abs(rx) > 1e-6) | (np.abs(ry) > 1e-6)))
    # lattice points inside the world's margin (one grid spacing from the edge)
    T, side = w["tile"], w["side"]
    g = np.arange(np.ceil(grid / grid), np.floor((side - grid) / grid) + 1) * grid
    gx, gy = np.meshgrid(g, g)
    gx, gy = gx.ravel(), gy.ravel()
    occ = set(zip(np.round(fx / grid).astype(int), np.round(fy / grid).astype(int)))
    taken = np.array([(int(round(a / grid)), int(round(b / grid))) in occ for a, b in zip(gx, gy)])
    lines = np.arange(1, int(round(side / T))) * T
    d = np.minimum(np.min(np.abs(gx[:, None] - lines), 1), np.min(np.abs(gy[:, None] - lines), 1))
    rows = np.minimum(np.floor(d / grid + 0.5).astype(int), 3)  # grid rows from the border
    res["occupancy_by_rows"] = {str(r): [float(taken[rows == r].mean()) if np.any(rows == r) else float("nan"), int(np.sum(rows == r))]
                                for r in range(4)}
    res["occupancy"] = float(taken.mean())
    res["border_phase"] = [float((v + 0.5 * grid) % grid - 0.5 * grid) for v in lines]
    # the lattice phase of each tile's own flowers (by the tile that placed them)
    if np.any(w["placer"] >= 0):
        ph = {}
        for t in np.unique(w["placer"][fl]):
            m = w["placer"][fl] == t
            ph[int(t)] = [float(np.median(rx[m])), float(np.median(ry[m]))]
        res["per_tile_phase_max"] = float(max(abs(v) for p in ph.values() for v in p)) if ph else 0.0
    return res


def render(ws: list[tuple[str, dict]], out: str, grid: float) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle

    fig, axes = plt.subplots(1, len(ws), figsize=(7 * len(ws), 7))
    axes = np.atleast_1d(axes)
    cols = {"vine": "#2b7a2b", "hook": "#a3231f", "teardrop": "#d9a441", "lotus": "#1f4fa3", "peony": "#8a1fa3", "seed": "k"}
    for ax, (name, w) in zip(axes, ws):
        T = w["tile"]
        c = 2 * T
        lo, hi = c - 0.75 * T, c + 0.75 * T
        m = (w["x"] > lo) & (w["x"] < hi) & (w["y"] > lo) & (w["y"] < hi)
        kinds = w["kinds"]
        for k, kn in enumerate(kinds):
            mk = m & (w["kind"] == k)
            if kn in ("lotus", "peony"):
                ax.add_collection(PatchCollection([Circle((a, b), 6.0) for a, b in zip(w["x"][mk], w["y"][mk])],
                                                  facecolor=cols.get(kn, "k"), alpha=0.5, edgecolor="none"))
            else:
                ax.scatter(w["x"][mk], w["y"][mk], s=3, c=cols.get(kn, "k"), label=kn)
        for v in (T, 2 * T, 3 * T):
            ax.axvline(v, color="k", lw=0.8)
            ax.axhline(v, color="k", lw=0.8)
        gl = np.arange(np.ceil(lo / grid), np.floor(hi / grid) + 1) * grid
        for v in gl:
            ax.axvline(v, color="0.8", lw=0.4, zorder=0)
            ax.axhline(v, color="0.8", lw=0.4, zorder=0)
        ax.set_xlim(lo, hi)
        ax.set_ylim(lo, hi)
        ax.set_aspect("equal")
        ax.set_title(f"{name} T {T:g} (corner at {c:g}, {c:g})")
        ax.legend(loc="upper right", fontsize=7, markerscale=3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tags", nargs="+")
    ap.add_argument("--png", default=None)
    ap.add_argument("--tiles", default=None, help="only these tile sizes")
    args = ap.parse_args()
    sys.path.insert(0, str(HERE.parent / "src"))
    from strew.ornament.patterns.vase import GRID

    ws = []
    for tag in args.tags:
        for p in sorted(RES.glob(f"orn19m_{tag}_T*.npz")):
            w = _load(p)
            if args.tiles and f"{w['tile']:g}" not in args.tiles.split(","):
                continue
            r = grid_report(w, GRID)
            print(f"{tag} T {w['tile']:g}: {len(w['x']):,} el, {r['flowers']} flowers, off the world lattice {r['off_lattice']}, "
                  f"occupancy {r['occupancy']:.3f}; by grid rows from a border "
                  + ", ".join(f"{k}: {v[0]:.3f} (n {v[1]})" for k, v in r["occupancy_by_rows"].items())
                  + f"; border lines' phase {['%.1f' % v for v in r['border_phase']]}"
                  + (f"; per-tile phase max {r['per_tile_phase_max']:.2f}" if "per_tile_phase_max" in r else ""))
            ws.append((tag, w))
    if args.png:
        render(ws, args.png, GRID)


if __name__ == "__main__":
    main()

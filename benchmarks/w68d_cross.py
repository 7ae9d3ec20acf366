"""w68d: in the untiled control, where the vines near an inner border grew from (issue 19.4 point 4).

``python benchmarks/w68d_cross.py --tiles 32,40,48`` grows the control (hierarchy, one run seeded at the tiled
world's four first-phase seed points, hie15_make.tiled_seed_points; seed 19) and, for each vine centred within
3 s of an inner border (signed distance orn19m_willow._sd, negative on the earlier tile's side, s the world's
mean spacing), asks whether its parent's centre lies across that border. A tiled world's finished tile cannot
grow the vines whose parents lie across (the later tile's side is empty when it grows) and the later tile finds
the finished side already filled by the later phases: the share of such vines bounds what a finished side can
hold of the control's vines in that band.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--tiles", default="32,40,48")
    ap.add_argument("--kinds", default="vine", help="comma-separated element types (each row: its own parent)")
    args = ap.parse_args()
    from hie15_make import tiled_seed_points
    from orn19m_willow import _sd

    import strew
    from strew.ornament._engine import grow_elements

    edges = np.arange(-3.0, 3.0 + 1e-9, 1.0)
    kinds = args.kinds.split(",")
    tot = np.zeros((len(kinds), len(edges) - 1))
    cross = np.zeros((len(kinds), len(edges) - 1))
    for tile in [float(v) for v in args.tiles.split(",")]:
        side = 4 * tile
        orn = grow_elements("hierarchy", strew.Region.rectangle(side, side), seeds=tiled_seed_points(tile), rng=19)
        els = [e for e in orn.elements if e.type != "seed"]
        n = len(els)
        s = 1.0 / np.sqrt(n / side**2)
        for ki, kind in enumerate(kinds):
            vines = [e for e in els if e.type == kind and e.parent is not None and e.parent.type != "seed"]
            _count(vines, side, tile, s, edges, tot[ki], cross[ki], _sd)
        print(f"T{tile:g}: {n} elements, s {s:.2f}", flush=True)
    for ki, kind in enumerate(kinds):
        print(f"{kind}: bin (s)   n  parent across  share")
        for k in range(len(edges) - 1):
            print(f"  [{edges[k]:+.0f},{edges[k + 1]:+.0f})  {tot[ki, k]:6.0f}  {cross[ki, k]:6.0f}  {cross[ki, k] / max(tot[ki, k], 1):.3f}")


def _count(vines, side, tile, s, edges, tot, cross, _sd) -> None:
    xy = np.array([np.asarray(e.proxies[0].bounding_circle()[:2]) for e in vines])
    pxy = np.array([np.asarray(e.parent.proxies[0].bounding_circle()[:2]) for e in vines])
    _, sd = _sd(xy[:, 0], xy[:, 1], side, tile)
    sd = sd / s
    # across: the parent's centre on the other side of the vine's nearest inner border line
    lines = np.arange(1, 4) * tile
    ix = np.argmin(np.abs(xy[:, 0][:, None] - lines), axis=1)
    iy = np.argmin(np.abs(xy[:, 1][:, None] - lines), axis=1)
    dx = np.abs(xy[:, 0] - lines[ix])
    dy = np.abs(xy[:, 1] - lines[iy])
    vert = dx <= dy
    ax = np.where(vert, 0, 1)
    L = np.where(vert, lines[ix], lines[iy])
    v = xy[np.arange(len(xy)), ax] - L
    p = pxy[np.arange(len(xy)), ax] - L
    across = v * p < 0
    b = np.digitize(sd, edges) - 1
    ok = (b >= 0) & (b < len(edges) - 1)
    np.add.at(tot, b[ok], 1)
    np.add.at(cross, b[ok], across[ok])


if __name__ == "__main__":
    main()

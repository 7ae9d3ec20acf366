"""Where pack's surplus at a tile border comes from, on strew demo's trees (issue 19.4).

Two tiles as in ``benchmarks/pack_seam_two_tiles.py --input trees`` (trees scale 0.2-1.0,
rotation +-0.15, halo 60, border at x = 0, A packed on [-220, 75], B on [-75, 160]), the
surplus taken apart: by the tile that placed each element (A's kept, B's), by scale bin
(0.2-0.4 .. 0.8-1.0), by distance from the border (bins of one spacing s), and B's
elements on A's side by where they sit: in a *hole* (the position within the disc of
bounding radius about one of A's dropped elements, as strew.tiles._in_holes; ``--disc
bbox``: the box centre in the disc about the box centre that circumscribes it) or in a *gap* of A's kept packing.
Also printed: the covered area's ratio (the elements' area per unit area) in each bin.

``--handover``:
  ``ramp``: strew.tiles today (``_ramp``): A drops an element at distance d before the
  border with probability (1 - min(1, d / halo)) (a_min / a) ** 0.5; B packs its whole
  grown rectangle around A's kept elements.
  ``holes``: as ``ramp``, but B's region on A's side is only the union of its dropped
  elements' circumscribed discs (grown by ``--grow`` spacings): B refills the holes
  and nothing else of A's packing.
  ``holes-filter``: as ``ramp``, then B's elements centred on A's side outside every
  dropped disc are dropped.
  ``centre``: A keeps the centres before the border, B's region reaches one halo.
  ``tiles``: as ``ramp``, then B's elements positioned on A's side are kept by
  ``strew.tiles._in_holes`` (the world's rule), given A's dropped elements.

Run: ``python benchmarks/pack_seam_split.py [--seeds 12] [--height 1200] [--handover ramp|holes|holes-filter|centre]
[--grow 0] [--exponent 0.5]``; writes ``benchmarks/results/pack_seam_split_<handover>.json``.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent


def main() -> None:
    import shapely

    import strew
    import strew.tiles
    from strew._resources import example_path
    from strew.io import load_shapes
    from strew.pack import pack

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=12)
    ap.add_argument("--height", type=float, default=1200.0)
    ap.add_argument("--handover", choices=("ramp", "holes", "holes-filter", "centre", "tiles"), default="ramp")
    ap.add_argument("--grow", type=float, default=0.0, help="holes: the dropped discs grown by this many spacings")
    ap.add_argument("--exponent", type=float, default=0.5)
    ap.add_argument("--width", type=float, default=None, help="the ramp's width in spacings [the halo]")
    ap.add_argument("--disc", choices=("bbox", "origin"), default="origin",
                    help="hole discs about the dropped elements' positions with their bounding radius (strew.tiles), or their boxes' centres")
    ap.add_argument("--tag", default="")
    ap.add_argument("--quick", action="store_true", help="3 seeds, tag _quick (a check of the script)")
    args = ap.parse_args()
    if args.quick:
        args.seeds, args.tag = 3, args.tag + "_quick"
    lib = load_shapes(example_path("pack", "trees.json"))
    kw = {"scale": (0.2, 1.0), "rotation": (-0.15, 0.15)}
    h, border, x_a, x_b = 60.0, 0.0, -220.0, 160.0
    reach = 1.0 if args.handover == "centre" else 1.25
    g = h * reach
    height = args.height
    nb = 18  # one-spacing bins, -9 s .. +9 s
    sb = np.array([0.2, 0.4, 0.6, 0.8, 1.0001])
    cnt = {k: np.zeros((nb, 4)) for k in ("A", "B_hole", "B_gap", "B_own")}
    area = np.zeros(nb)
    t0 = time.process_time()
    s = 12.46  # A's interior spacing (pack_seam_two_tiles --input trees)
    for seed in range(args.seeds):
        a = pack(lib, strew.Region(shapely.box(x_a, 0, border + g, height)), rng=100 + seed, **kw)
        geo = np.asarray(a.geometry_of("geometry"))
        b0 = shapely.bounds(geo)
        xa = (b0[:, 0] + b0[:, 2]) / 2
        width = h if args.width is None else min(h, args.width * s)
        if args.handover == "centre":
            keep = xa < border
        else:
            u = np.random.default_rng(300 + seed).random(len(a))
            sc = np.abs(np.asarray(a.scale, float).reshape(len(a), -1))
            ar = np.array([float(a.shapes[k].area) for k in a.kinds])[a.kind] * sc[:, 0] * sc[:, -1]
            w = (ar.min() / ar) ** args.exponent
            keep = (a.x < border) & (u >= (1 - np.clip((border - a.x) / width, 0, 1)) * w)
        dm = (~keep) & (a.x < border)
        dropped = geo[dm]
        if args.disc == "origin":  # strew.tiles._hole_discs: the position, the bounding radius
            cen = shapely.points(a.x[dm], a.y[dm])
            rad = np.array([float(a.shapes[k].radius) for k in a.kinds])[a.kind[dm]] * np.abs(np.asarray(a.scale, float).reshape(len(a), -1)[dm, 0])
        else:
            cen = shapely.centroid(shapely.envelope(dropped))
            rad = np.array([np.max(np.hypot(*(shapely.get_coordinates(p) - shapely.get_coordinates(c)).T)) for p, c in zip(dropped, cen)]) \
                if len(dropped) else np.zeros(0)
        discs = shapely.buffer(cen, rad + args.grow * s)
        holes = shapely.union_all(discs) if len(discs) else shapely.Polygon()
        hole_xyr = strew.tiles._hole_discs(a, ~keep)  # as strew.tiles.run_tile: the ramp's and those past the border
        a, xa = a.select(keep), xa[keep]
        ctx = a.select(xa > border - 2 * h)
        rb = shapely.box(border - g, 0, x_b, height)
        if args.handover == "holes":
            rb = shapely.union(shapely.intersection(holes, rb), shapely.box(border, 0, x_b, height))
        b = pack(lib, strew.Region(rb), context=ctx, rng=200 + seed, **kw)
        gb = np.asarray(b.geometry_of("geometry"))
        bb = shapely.bounds(gb)
        xb = (bb[:, 0] + bb[:, 2]) / 2
        cb = shapely.points(b.x, b.y) if args.disc == "origin" else shapely.points(xb, (bb[:, 1] + bb[:, 3]) / 2)
        in_hole = shapely.contains(holes, cb) if len(discs) else np.zeros(len(b), bool)
        if args.handover == "tiles":  # strew.tiles._in_holes, the rule of the tiled world
            mine = b.x < border
            k2 = np.ones(len(b), bool)
            k2[mine] = strew.tiles._in_holes(b.select(mine), (ctx.with_meta(holes=hole_xyr),), {0: [(0.0, 0.0)]}, ctx)
            b, xb, gb, in_hole = b.select(k2), xb[k2], gb[k2], in_hole[k2]
        if args.handover == "holes-filter":
            k2 = (xb >= border) | in_hole
            b, xb, gb, in_hole = b.select(k2), xb[k2], gb[k2], in_hole[k2]
        edges = border + np.arange(-nb // 2, nb // 2 + 1) * s

        def add(key, x, scale, m):
            i = np.searchsorted(edges, x[m]) - 1
            j = np.searchsorted(sb, np.asarray(scale, float).reshape(len(x), -1)[m, 0]) - 1
            ok = (i >= 0) & (i < nb)
            np.add.at(cnt[key], (i[ok], np.clip(j[ok], 0, 3)), 1)

        add("A", xa, a.scale, np.ones(len(a), bool))
        add("B_hole", xb, b.scale, (xb < border) & in_hole)
        add("B_gap", xb, b.scale, (xb < border) & ~in_hole)
        add("B_own", xb, b.scale, xb >= border)
        for x, gg in ((xa, np.asarray(a.geometry_of("geometry"))), (xb, gb)):
            i = np.searchsorted(edges, x) - 1
            ok = (i >= 0) & (i < nb)
            np.add.at(area, i[ok], shapely.area(gg[ok]))
    cpu = time.process_time() - t0
    tot = sum(cnt.values())
    far = np.r_[0:2, nb - 2:nb]
    ref = tot[far].sum(axis=1).mean()
    ref_k = tot[far].mean(axis=0)
    aref = area[far].mean()
    print(f"pack seam split, trees, {args.seeds} seeds, height {height:g}, handover {args.handover}"
          f"{f', grow {args.grow:g} s' if args.handover == 'holes' else ''}, exponent {args.exponent:g}: {cpu:.1f} CPU s")
    print("  bins of one spacing, -9 s .. +9 s (far: beyond 7 s), density / far density")
    rows = {}
    for k in ("A", "B_hole", "B_gap", "B_own"):
        rows[k] = cnt[k].sum(axis=1) / ref
        print(f"  {k:7s} " + " ".join(f"{v:.2f}" for v in rows[k]))
    rows["all"] = tot.sum(axis=1) / ref
    rows["area"] = area / aref
    print(f"  {'all':7s} " + " ".join(f"{v:.2f}" for v in rows["all"]))
    print(f"  {'area':7s} " + " ".join(f"{v:.2f}" for v in rows["area"]))
    for j, lab in enumerate(("0.2-0.4", "0.4-0.6", "0.6-0.8", "0.8-1.0")):
        rows[f"scale {lab}"] = tot[:, j] / ref_k[j]
        print(f"  sc {lab} " + " ".join(f"{v:.2f}" for v in rows[f"scale {lab}"]))
    mid = nb // 2
    r1 = float(rows["all"][mid - 1:mid + 1].mean())
    r2 = float(rows["all"][mid - 2:mid + 2].mean())
    r1a = float(rows["area"][mid - 1:mid + 1].mean())
    print(f"  density +-1s {r1:.3f}, +-2s {r2:.3f}; covered area +-1s {r1a:.3f}; on A's side within the reach, B's elements: "
          f"{int(cnt['B_hole'].sum())} in holes, {int(cnt['B_gap'].sum())} in gaps")
    out = HERE / "results" / f"pack_seam_split_{args.handover}{args.tag}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"command": "python benchmarks/pack_seam_split.py " + " ".join(f"--{k} {v}" for k, v in vars(args).items()),
                               "cpu_s": cpu, "ratio_1s": r1, "ratio_2s": r2, "area_1s": r1a,
                               "rows": {k: np.round(v, 4).tolist() for k, v in rows.items()}}, indent=1))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

"""Pack's seam at one tile border, taken apart by which tile placed each element (issue 19.4).

The tiled world (:mod:`strew.tiles`) packs a phase-0 tile A in its rectangle grown by
``reach`` and hands the border over to the later tile B; B packs its grown rectangle
around A's kept elements (the ``context``) and keeps everything it places. Here that
happens for one vertical border (x = 0 of the profile), with the bar and disc of
``benchmarks/worlds_strips.py`` (its pack world, halo 3.3541), for several seeds.

``--handover``: ``ramp`` (strew.tiles today, ``_ramp``): A drops an element at distance
``d`` before the border with probability ``(1 - min(1, d / halo)) (a_min / a) ** 0.5``
(``a`` its area) and the regions reach 1.25 halo; ``centre`` (strew.tiles before): A keeps the centres before the border, the regions
reach one halo. ``--reach R``: the regions' reach in halos instead.

Printed: the density of element centres (bounding-box centres) in bins of half a spacing
from -3 s to +3 s (positive: into B), as a ratio to the far bins of the same run (beyond
4 s on both sides), split into A's elements, B's elements and all; the ratios over +-1 s
and +-2 s; and for B's elements centred on A's side, how late in B's Step 2 they came
(the quartiles of their rank, 0 = first Step 2 placement, 1 = last).

``--kw '{"fits": 1}'``: parameters for both tiles' ``pack`` (to try a variant).

``--input trees``: strew demo's trees (scale 0.2-1.0, halo 60, about 4.8 s; border at x = 0,
A from -220, B to 160, bins -9 s .. +9 s, printed -6 s .. +6 s, the far bins beyond 7 s,
"bars' share" is the oaks'). Ramp variants: ``--width Ns`` (the ramp N of A's spacings wide,
at most the halo), ``--exponent E`` (of the area ratio), ``--cut C`` (B drops its elements
centred deeper than C ramp widths into A). Trees, 12 seeds, height 1200 (issue 19.4): the
halo-wide ramp gives +-1s 1.078, and A's side is 1.06-1.24 of the far bins over its whole
ramp and beyond it, as deep as B's region reaches (B alone adds 4-9 % there: a second pack
over a full packing still finds room for the smallest trees); a ramp of 2 s with the cut
leaves A's side beyond the ramp at 1.00 but the ramp itself at 1.09-1.16 (+-1s 1.078,
exponent 1: 1.093; a 1 s ramp 1.131): the holes are refilled by more, smaller trees. The
centre hand-over gives 1.185 here (the world, d66b77e: 1.187), and B adds 6-9 % to A's
full packing there too: A's own pack is not saturated for the smallest trees.

Run: ``python benchmarks/pack_seam_two_tiles.py [--seeds 8] [--kw JSON] [--handover ramp|centre] [--height 200]
[--input trees] [--width halo|Ns] [--exponent 0.5] [--cut C]``; writes
``benchmarks/results/pack_seam_two_tiles.json``.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent


def _centres(arr) -> np.ndarray:
    import shapely

    b = shapely.bounds(np.asarray(arr.geometry_of("geometry")))
    return (b[:, 0] + b[:, 2]) / 2


def main() -> None:
    import shapely

    import strew
    from strew.pack import pack

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=8)
    ap.add_argument("--kw", default="{}", help="JSON parameters for pack (both tiles)")
    ap.add_argument("--halo", type=float, default=3.3541, help="the halo (worlds_strips' pack world: 3.3541)")
    ap.add_argument("--handover", choices=("ramp", "centre"), default="ramp", help="A's keep rule (see the docstring)")
    ap.add_argument("--reach", type=float, default=None, help="the regions' reach in halos [1.25 with ramp, 1 with centre]")
    ap.add_argument("--height", type=float, default=200.0, help="the border's length")
    ap.add_argument("--input", choices=("bar_disc", "trees"), default="bar_disc",
                    help="trees: strew demo's trees, scale 0.2-1.0, rotation +-0.15, halo 60 (benchmarks/pack_seam_trees.py)")
    ap.add_argument("--exponent", type=float, default=0.5, help="the area ratio's exponent in the drop probability")
    ap.add_argument("--width", default="halo", help="the ramp's width: 'halo', or 'Ns' (N of A's spacings, at most the halo)")
    ap.add_argument("--cut", type=float, default=None,
                    help="B drops its elements centred in A deeper than CUT ramp widths (strew.tiles._ramp: 1.25)")
    ap.add_argument("--out", default=None, help="[benchmarks/results/pack_seam_two_tiles.json; --quick: pack_seam_two_tiles_quick.json]")
    ap.add_argument("--quick", action="store_true", help="3 seeds, JSON to pack_seam_two_tiles_quick.json (a check of the script)")
    args = ap.parse_args()
    if args.quick:
        args.seeds = 3
    args.out = args.out or str(HERE / "results" / f"pack_seam_two_tiles{'_quick' if args.quick else ''}.json")
    kw = json.loads(args.kw)
    reach = (1.25 if args.handover == "ramp" else 1.0) if args.reach is None else args.reach
    lib = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
    h, border = args.halo, 100.0
    x_a, x_b = 40.0, 160.0
    n_bins = 24  # half spacings, -6 s .. +6 s (trees: -9 s .. +9 s, past their ramp of 4.9 s)
    if args.input == "trees":
        from strew._resources import example_path
        from strew.io import load_shapes

        lib = load_shapes(example_path("pack", "trees.json"))
        kw = {"scale": (0.2, 1.0), "rotation": (-0.15, 0.15), **kw}
        h = 60.0 if args.halo == 3.3541 else args.halo
        border, x_a, x_b, n_bins = 0.0, -220.0, 160.0, 36
    acc = {"A": np.zeros(n_bins), "B": np.zeros(n_bins)}
    bars = np.zeros(n_bins)
    g = h * reach
    height = args.height
    late = []
    t0 = time.process_time()
    s = None
    for seed in range(args.seeds):
        a = pack(lib, strew.Region(shapely.box(x_a, 0, border + g, height)), rng=100 + seed, **kw)
        xa = _centres(a)
        if s is None:  # the spacing of A's interior
            inner = (xa > x_a + 10) & (xa < border - 10)
            s = 1.0 / np.sqrt(np.count_nonzero(inner) / ((border - x_a - 20) * height))
        width = h if args.width == "halo" else min(h, float(args.width.rstrip("s")) * s)
        if args.handover == "ramp":  # strew.tiles._ramp (on the element's position, here the centre)
            u = np.random.default_rng(300 + seed).random(len(a))
            sc = np.abs(np.asarray(a.scale, float).reshape(len(a), -1))
            area = np.array([float(a.shapes[k].area) for k in a.kinds])[a.kind] * sc[:, 0] * sc[:, -1]
            w = (area.min() / area) ** args.exponent
            keep = (a.x < border) & (u >= (1 - np.clip((border - a.x) / width, 0, 1)) * w)
        else:
            keep = xa < border
        a, xa = a.select(keep), xa[keep]
        ctx = a.select(xa > border - 2 * h)
        b = pack(lib, strew.Region(shapely.box(border - g, 0, x_b, height)), context=ctx, rng=200 + seed, **kw)
        if args.cut is not None:
            b = b.select(b.x >= border - args.cut * width)
        xb = _centres(b)
        edges = border + np.arange(-n_bins // 2, n_bins // 2 + 1) * s / 2
        acc["A"] += np.histogram(xa, edges)[0]
        acc["B"] += np.histogram(xb, edges)[0]
        k0 = a.kinds[0]  # bar (bar_disc), oak (trees)
        bars += np.histogram(xa[a.kind == a.kinds.index(k0)], edges)[0] + np.histogram(xb[b.kind == b.kinds.index(k0)], edges)[0]
        n1 = int(b.meta["pack"].get("sparse", 0))
        rank = (np.arange(len(b)) - n1) / max(len(b) - n1, 1)
        late += list(rank[(xb < border) & (np.arange(len(b)) >= n1)])
    cpu = time.process_time() - t0
    tot = acc["A"] + acc["B"]
    far = np.r_[0:4, n_bins - 4:n_bins]
    ref = tot[far].mean()
    prof = {k: (v / ref) for k, v in (("A", acc["A"]), ("B", acc["B"]), ("all", tot))}
    mid = n_bins // 2
    r1 = float(prof["all"][mid - 2:mid + 2].mean())
    r2 = float(prof["all"][mid - 4:mid + 4].mean())
    sel = slice(mid - 6, mid + 6) if args.input == "bar_disc" else slice(mid - 12, mid + 12)
    share = float(bars[mid - 2:mid + 2].sum() / tot[mid - 2:mid + 2].sum() / (bars[far].sum() / tot[far].sum()))
    print(f"pack seam, two tiles, {args.seeds} seeds, kw {kw}, handover {args.handover}, reach {reach:g} halo: "
          f"spacing {s:.3f}, {cpu:.1f} CPU s")
    for k in ("A", "B", "all"):
        print(f"  {k:3s} (s/2 bins, {'-3s..+3s' if args.input == 'bar_disc' else '-6s..+6s'} into B): " + " ".join(f"{v:.2f}" for v in prof[k][sel]))
    q = np.percentile(late, [25, 50, 75]).round(2).tolist() if late else []
    print(f"  density ratio +-1s {r1:.3f}, +-2s {r2:.3f} (vs bins beyond {4 if args.input == 'bar_disc' else 7} s); bars' share +-1s {share:.3f} of theirs")
    print(f"  B's elements centred in A: {len(late)}, their rank in B's Step 2 (quartiles) {q}")
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"input": args.input, "width": args.width, "exponent": args.exponent, "cut": args.cut,
                               "seeds": args.seeds, "kw": {k: v for k, v in kw.items()}, "halo": h, "handover": args.handover, "reach_halos": reach,
                               "height": height, "bar_share_ratio_1s": share, "spacing": s, "cpu_s": cpu,
                               "profile": {k: v[sel].round(4).tolist() for k, v in prof.items()},
                               "ratio_1s": r1, "ratio_2s": r2, "b_in_a": len(late), "b_in_a_rank_quartiles": q},
                              indent=1))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

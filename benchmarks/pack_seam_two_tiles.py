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

Run: ``python benchmarks/pack_seam_two_tiles.py [--seeds 8] [--kw JSON] [--handover ramp|centre] [--height 200]``; writes
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
    ap.add_argument("--out", default=str(HERE / "results" / "pack_seam_two_tiles.json"))
    args = ap.parse_args()
    kw = json.loads(args.kw)
    reach = (1.25 if args.handover == "ramp" else 1.0) if args.reach is None else args.reach
    lib = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
    h, border = args.halo, 100.0
    n_bins = 24  # half spacings, -6 s .. +6 s
    acc = {"A": np.zeros(n_bins), "B": np.zeros(n_bins)}
    bars = np.zeros(n_bins)
    g = h * reach
    height = args.height
    late = []
    t0 = time.process_time()
    s = None
    for seed in range(args.seeds):
        a = pack(lib, strew.Region(shapely.box(40, 0, border + g, height)), rng=100 + seed, **kw)
        xa = _centres(a)
        if s is None:  # the spacing of A's interior
            inner = (xa > 50) & (xa < border - 10)
            s = 1.0 / np.sqrt(np.count_nonzero(inner) / ((border - 60) * height))
        if args.handover == "ramp":  # strew.tiles._ramp (on the element's position, here the centre)
            u = np.random.default_rng(300 + seed).random(len(a))
            sc = np.abs(np.asarray(a.scale, float).reshape(len(a), -1))
            area = np.array([float(a.shapes[k].area) for k in a.kinds])[a.kind] * sc[:, 0] * sc[:, -1]
            w = (area.min() / area) ** 0.5
            keep = (a.x < border) & (u >= (1 - np.clip((border - a.x) / h, 0, 1)) * w)
        else:
            keep = xa < border
        a, xa = a.select(keep), xa[keep]
        ctx = a.select(xa > border - 2 * h)
        b = pack(lib, strew.Region(shapely.box(border - g, 0, 160, height)), context=ctx, rng=200 + seed, **kw)
        xb = _centres(b)
        edges = border + np.arange(-n_bins // 2, n_bins // 2 + 1) * s / 2
        acc["A"] += np.histogram(xa, edges)[0]
        acc["B"] += np.histogram(xb, edges)[0]
        bars += np.histogram(xa[a.kind == a.kinds.index("bar")], edges)[0] + np.histogram(xb[b.kind == b.kinds.index("bar")], edges)[0]
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
    sel = slice(mid - 6, mid + 6)
    share = float(bars[mid - 2:mid + 2].sum() / tot[mid - 2:mid + 2].sum() / (bars[far].sum() / tot[far].sum()))
    print(f"pack seam, two tiles, {args.seeds} seeds, kw {kw}, handover {args.handover}, reach {reach:g} halo: "
          f"spacing {s:.3f}, {cpu:.1f} CPU s")
    for k in ("A", "B", "all"):
        print(f"  {k:3s} (s/2 bins, -3s..+3s into B): " + " ".join(f"{v:.2f}" for v in prof[k][sel]))
    q = np.percentile(late, [25, 50, 75]).round(2).tolist() if late else []
    print(f"  density ratio +-1s {r1:.3f}, +-2s {r2:.3f} (vs bins beyond 4 s); bars' share +-1s {share:.3f} of theirs")
    print(f"  B's elements centred in A: {len(late)}, their rank in B's Step 2 (quartiles) {q}")
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"seeds": args.seeds, "kw": kw, "halo": h, "handover": args.handover, "reach_halos": reach,
                               "height": height, "bar_share_ratio_1s": share, "spacing": s, "cpu_s": cpu,
                               "profile": {k: v[sel].round(4).tolist() for k, v in prof.items()},
                               "ratio_1s": r1, "ratio_2s": r2, "b_in_a": len(late), "b_in_a_rank_quartiles": q},
                              indent=1))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

"""Pack's seam at one tile border, taken apart by which tile placed each element (issue 19.4).

The tiled world (:mod:`strew.tiles`) packs a phase-0 tile A in its rectangle grown by the
halo and keeps the elements whose centre lies in A; the later tile B packs its grown
rectangle around A's kept elements (the ``context``) and keeps everything it places. Here
that happens for one vertical border (x = 0 of the profile), with the bar and disc of
``benchmarks/worlds_strips.py`` (its pack world, halo 3.3541), for several seeds.

Printed: the density of element centres (bounding-box centres) in bins of half a spacing
from -3 s to +3 s (positive: into B), as a ratio to the far bins of the same run (beyond
4 s on both sides), split into A's elements, B's elements and all; the ratios over +-1 s
and +-2 s; and for B's elements centred on A's side, how late in B's Step 2 they came
(the quartiles of their rank, 0 = first Step 2 placement, 1 = last).

``--kw '{"fits": 1}'``: parameters for both tiles' ``pack`` (to try a variant).

Run: ``python benchmarks/pack_seam_two_tiles.py [--seeds 8] [--kw JSON]``; writes
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
    ap.add_argument("--out", default=str(HERE / "results" / "pack_seam_two_tiles.json"))
    args = ap.parse_args()
    kw = json.loads(args.kw)
    lib = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
    h, border = args.halo, 100.0
    n_bins = 24  # half spacings, -6 s .. +6 s
    acc = {"A": np.zeros(n_bins), "B": np.zeros(n_bins)}
    late = []
    t0 = time.process_time()
    s = None
    for seed in range(args.seeds):
        a = pack(lib, strew.Region(shapely.box(40, 0, border + h, 200)), rng=100 + seed, **kw)
        xa = _centres(a)
        if s is None:  # the spacing of A's interior
            inner = (xa > 50) & (xa < border - 10)
            s = 1.0 / np.sqrt(np.count_nonzero(inner) / ((border - 60) * 200))
        keep = xa < border
        a, xa = a.select(keep), xa[keep]
        ctx = a.select(xa > border - 2 * h)
        b = pack(lib, strew.Region(shapely.box(border - h, 0, 160, 200)), context=ctx, rng=200 + seed, **kw)
        xb = _centres(b)
        edges = border + np.arange(-n_bins // 2, n_bins // 2 + 1) * s / 2
        acc["A"] += np.histogram(xa, edges)[0]
        acc["B"] += np.histogram(xb, edges)[0]
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
    print(f"pack seam, two tiles, {args.seeds} seeds, kw {kw}: spacing {s:.3f}, {cpu:.1f} CPU s")
    for k in ("A", "B", "all"):
        print(f"  {k:3s} (s/2 bins, -3s..+3s into B): " + " ".join(f"{v:.2f}" for v in prof[k][sel]))
    q = np.percentile(late, [25, 50, 75]).round(2).tolist() if late else []
    print(f"  density ratio +-1s {r1:.3f}, +-2s {r2:.3f} (vs bins beyond 4 s)")
    print(f"  B's elements centred in A: {len(late)}, their rank in B's Step 2 (quartiles) {q}")
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"seeds": args.seeds, "kw": kw, "halo": h, "spacing": s, "cpu_s": cpu,
                               "profile": {k: v[sel].round(4).tolist() for k, v in prof.items()},
                               "ratio_1s": r1, "ratio_2s": r2, "b_in_a": len(late), "b_in_a_rank_quartiles": q},
                              indent=1))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

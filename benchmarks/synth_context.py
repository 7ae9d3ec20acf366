"""synth's ``context`` as neighbourhood (issues 13, 18, 19): seams where a region is grown
beside finished elements.

For each fidelity-suite class: synth fills a rectangle 3 x 3 frames (seed 1); its left
half is the context, and synth fills the whole rectangle again around it (seed 101),
once with the context as neighbourhood (today) and once with the context only an
obstacle (the baseline: ``add_context`` disabled, what synth did before). Printed: the
density of a strip half a frame wide across the seam over the new half's interior, the
largest difference of a kind's fraction between them, and the share of failing windows
of the local fidelity map of the union (``strew.metrics.fidelity``). With ``--tiles``,
also ``strew.tiles.tiled("synth", stones.svg, 600 x 400, tile 100)``: the density of
strips 10 wide along tile borders over the rest.

    python benchmarks/synth_context.py [--only two_sizes,clusters] [--tiles]
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from _runner import Bench, parse_args

from strew import Region
from strew.arrangement import concat
from strew.metrics import fidelity, overlaps
from strew.synth import synthesize

ROOT = Path(__file__).resolve().parents[1]


def _suite():
    from _runner import fidelity_suite

    return fidelity_suite()


def strip(arr, xa, xb, ya, yb):
    m = (arr.x >= xa) & (arr.x < xb) & (arr.y >= ya) & (arr.y < yb)
    frac = np.bincount(np.asarray(arr.kind)[m], minlength=len(arr.kinds)) / max(int(m.sum()), 1)
    return m.sum() / ((xb - xa) * (yb - ya)), frac


def halves(ex, neighbourhood: bool) -> dict:
    import strew.synth._context as C

    x0, y0, x1, y1 = ex.region.bounds
    w, h = 3 * (x1 - x0), 3 * (y1 - y0)
    region = Region.rectangle(w, h)
    first = synthesize(ex, region, rng=1, measure=False)
    ctx = first.select(first.x < w / 2)
    orig = C.add_context
    if not neighbourhood:
        C.add_context = lambda *a, **k: np.zeros(0, np.int64)
    try:
        new = synthesize(ex, region, rng=101, measure=False, context=ctx)
    finally:
        C.add_context = orig
    both = concat([ctx, new])
    band = 0.5 * (x1 - x0)
    d_in, f_in = strip(new, w / 2 + band, w - band / 2, 0.1 * h, 0.9 * h)
    d_s, f_s = strip(both, w / 2 - band / 2, w / 2 + band / 2, 0.1 * h, 0.9 * h)
    rep = fidelity(ex, both, region, eq5=False)
    score = np.asarray(rep.local["score"], float)
    ok = np.isfinite(score)
    return {"seam_density": round(float(d_s / d_in), 3), "max_fraction_diff": round(float(np.abs(f_s - f_in).max()), 3),
            "failing_windows": round(float(np.mean(score[ok] > 1.0)), 3), "faithful": rep.faithful, "overlaps": len(overlaps(both)[0])}


def tiles_border() -> float:
    from strew.io import load
    from strew.tiles import tiled

    ex = load(ROOT / "examples" / "exemplars" / "stones.svg")
    W, H, T = 600.0, 400.0, 100.0
    a = tiled("synth", ex, (W, H), tile_size=T, seed=1)
    band = 0.1 * T
    x, y = a.x, a.y
    inner = (x > band) & (x < W - band) & (y > band) & (y < H - band)
    near = lambda v: np.abs(((v + T / 2) % T) - T / 2) < band / 2  # noqa: E731
    border = inner & (near(x) | near(y))
    gx, gy = np.meshgrid(np.linspace(band, W - band, 600), np.linspace(band, H - band, 400))
    bfrac = float((near(gx) | near(gy)).mean())
    return float((border.sum() / bfrac) / ((inner & ~border).sum() / (1 - bfrac)))


def main() -> None:
    def extra(p) -> None:
        p.add_argument("--only", default="two_sizes,clusters,three_sizes,stones", help="suite classes, comma-separated")
        p.add_argument("--tiles", action="store_true", help="also the tile-border strips of strew.tiles")

    args = parse_args(__doc__.splitlines()[0], extra)
    mk = _suite()
    bench = Bench("synth_context", "synth grown beside a finished half: context as neighbourhood vs obstacle only", baseline="context as obstacle only", json_path=args.json)
    for name in args.only.split(","):
        ex = mk.make_exemplar(name)
        for nb in (False, True):
            r = halves(ex, nb)
            bench.row(name, context="neighbourhood" if nb else "obstacle", **r)
            print(f"  {name:12s} {'neighbourhood' if nb else 'obstacle':13s} {r}", flush=True)
    if args.tiles:
        ratio = tiles_border()
        bench.row("tiles stones.svg", context="neighbourhood", seam_density=round(ratio, 3))
        print(f"  tiles: border strips / rest {ratio:.3f}")
    bench.finish()


if __name__ == "__main__":
    main()

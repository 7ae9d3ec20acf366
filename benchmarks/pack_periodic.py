"""Benchmark of pack's repeat tiles (issue 18 point 1): periodic against plain, same run.

For each configuration (shapes of examples/pack in a rectangle, fill-gap and naive), a
``periodic=True`` pack next to a plain pack of the same size and seeds:

* time (median of ``--repeat`` runs per seed, then the median over seeds), count and
  coverage of the tile (the periodic tile's wrapped images, clipped), and their ratios
  periodic / plain;
* overlaps of the periodic tile laid 3 x 3 (``strew._periodic.tiled_copies``; must be 0);
* edge strips against the interior: strips two element diameters wide along the tile's
  four edges (the diameter of the largest kind's circumscribed circle at its largest
  scale), the ratio of element density (canonical centroids per area), of area coverage
  (wrapped images, clipped), and the largest difference of a kind's share. The plain
  pack is measured the same way, as if it were a tile (its elements keep off the edge:
  its strips are thinner).

Also ``poisson_disk`` on the torus against the plane at the same radius.

Run: ``python benchmarks/pack_periodic.py`` (``--quick``: smaller, one seed). Numba
compiles (or loads from its cache) every kernel in a warm-up before anything is timed.

Figures of ``python benchmarks/pack_periodic.py --repeat 3`` (300 x 260, seeds 1-3; the
shared 2-core machine at load 8-10, so time ratios swing by about 0.2 between runs):

============================  ==========  =====  =====  ========  ============  ==========  ==========
case                          time ratio  n      cov    3x3       edge density  edge cov    plain edge
                              per/plain   ratio  ratio  overlaps  per / inner   per/inner   density
============================  ==========  =====  =====  ========  ============  ==========  ==========
fill-gap elongated            1.22        1.01   1.01   0         1.01          1.00        0.96
fill-gap concave              0.90        1.04   1.04   0         0.99          0.99        0.92
fill-gap three kinds          0.96        1.03   1.03   0         1.01          1.01        0.96
fill-gap stones 0.25-0.5 fit  1.38        1.00   1.02   0         1.01          0.99        0.95
naive concave                 1.18        1.07   1.07   0         1.02          1.01        0.91
naive three kinds             1.21        1.04   1.04   0         1.00          1.00        0.92
poisson_disk r=0.5            1.88        1.00          0
============================  ==========  =====  =====  ========  ============  ==========  ==========

Kind shares in the strips differ from the interior's by 0.04-0.08 at most (three kinds,
about 150 elements in the strips: the binomial noise of a share of 1/3 is about 0.04).
Since this table the torus sampler wraps its grid indices and differences by one
comparison instead of a modulo: ``poisson_disk`` periodic / plain 1.43x (CPU, median of
5, 300 x 260, r = 0.5; was 1.88x wall above).

First run (empty numba cache): a periodic pack compiles its own specialisation of the
Step 2 loop (``_rounds`` with ``per`` an array; a plain pack's has ``per=None`` and none
of the torus branches), about 13 s of CPU after a plain pack has filled the cache.
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _runner import Bench, median_time, parse_args  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pack"


def strips(arr, width: float) -> tuple[float, float, float]:
    """(density ratio, coverage ratio, largest kind-share difference) of the edge strips
    of ``width`` against the interior of a periodic arrangement."""
    import numpy as np
    import shapely

    from strew import _periodic as P

    x0, y0, w, h = P.frame(arr)
    c = shapely.centroid(arr.geometry)
    cx, cy = P.canonical(shapely.get_x(c), shapely.get_y(c), (x0, y0, w, h))
    u, v = cx - x0, cy - y0
    edge = (u < width) | (u >= w - width) | (v < width) | (v >= h - width)
    inner = shapely.box(x0 + width, y0 + width, x0 + w - width, y0 + h - width)
    ring = shapely.box(x0, y0, x0 + w, y0 + h).difference(inner)
    density = (edge.sum() / ring.area) / max((~edge).sum() / inner.area, 1e-300)
    cover = shapely.union_all(P.images(arr).geometry)
    coverage = (shapely.area(shapely.intersection(cover, ring)) / ring.area) / (shapely.area(shapely.intersection(cover, inner)) / inner.area)
    share = max(abs((arr.kind[edge] == i).mean() - (arr.kind[~edge] == i).mean()) for i in range(len(arr.kinds)))
    return float(density), float(coverage), float(share)


def main() -> None:
    args = parse_args(__doc__.splitlines()[0])
    import numpy as np
    import shapely

    from strew import Region, load_shapes, metrics
    from strew import _periodic as P
    from strew.pack import pack, poisson_disk

    size = (150, 130) if args.quick else (300, 260)
    region = Region.rectangle(*size)
    seeds = [1] if args.quick else [1, 2, 3]
    naive_failures = 1000 if args.quick else 3000
    # (label, shapes file, keyword arguments)
    configs = [
        ("fill-gap elongated", "leaf.json", {"scale": (0.5, 0.5)}),
        ("fill-gap concave", "hook.json", {"scale": (0.4, 0.4)}),
        ("fill-gap three kinds", "mix.json", {"scale": (0.5, 0.5)}),
        ("fill-gap stones 0.25-0.5 fit", "stones.json", {"scale": (0.25, 0.5), "scale_choice": "fit"}),
        ("naive concave", "hook.json", {"scale": (0.4, 0.4), "method": "naive", "max_failures": naive_failures}),
        ("naive three kinds", "mix.json", {"scale": (0.5, 0.5), "method": "naive", "max_failures": naive_failures}),
    ]
    hook = load_shapes(EXAMPLES / "hook.json")
    for periodic in (False, True):  # warm-up: compile or load every kernel
        pack(hook, Region.rectangle(100, 100), rng=0, scale=(0.3, 0.3), periodic=periodic)
        pack(hook, Region.rectangle(100, 100), rng=0, scale=(0.3, 0.3), method="naive", max_failures=50, periodic=periodic)

    bench = Bench("pack_periodic", "strew.pack: periodic repeat tiles vs plain packs of the same size", baseline="plain (non-periodic)",
                  json_path=args.json)
    med = statistics.median
    for label, file, kw in configs:
        shapes = load_shapes(EXAMPLES / file)
        hi = kw["scale"][1]
        # the circumscribed circle about the bounding-box centre, as pack's §4.1 circle O
        diameter = 0.0
        for s in shapes.values():
            xy = shapely.get_coordinates(s.geometry)
            c = (xy.min(axis=0) + xy.max(axis=0)) / 2
            diameter = max(diameter, 2 * hi * float(np.sqrt(((xy - c) ** 2).sum(axis=1)).max()))
        width = 2 * diameter
        t_per, t_pl, n_per, n_pl, ov, d_per, c_per, s_per, d_pl, c_pl, cov_per, cov_pl = ([] for _ in range(12))
        for seed in seeds:
            t, a = median_time(lambda: pack(shapes, region, rng=seed, periodic=True, **kw), repeat=args.repeat, warmup=0)
            s, b = median_time(lambda: pack(shapes, region, rng=seed, **kw), repeat=args.repeat, warmup=0)
            t_per.append(t), t_pl.append(s), n_per.append(len(a)), n_pl.append(len(b))
            ov.append(len(metrics.overlaps(P.tiled_copies(a, 3, 3))[0]))
            tile = shapely.box(0, 0, *size)
            cov_per.append(shapely.area(shapely.intersection(shapely.union_all(P.images(a).geometry), tile)) / tile.area)
            cov_pl.append(metrics.coverage(b))
            d, c, sh = strips(a, width)
            d_per.append(d), c_per.append(c), s_per.append(sh)
            d, c, _ = strips(P.mark(b, P.frame_of_region(region)), width)
            d_pl.append(d), c_pl.append(c)
        bench.row(
            label,
            periodic_s=med(t_per),
            plain_s=med(t_pl),
            time_ratio=med(t_per) / med(t_pl),
            periodic_n=float(np.mean(n_per)),
            plain_n=float(np.mean(n_pl)),
            count_ratio=float(np.mean(n_per) / np.mean(n_pl)),
            cov_ratio=float(np.mean(cov_per) / np.mean(cov_pl)),
            overlaps_3x3=int(sum(ov)),
            strip_width=width,
            edge_density=float(np.mean(d_per)),
            edge_coverage=float(np.mean(c_per)),
            kind_share_diff=float(np.mean(s_per)),
            plain_edge_density=float(np.mean(d_pl)),
            plain_edge_coverage=float(np.mean(c_pl)),
        )

    radius = 1.0 if args.quick else 0.5
    t_per, pts = median_time(lambda: poisson_disk(size, radius, rng=1, periodic=True), repeat=args.repeat)
    t_pl, ref = median_time(lambda: poisson_disk(size, radius, rng=1), repeat=args.repeat)
    w, h = size
    copies = np.concatenate([pts + [i * w, j * h] for i in (-1, 0, 1) for j in (-1, 0, 1)])
    from scipy.spatial import cKDTree

    dmin = float(cKDTree(copies).query(pts, k=2)[0][:, 1].min())
    bench.row(
        f"poisson_disk r={radius:g}",
        periodic_s=t_per,
        plain_s=t_pl,
        time_ratio=t_per / t_pl,
        periodic_n=float(len(pts)),
        plain_n=float(len(ref)),
        count_ratio=len(pts) / len(ref),
        overlaps_3x3=int(dmin < radius),
    )
    bench.finish()
    bad = [r["case"] for r in bench.rows if r.get("overlaps_3x3", 0)]
    if bad:
        print(f"overlaps across the wrap in: {', '.join(bad)}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()

"""Benchmark of repeat tiles (issue 18 point 5): every method that takes ``periodic``.

For each method whose spec declares a ``periodic`` parameter (read from
``strew._method.spec(name).names``, so methods join as they gain it), or whose
``--periodic`` runs through :func:`strew.tiles.periodic` (synth), a few tiles are
made twice with the same seed and size: periodic, and not (the baseline). Each result is
judged by :func:`strew.metrics.repeat_report` as if laid side by side (the non-periodic
one with its rectangle as the tile): overlaps across the wrap (must be 0 for the
periodic tile), the density and coverage of the strips along the tile's edges against
the interior (1 is seamless; a tile made without wrapping thins out there), the largest
difference of kind fractions between them, and, for the exemplar methods, the median
local fidelity score of windows straddling the seams against windows inside the tile.
Figures are means over ``--seeds`` seeds (overlaps: the worst seed); times are medians of
``--repeat`` runs per seed (default 1, after one warm-up run that compiles kernels), and
``time_ratio`` is the median over seeds of periodic / non-periodic, from the same run.
Columns: ``p_`` the periodic tile, ``f_`` the run without wrapping; ``n`` elements,
``wrap_ov`` / ``in_ov`` overlaps across the wrap / inside the tile, ``edge_dens`` /
``edge_cov`` edge strips' density / coverage over the interior's, ``kind_diff`` the
largest kind-fraction difference, ``seam_fid`` the seam windows' median fidelity score
over the interior windows', ``seam_fail`` the share of seam windows that fail.

    python benchmarks/periodic.py [--quick] [--seeds 3] [--repeat N] [--only pack,synth]
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402
from _runner import Bench, median_time, parse_args  # noqa: E402

from strew import Region, Shape, _method, load, metrics  # noqa: E402
from strew.cli._spec import TILED_PERIODIC  # noqa: E402
from strew.tiles import periodic as tiles_periodic  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def _cases(quick: bool) -> dict[str, list[tuple[str, Any, dict[str, Any], Region, Any]]]:
    """method -> [(label, input, params, region, exemplar or None)]."""
    k = 0.6 if quick else 1.0
    shapes = {"disc": Shape.circle(5), "bar": Shape.rectangle(16, 5), "tri": Shape.polygon([(-6, 5), (6, 5), (0, -6)])}
    rect = Region.rectangle(round(300 * k), round(200 * k))
    ex = ROOT / "examples" / "synth" / "stones.json"
    return {
        "pack": [
            ("pack fill-gap", shapes, {"method": "fill-gap"}, rect, None),
            ("pack naive", shapes, {"method": "naive", "max_failures": 2000}, rect, None),
        ],
        "synth": [("synth stones", load(ex), {}, Region.rectangle(round(400 * k), round(300 * k)), load(ex))],
        "grow": [("grow stones", load(ex), {}, Region.rectangle(round(300 * k), round(240 * k)), load(ex))],
        "ornament": [("ornament dots", "dots", {}, Region.rectangle(round(150 * k), round(100 * k)), None)],
        "program": [("program grid", str(ROOT / "examples" / "program" / "fig05_partitions.py"), {"name": "grid"}, Region.rectangle(round(600 * k), round(400 * k)), None)],
    }


def _figures(prefix: str, arr: Any, tile: Any, exemplar: Any) -> dict[str, Any]:
    r = metrics.repeat_report(arr, exemplar, tile=tile)
    out = {
        f"{prefix}n": r["count"],
        f"{prefix}wrap_ov": r["overlaps"]["across"],
        f"{prefix}in_ov": r["overlaps"]["inside"],
        f"{prefix}edge_dens": r["density"]["ratio"],
        f"{prefix}edge_cov": r["coverage"]["ratio"],
        f"{prefix}kind_diff": r["kind_fractions"]["max_difference"],
    }
    if "fidelity" in r:
        out[f"{prefix}seam_fid"] = r["fidelity"]["ratio"]
        out[f"{prefix}seam_fail"] = r["fidelity"]["seam_failing"]
    return out


def main() -> int:
    def extra(p: Any) -> None:
        p.add_argument("--only", default=None, help="comma-separated methods")
        p.add_argument("--seeds", type=int, default=3, help="seeds per case (figures are their means)")
        p.set_defaults(repeat=1)

    args = parse_args(__doc__.splitlines()[0], extra)
    only = set(args.only.split(",")) if args.only else None
    seeds = range(1, 1 + (1 if args.quick else max(1, args.seeds)))
    bench = Bench("periodic", "repeat tiles: periodic vs the same run without wrapping", baseline="periodic=False, same seed and size", json_path=args.json)
    from strew import _periodic

    for name, cases in _cases(args.quick).items():
        if only and name not in only:
            continue
        spec = _method.spec(name)
        fn = spec.function()
        if "periodic" in spec.names:
            make = lambda data, region, seed, params, fn=fn: fn(data, region, rng=seed, periodic=True, **params)  # noqa: E731
        elif name in TILED_PERIODIC:  # --periodic through strew.tiles.periodic (a torus of tiles)
            make = lambda data, region, seed, params, name=name: tiles_periodic(name, data, region, rng=seed, **params)  # noqa: E731
        else:
            bench.row(name, note="no periodic parameter yet")
            continue
        for label, data, params, region, exemplar in cases:
            figs: list[dict[str, Any]] = []
            ratios = []
            note = ""
            for seed in seeds:
                try:
                    t_p, tile_arr = median_time(lambda: make(data, region, seed, params), repeat=args.repeat, warmup=0 if figs else 1)
                    t_f, flat = median_time(lambda: fn(data, region, rng=seed, **params), repeat=args.repeat, warmup=0 if figs else 1)
                except Exception as exc:  # a method mid-change: say so and go on
                    note = f"failed: {type(exc).__name__}: {str(exc)[:80]}"
                    break
                frame = _periodic.frame(tile_arr)
                if frame is None:
                    note = "periodic=True gave no meta.periodic"
                    break
                ratios.append(t_p / t_f if t_f > 0 else float("nan"))
                figs.append({**_figures("p_", tile_arr, None, exemplar), **_figures("f_", flat, frame, exemplar)})
            if note:
                bench.row(label, note=note)
                continue
            row: dict[str, Any] = {"seeds": len(figs), "time_ratio": statistics.median(ratios)}
            for key in figs[0]:
                vals = [f[key] for f in figs]
                # overlaps: the worst seed; the rest: means over seeds
                row[key] = max(vals) if key.endswith("_ov") else float(np.nanmean(vals))
            bench.row(label, **row)
    bench.finish()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

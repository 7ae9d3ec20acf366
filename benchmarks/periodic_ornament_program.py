"""Periodic (repeat-tile) ornament and program (issue 18, points 1 and 2).

For ornament (dots, and flowers in the ink style) and program (uniform and grid
partitions of examples/program/fig05_partitions.py), times a periodic run next to the
non-periodic run of the same size and seed, and prints the medians and their ratio,
the element count, the overlaps among 3 x 3 tiled copies (must be 0; ornament's filled
styles only) and the ratio of the edge strips' coverage (ornament: area of ink per area;
program: edge length per area) to the interior's.

Run: ``python benchmarks/periodic_ornament_program.py [--repeat N] [--quick]``; writes
``benchmarks/results/periodic_ornament_program.json`` (``--quick``: one run, ``..._quick.json``).
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
from pathlib import Path

import numpy as np
import shapely

from strew import _periodic as P
from strew import metrics
from strew.ornament import grow_ornament
from strew.program import run as run_program
from strew.region import Region

ROOT = Path(__file__).resolve().parent
SCRIPT = ROOT.parent / "examples" / "program" / "fig05_partitions.py"


def _median_time(fn, repeat: int):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def _strip_ratio(geom, w: float, h: float, band: float, measure) -> float:
    tile = shapely.box(0, 0, w, h)
    inner = shapely.box(band, band, w - band, h - band)
    strip = tile.difference(inner)
    return (measure(geom.intersection(strip)) / strip.area) / (measure(geom.intersection(inner)) / inner.area)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="one timed run per case, JSON to periodic_ornament_program_quick.json (a check of the script)")
    args = ap.parse_args()
    if args.quick:
        args.repeat = 1
    rows = []
    cases = [
        ("ornament", "dots", "outline", (60.0, 45.0), 8.0),
        ("ornament", "flowers", "ink", (60.0, 45.0), 8.0),
        ("program", "uniform", None, (1400.0, 1000.0), 150.0),
        ("program", "grid", None, (1400.0, 1000.0), 150.0),
    ]
    for method, name, style, (w, h), band in cases:
        region = Region.rectangle(w, h)
        if method == "ornament":
            def go(per, name=name, style=style, region=region):
                return grow_ornament(name, region, rng=2, periodic=per, style=style)
        else:
            def go(per, name=name, region=region):
                return run_program(SCRIPT, region, rng=2, name=name, periodic=per)
        go(False), go(True)  # warm up (numba compilation) outside the timings
        t_plain, plain = _median_time(lambda: go(False), args.repeat)
        t_per, per = _median_time(lambda: go(True), args.repeat)
        tiled = P.tiled_copies(per, 3, 3)
        if method == "ornament":
            cross = len(metrics.overlaps(tiled)[0])
            geom = shapely.intersection(shapely.union_all(P.images(per).geometry), shapely.box(0, 0, w, h))
            ratio = _strip_ratio(geom, w, h, band, shapely.area)
        else:
            faces = tiled.select(np.flatnonzero(np.asarray(tiled["cell"]) == "face"))
            cross = len(metrics.overlaps(faces)[0])
            edges = per.select(np.flatnonzero(np.asarray(per["cell"]) == "edge"))
            ratio = _strip_ratio(shapely.union_all(edges.geometry), w, h, band, shapely.length)
        row = dict(method=method, case=name, size=[w, h], plain_s=t_plain, periodic_s=t_per, ratio=t_per / t_plain,
                   plain_count=len(plain), periodic_count=len(per), tiled_overlaps=cross, edge_strip_vs_interior=ratio)
        rows.append(row)
        print(f"{method:9s} {name:8s} {w:g}x{h:g}: plain {t_plain:.3f} s  periodic {t_per:.3f} s  ratio {t_per / t_plain:.2f}  "
              f"count {len(plain)} / {len(per)}  3x3 overlaps {cross}  edge strip / interior {ratio:.3f}")
    out = ROOT / "results" / f"periodic_ornament_program{'_quick' if args.quick else ''}.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps({"repeat": args.repeat, "rows": rows}, indent=2) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

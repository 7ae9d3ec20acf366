"""Benchmark of tiled worlds (issue 19 point 5): pack fill-gap, tile by tile.

Every configuration runs in a fresh subprocess (so that its peak RSS is its own):

(a) time per element of a pack world (a bar 3 x 1.5 and a disc of radius 1, about 0.14
    elements per unit area, tiles of 100 x 100, about 1,400 elements a tile) from 1e5 to
    1e6 elements on 2 local Dask worker processes, Parquet written by the client;
(b) 2 workers against 1 (the in-process runner) on the 1e5 world: speed-up;
(c) peak RSS of each worker process (``ru_maxrss``) at 1e5 and 1e6: bounded by the
    tile, not the world, when it stays flat.

Times exclude starting the cluster (reported apart) and include writing Parquet; numba's
kernels are loaded (or compiled) by a small warm-up world in every worker first. The
machine is shared: the ratios are from the same run.

Run: ``python benchmarks/worlds.py`` (``--quick``: 2e4 and 1e5 only; ``--repeat N``
repeats of the speed-up pair, default 3; ``--sizes 1e5,1e6,1e7`` the sizes of (a)).
Writes ``benchmarks/results/worlds.json``. ``--seams`` prints only the border-strip
statistics of tiled and periodic worlds (``benchmarks/results/worlds_seams.json``).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

DENSITY = 0.1395  # elements per unit area of this pack world (measured, 300 x 240)
TILE = 100.0

_CHILD = r"""
import json, resource, sys, tempfile, time
import strew
from strew.tiles import world
from strew.io._parquet import ParquetWriter

side, workers, tile = float(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
shapes = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
out = {}
client = cluster = None
kw = {}
if workers > 1:
    from dask.distributed import Client, LocalCluster
    t0 = time.perf_counter()
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40)
    client = Client(cluster)
    out["cluster_s"] = time.perf_counter() - t0
    kw = {"scheduler": cluster.scheduler_address}
# warm-up: load (or compile) the kernels in every worker. A 2 x 2 world on the cluster
# is not enough: its 4 tiles depend on each other and may all run on one worker, and
# the other then loads its kernels inside the timed run (measured: 216 CPU us/el on 2
# workers against 146 with this warm-up, 101 in-process, 500 x 500 world)
world("pack", shapes, (2 * tile, 2 * tile), tile_size=tile, seed=99, workers=workers, **kw)
if client is not None:
    client.run(lambda: world("pack", shapes, (2 * tile, 2 * tile), tile_size=tile, seed=98))
def cpu():
    import os
    t = os.times()
    return t.user + t.system
def cpu_all():
    return cpu() + (sum(client.run(cpu).values()) if client is not None else 0.0)
with tempfile.TemporaryDirectory() as tmp:
    w = ParquetWriter(tmp + "/w.parquet")
    c0 = cpu_all()
    t0 = time.perf_counter()
    info = world("pack", shapes, (side, side), tile_size=tile, seed=1, workers=workers, sink=w.write, **kw)
    w.close(info.shapes, info.meta)
    out["seconds"] = time.perf_counter() - t0
    out["cpu_seconds"] = cpu_all() - c0
out["elements"] = int(info.counts.sum())
out["tiles"] = len(info.counts)
out["client_maxrss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
if client is not None:
    rss = client.run(lambda: __import__("resource").getrusage(__import__("resource").RUSAGE_SELF).ru_maxrss / 1024)
    out["worker_maxrss_mb"] = sorted(rss.values())
    client.close(); cluster.close()
else:
    out["worker_maxrss_mb"] = [out["client_maxrss_mb"]]
print("RESULT " + json.dumps(out))
"""


def run(n: float, workers: int) -> dict:
    side = math.sqrt(n / DENSITY)
    p = subprocess.run([sys.executable, "-c", _CHILD, f"{side:.3f}", str(workers), str(TILE)],
                       capture_output=True, text=True, check=False)
    line = [x for x in p.stdout.splitlines() if x.startswith("RESULT ")]
    if p.returncode or not line:
        raise SystemExit(f"child failed ({p.returncode}):\n{p.stderr[-3000:]}")
    r = json.loads(line[0][7:])
    r.update(target=n, workers=workers, side=side, us_per_element=1e6 * r["seconds"] / max(r["elements"], 1),
             cpu_us_per_element=1e6 * r["cpu_seconds"] / max(r["elements"], 1))
    print(f"  n~{n:.0e} workers={workers}: {r['elements']:,} el, {r['tiles']} tiles, {r['seconds']:.1f} s, "
          f"{r['us_per_element']:.0f} us/el ({r['cpu_us_per_element']:.0f} CPU us/el, all processes), worker peak RSS {max(r['worker_maxrss_mb']):.0f} MB, "
          f"client {r['client_maxrss_mb']:.0f} MB", flush=True)
    return r


def seams(seeds: tuple[int, ...] = (3, 4, 5, 6)) -> dict:
    """Border-strip statistics (issue 19 point 4, issue 18 through strew.tiles.periodic).

    pack: a 150 x 120 world in tiles of 30, strips of half-width halo about the inner
    borders against the rest (and an untiled pack of the same world on the same lines);
    periodic pack (200 x 200), synth (stones.svg) and grow (tiles.svg) 400 x 400 in tiles
    of 100: strips along the repeat tile's edges (width halo for pack, halo / 2 else),
    and the overlaps of 3 x 3 copies.
    """
    import numpy as np

    import strew
    from strew import _periodic as P
    from strew.io import load
    from strew.pack import pack
    from strew.tiles import periodic, tiled

    sys.path.insert(0, str(Path(__file__).parents[1] / "tests" / "worlds"))
    from world_stats import border_strips, overlapping_pairs

    shapes = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
    size, tile = (150.0, 120.0), 30.0
    out: dict = {"pack_tiled": [], "pack_untiled": []}
    for seed in seeds:
        for key, arr in (("pack_tiled", tiled("pack", shapes, size, tile_size=tile, seed=seed)),
                         ("pack_untiled", pack(shapes, strew.Region.rectangle(*size), rng=seed))):
            halo = 2 * float(np.hypot(1.5, 0.75))
            st, inn, sa, ia = border_strips(arr, size, tile, halo, halo)
            ratio = (st.sum() / sa) / (inn.sum() / ia)
            dfrac = float((arr.kind[st] == 0).mean() - (arr.kind[inn] == 0).mean())
            out[key].append({"seed": seed, "elements": len(arr), "strip_density_ratio": ratio, "bar_fraction_diff": dfrac})
            print(f"  {key:13s} seed {seed}: {len(arr):,} el, border strips {ratio:.3f}x the interior's density, "
                  f"bar fraction strip - interior {dfrac:+.3f}", flush=True)

    def edge(a, width):
        x0, y0, w, h = P.frame(a)
        x, y = a.x - x0, a.y - y0
        e = (x < width) | (x > w - width) | (y < width) | (y > h - width)
        ea = w * h - (w - 2 * width) * (h - 2 * width)
        return float((e.sum() / ea) / ((~e).sum() / (w * h - ea)))

    ex = Path(__file__).parents[1] / "examples" / "exemplars"
    runs = [("periodic pack", "pack", shapes, 200.0, None, 1.0), ("periodic synth", "synth", load(ex / "stones.svg"), 400.0, 100.0, 0.5),
            ("periodic grow", "grow", load(ex / "tiles.svg"), 400.0, 100.0, 0.5)]
    for name, method, inp, side, t, frac in runs:
        out[name] = []
        for seed in (1, 2, 3):
            a = periodic(method, inp, (side, side), rng=seed, tile_size=t)
            width = frac * a.meta["world"]["halo"]
            r = {"seed": seed, "elements": len(a), "edge_density_ratio": edge(a, width), "edge_width": width,
                 "overlaps_3x3": overlapping_pairs(P.tiled_copies(a))}
            out[name].append(r)
            print(f"  {name:14s} seed {seed}: {len(a):,} el, edge strips (width {width:.2f}) {r['edge_density_ratio']:.3f}x "
                  f"the interior's density, overlaps in 3x3 copies {r['overlaps_3x3']}", flush=True)
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sizes", default=None, help="comma-separated element counts of (a), e.g. 1e5,1e6,1e7")
    ap.add_argument("--seams", action="store_true", help="only the border-strip statistics (writes worlds_seams.json)")
    args = ap.parse_args()
    if args.seams:
        t0 = time.perf_counter()
        print("border strips (issue 19 point 4; issue 18 through strew.tiles.periodic):")
        res = {"benchmark": "worlds --seams", "command": "python benchmarks/worlds.py --seams", **seams()}
        out = Path(__file__).parent / "results" / "worlds_seams.json"
        out.parent.mkdir(exist_ok=True)
        out.write_text(json.dumps(res, indent=1) + "\n")
        print(f"wrote {out} ({time.perf_counter() - t0:.0f} s)")
        return
    sizes = [2e4, 1e5] if args.quick else [1e5, 3e5, 1e6]
    if args.sizes:
        sizes = sorted(float(v) for v in args.sizes.split(","))
    small = sizes[0] if args.quick else 1e5
    t0 = time.perf_counter()
    load0 = os.getloadavg()
    print(f"machine: {os.cpu_count()} cores, load average {load0[0]:.1f} (other work shares the cores: "
          "wall-clock ratios are noisy, CPU per element less so)")
    print(f"(b) speed-up, {small:.0e} elements, medians of {args.repeat}:")
    one = [run(small, 1) for _ in range(args.repeat)]
    two = [run(small, 2) for _ in range(args.repeat)]
    s1 = statistics.median(r["seconds"] for r in one)
    s2 = statistics.median(r["seconds"] for r in two)
    print(f"  1 worker {s1:.1f} s, 2 workers {s2:.1f} s: speed-up {s1 / s2:.2f}x (target 1.7x)")
    print("(a) time per element on 2 workers:")
    scale = [two[len(two) // 2]] + [run(n, 2) for n in sizes if n != small]
    base = scale[0]["us_per_element"]
    cbase = scale[0]["cpu_us_per_element"]
    for r in scale:
        print(f"  {r['elements']:>10,} el  {r['us_per_element']:7.1f} us/el  ratio {r['us_per_element'] / base:.2f} "
              f"(target within 1.2)  CPU {r['cpu_us_per_element']:6.1f} us/el  ratio {r['cpu_us_per_element'] / cbase:.2f}  "
              f"worker peak RSS {max(r['worker_maxrss_mb']):.0f} MB")
    c1 = statistics.median(r["cpu_seconds"] for r in one)
    c2 = statistics.median(r["cpu_seconds"] for r in two)
    print(f"  CPU seconds on the {small:.0e} world: 1 worker {c1:.1f}, 2 workers {c2:.1f} (all processes; "
          f"{c1 / c2:.2f}x: the ideal speed-up on an idle machine is at most 2 x this)")
    result = {
        "benchmark": "worlds",
        "command": "python benchmarks/worlds.py" + (" --quick" if args.quick else "") + (f" --sizes {args.sizes}" if args.sizes else ""),
        "cores": os.cpu_count(), "load_average_start": load0[0], "load_average_end": os.getloadavg()[0],
        "tile_size": TILE,
        "speedup": {"elements": small, "one_worker_s": s1, "two_workers_s": s2, "ratio": s1 / s2,
                    "runs_one": one, "runs_two": two},
        "scaling": scale,
        "per_element_ratio_max": max(r["us_per_element"] for r in scale) / min(r["us_per_element"] for r in scale),
        "cpu_per_element_ratio_max": max(r["cpu_us_per_element"] for r in scale) / min(r["cpu_us_per_element"] for r in scale),
        "cpu_seconds_speedup_pair": [c1, c2],
        "worker_peak_rss_mb": {f"{r['elements']}": max(r["worker_maxrss_mb"]) for r in scale},
        "total_s": time.perf_counter() - t0,
    }
    out = Path(__file__).parent / "results" / "worlds.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(result, indent=1) + "\n")
    print(f"wrote {out} ({result['total_s']:.0f} s)")


if __name__ == "__main__":
    main()

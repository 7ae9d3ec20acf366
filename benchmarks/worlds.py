"""Benchmark of tiled worlds (issue 19 point 5): pack fill-gap, tile by tile.

Every configuration runs in a fresh subprocess (so that its peak RSS is its own):

(a) time per element of a pack world (a bar 3 x 1.5 and a disc of radius 1, about 0.14
    elements per unit area, tiles of 100 x 100, about 1,400 elements a tile) from 1e5 to
    1e6 elements on 2 local Dask worker processes, Parquet written by the client;
(b) 2 workers against 1 (the in-process runner) on the 1e5 world: speed-up;
(c) peak RSS of each worker process (``ru_maxrss``) at 1e5 and 1e6: bounded by the
    tile, not the world, when it stays flat.

Times exclude starting the cluster (reported apart; the LocalCluster is the one
``world(workers=N)`` starts, :func:`strew.tiles._connect`) and include writing Parquet;
numba's kernels are loaded (or compiled) by a small warm-up world in every worker first,
and the client writes that world as Parquet (the first write imports pandas). Each run
reports its CPU by process and thread (``cpu_by_role``: the client's main thread and IO
loop, where the scheduler and nannies run; the workers' task threads and the rest) and
a wall modelled on 2 idle cores from it. The machine is shared: the ratios are from the
same run.

Run: ``python benchmarks/worlds.py`` (``--quick``: 2e4 and 1e5 only; ``--repeat N``
repeats of the speed-up pair, default 3; ``--sizes 1e5,1e6,1e7`` the sizes of (a)).
Writes ``benchmarks/results/worlds.json``. ``--seams`` prints only the border-strip
statistics of tiled and periodic worlds (``benchmarks/results/worlds_seams.json``);
``--synth-seams [--seeds 3,4,5] [--before]`` synth's, tiled against untiled
(``worlds_synth_seams.json``).

Point 5 one measurement a command (``--only``, ``--method pack|synth``; writes
``worlds_<only>_<method>.json``):

- ``--only scaling --sizes 1e5,1e6,1e7``: time and CPU per element, worker peak RSS;
- ``--only scaling --method synth --sizes 1e5,1e6``: the same for synth (stones.svg);
- ``--only speedup --sizes 1e5 --repeat 3``: 2 workers against 1 on the same world (in
  process and on a 1-worker LocalCluster), CPU per element by process and thread, and
  the wall modelled on 2 idle cores from the CPU; ``--baseline-src /tmp/wt/src`` repeats
  it with strew imported from there (the code before), in the same run;
- ``--only memory --sizes 1e6 --tile-sizes 50,100,200``: worker peak RSS per tile size.
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
import json, os, resource, sys, tempfile, threading, time
import strew
from strew.tiles import world
from strew.io._parquet import ParquetWriter

side, workers, tile = float(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
method = sys.argv[4] if len(sys.argv) > 4 else "pack"
if method == "synth":
    from strew.io import load
    shapes = load(sys.argv[5])
else:
    shapes = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
out = {}
client = cluster = None
kw = {}
if workers > 1 or (len(sys.argv) > 6 and sys.argv[6] == "dask"):  # "dask": 1 worker on a cluster too
    from strew.tiles import _connect
    t0 = time.perf_counter()
    client, cluster = _connect(None, workers, True, 10.0)  # the LocalCluster world(workers=N) starts
    out["cluster_s"] = time.perf_counter() - t0
    kw = {"scheduler": cluster.scheduler_address}
# warm-up: load (or compile) the kernels in every worker. A 2 x 2 world on the cluster
# is not enough: its 4 tiles depend on each other and may all run on one worker, and
# the other then loads its kernels inside the timed run (measured: 216 CPU us/el on 2
# workers against 146 with this warm-up, 101 in-process, 500 x 500 world)
# and write the warm-up world as Parquet: the first write imports pandas and
# pyarrow.compute (0.25 s CPU alone, up to 1 s on a busy machine), in this process
# whatever the runner: a fixed cost, outside the timed run like the kernels' loading
with tempfile.TemporaryDirectory() as tmp:
    w = ParquetWriter(tmp + "/warm.parquet")
    warm = world(method, shapes, (2 * tile, 2 * tile), tile_size=tile, seed=99, workers=workers, sink=w.write, **kw)
    w.close(warm.shapes, warm.meta)
if client is not None:
    client.run(lambda: world(method, shapes, (2 * tile, 2 * tile), tile_size=tile, seed=98))
def threads():
    # CPU seconds of each thread of this process, by role: "main" (the client's loop,
    # sink and Parquet; in a worker its event loop), "loop" (the client process's IO
    # loop: scheduler, nannies, comms), "work" (a worker's task thread)
    names = {t.native_id: t.name for t in threading.enumerate()}
    tick = os.sysconf("SC_CLK_TCK")
    res = {}
    for tid in os.listdir("/proc/self/task"):
        try:
            with open(f"/proc/self/task/{tid}/stat") as f:
                st = f.read()
        except OSError:
            continue
        fields = st[st.rindex(")") + 2:].split()
        name = names.get(int(tid), "")
        role = "main" if name == "MainThread" else "work" if "Dask-Default-Threads" in name else "loop" if name == "IO loop" else "other"
        res[tid] = (role, (int(fields[11]) + int(fields[12])) / tick)
    return res
def cpu_all():
    procs = {"client": threads()}
    if client is not None:
        procs.update({"worker " + k: v for k, v in client.run(threads).items()})
    return procs
with tempfile.TemporaryDirectory() as tmp:
    w = ParquetWriter(tmp + "/w.parquet")
    c0 = cpu_all()
    t0 = time.perf_counter()
    info = world(method, shapes, (side, side), tile_size=tile, seed=1, workers=workers, sink=w.write, **kw)
    w.close(info.shapes, info.meta)
    out["seconds"] = time.perf_counter() - t0
    c1 = cpu_all()
# CPU by process kind and thread role: client process main thread / IO loop (the
# scheduler and nannies live there) / other threads; workers' task threads / the rest
roles = {}
for proc, ths in c1.items():
    kind = "client" if proc == "client" else "worker"
    for tid, (role, c) in ths.items():
        d = c - c0[proc].get(tid, (role, 0.0))[1]
        roles[f"{kind}_{role}"] = roles.get(f"{kind}_{role}", 0.0) + d
out["cpu_by_role"] = roles
out["cpu_seconds"] = sum(roles.values())
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


# synth's world: examples/exemplars/stones.svg (3 kinds of stone), tiles of 400 (halo 100, about 300 elements a tile; tiles of 200 spent 1.8-2.2 ms CPU per element, 2e3-6e3 elements)
SYNTH_EXEMPLAR = Path(__file__).parents[1] / "examples" / "exemplars" / "stones.svg"
SYNTH_DENSITY = 0.00191  # elements per unit area (measured: 1,222-1,232 in 800 x 800, seeds 1-2)
SYNTH_TILE = 400.0


def run(n: float, workers: int, method: str = "pack", tile: float | None = None, dask: bool = False, src: str | None = None) -> dict:
    """One world in a fresh subprocess; ``dask``: on a LocalCluster even for 1 worker;
    ``src``: import strew from this folder (a worktree's ``src``: the code before)."""
    density, tile = (SYNTH_DENSITY, tile or SYNTH_TILE) if method == "synth" else (DENSITY, tile or TILE)
    side = math.sqrt(n / density)
    env = dict(os.environ, PYTHONPATH=src) if src else None
    p = subprocess.run([sys.executable, "-c", _CHILD, f"{side:.3f}", str(workers), f"{tile:g}", method, str(SYNTH_EXEMPLAR), "dask" if dask else ""],
                       capture_output=True, text=True, check=False, env=env)
    line = [x for x in p.stdout.splitlines() if x.startswith("RESULT ")]
    if p.returncode or not line:
        raise SystemExit(f"child failed ({p.returncode}):\n{p.stderr[-3000:]}")
    r = json.loads(line[0][7:])
    ne = max(r["elements"], 1)
    roles = r["cpu_by_role"]
    # modelled wall on 2 idle cores: every process's CPU shares them, and a lone worker
    # cannot go faster than its own CPU (the in-process runner: all of it is serial)
    if r.get("cluster_s") is None:
        model = r["cpu_seconds"]
    else:
        model = max(r["cpu_seconds"] / 2, (roles.get("worker_work", 0.0) + roles.get("worker_main", 0.0) + roles.get("worker_other", 0.0)) / workers)
    r.update(method=method, tile_size=tile, target=n, workers=workers, on_dask=bool(dask or workers > 1), side=side, us_per_element=1e6 * r["seconds"] / ne,
             cpu_us_per_element=1e6 * r["cpu_seconds"] / ne, cpu_us_per_element_by_role={k: 1e6 * v / ne for k, v in roles.items()},
             modelled_s=model, src=src)
    by_role = ", ".join(f"{k} {1e6 * v / ne:.1f}" for k, v in sorted(roles.items()) if v > 0.005)
    print(f"  {method} n~{n:.0e} workers={workers}{' (Dask)' if r['on_dask'] else ''} tile {tile:g}{' [' + src + ']' if src else ''}: {r['elements']:,} el, {r['tiles']} tiles, {r['seconds']:.1f} s, "
          f"{r['us_per_element']:.0f} us/el ({r['cpu_us_per_element']:.0f} CPU us/el, all processes: {by_role}; modelled wall on 2 idle cores {model:.2f} s), "
          f"worker peak RSS {max(r['worker_maxrss_mb']):.0f} MB, client {r['client_maxrss_mb']:.0f} MB", flush=True)
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
    out.update(synth_seams(seeds[:3]))
    return out


def synth_seams(seeds: tuple[int, ...] = (3, 4, 5), classes: tuple[str, ...] = ("stones", "two_sizes"), frames: float = 4.0,
                before: bool = False) -> dict:
    """Border strips of tiled synth (issue 19 point 4) against an untiled synth of the same world.

    Each fidelity-suite exemplar (stones: one kind, a scatter; two_sizes: stones and
    pebbles) fills a square of ``frames`` x its frame, cut into 4 x 4 tiles (halo a
    quarter tile); strips of half-width 0.05 and 0.1 tile about the inner borders
    against the rest, leaving out the world's edge band of one halo: density ratio and
    each kind's density ratio; overlaps of the tiled world. ``before``: also tiled with
    each tile's region its whole grown rectangle (the code before the finished
    neighbours' interiors were left out, strew.tiles._outside_finished), same run.
    """
    import numpy as np

    import strew
    from strew.synth import synthesize
    from strew import tiles as tiles_mod
    from strew.tiles import tiled

    modes = ("tiled", "before", "untiled") if before else ("tiled", "untiled")
    here = Path(__file__).parents[1]
    sys.path.insert(0, str(here / "tests" / "worlds"))
    sys.path.insert(0, str(here / "tests"))
    from strew_testing import fidelity_suite
    from world_stats import border_strips, overlapping_pairs

    suite = fidelity_suite()
    out: dict = {}
    for cls in classes:
        ex = suite.make_exemplar(cls)
        x0, y0, x1, y1 = ex.region.bounds
        side = frames * (x1 - x0)
        size, tile = (side, side), side / 4
        for mode in modes:
            key = f"synth_{cls}_{mode}"
            out[key] = []
            for seed in seeds:
                t0 = time.process_time()
                if mode == "untiled":
                    arr = synthesize(ex, strew.Region.rectangle(*size), rng=seed, measure=False)
                else:  # "before": the region of a tile is its whole grown rectangle (as at 845a513)
                    grows, tiles_mod._GROWS_FROM_CONTEXT = tiles_mod._GROWS_FROM_CONTEXT, (() if mode == "before" else tiles_mod._GROWS_FROM_CONTEXT)
                    try:
                        arr = tiled("synth", ex, size, tile_size=tile, seed=seed)
                    finally:
                        tiles_mod._GROWS_FROM_CONTEXT = grows
                cpu = time.process_time() - t0
                row = {"seed": seed, "elements": len(arr), "cpu_s": cpu, "kinds": list(arr.kinds)}
                for width in (0.05 * tile, 0.1 * tile):
                    st, inn, sa, ia = border_strips(arr, size, tile, width, tile / 4)
                    kind = np.asarray(arr.kind)
                    row[f"w{width:g}"] = {
                        "strip_elements": int(st.sum()),
                        "density_ratio": float((st.sum() / sa) / (inn.sum() / ia)),
                        "kind_density_ratio": [float(((kind[st] == k).sum() / sa) / max((kind[inn] == k).sum() / ia, 1e-12))
                                               for k in range(len(arr.kinds))]}
                row["overlaps"] = overlapping_pairs(arr) if mode != "untiled" else None
                out[key].append(row)
                ws = "; ".join(f"strips +-{w[1:]}: {v['density_ratio']:.3f}x ({v['strip_elements']} el), by kind "
                               + "/".join(f"{r:.2f}" for r in v["kind_density_ratio"])
                               for w, v in row.items() if w.startswith("w"))
                print(f"  synth {cls:9s} {mode:7s} seed {seed}: {len(arr):,} el ({'/'.join(arr.kinds)}), {ws}"
                      + (f", overlaps {row['overlaps']}" if mode != "untiled" else "") + f" [{cpu:.0f} CPU s]", flush=True)
        for mode in modes:
            rows = out[f"synth_{cls}_{mode}"]
            for w in [k for k in rows[0] if k.startswith("w")]:
                d = [r[w]["density_ratio"] for r in rows]
                print(f"  synth {cls:9s} {mode:7s} strips +-{w[1:]}: density ratio mean {np.mean(d):.3f} "
                      f"(range {min(d):.3f}-{max(d):.3f}) over seeds {','.join(map(str, seeds))}", flush=True)
    return out


def only(args: argparse.Namespace, sizes: list[float]) -> None:
    """One measurement of point 5 per command (``--only``), for ``--method pack|synth``.

    scaling: time per element at ``--sizes`` on ``--workers`` workers (ratio to the
    smallest); speedup: ``--sizes``' smallest world on 1 worker and on 2, ``--repeat``
    times each; memory: peak RSS per worker on the ``--sizes``' smallest world for each
    of ``--tile-sizes``. Writes ``benchmarks/results/worlds_<only>_<method>.json``.
    """
    t0 = time.perf_counter()
    load0 = os.getloadavg()
    print(f"machine: {os.cpu_count()} cores, load average {load0[0]:.1f}; {args.only}, {args.method}")
    res: dict = {"benchmark": f"worlds --only {args.only}", "method": args.method, "cores": os.cpu_count(),
                 "load_average_start": load0[0],
                 "command": " ".join(["python benchmarks/worlds.py", *sys.argv[1:]])}
    if args.only == "scaling":
        runs = [run(n, args.workers, args.method) for n in sizes]
        base, cbase = runs[0]["us_per_element"], runs[0]["cpu_us_per_element"]
        for r in runs:
            print(f"  {r['elements']:>11,} el  {r['us_per_element']:8.1f} us/el  ratio {r['us_per_element'] / base:.2f} (target within 1.2)"
                  f"  CPU {r['cpu_us_per_element']:8.1f} us/el  ratio {r['cpu_us_per_element'] / cbase:.2f}  worker peak RSS {max(r['worker_maxrss_mb']):.0f} MB",
                  flush=True)
        res.update(runs=runs, per_element_ratio_max=max(r["us_per_element"] for r in runs) / min(r["us_per_element"] for r in runs),
                   cpu_per_element_ratio_max=max(r["cpu_us_per_element"] for r in runs) / min(r["cpu_us_per_element"] for r in runs))
    elif args.only == "speedup":
        n = sizes[0]
        srcs = [None] + ([args.baseline_src] if args.baseline_src else [])
        for src in srcs:
            # two baselines: the in-process runner (no Dask at all), and 1 worker on a
            # LocalCluster, whose scheduler and client share the 2 cores just as they do
            # with 2; interleaved, so that a change of the machine's load hits all three
            one, one_dask, two = [], [], []
            for _ in range(args.repeat):
                one.append(run(n, 1, args.method, src=src))
                one_dask.append(run(n, 1, args.method, dask=True, src=src))
                two.append(run(n, 2, args.method, src=src))
            med = {k: {f: statistics.median(r[f] for r in rs) for f in ("seconds", "modelled_s", "cpu_us_per_element")}
                   for k, rs in (("one", one), ("one_dask", one_dask), ("two", two))}
            s1, s1d, s2 = (med[k]["seconds"] for k in ("one", "one_dask", "two"))
            m1, m1d, m2 = (med[k]["modelled_s"] for k in ("one", "one_dask", "two"))
            label = f"[{src}] " if src else ""
            print(f"  {label}{n:.0e} elements: 1 worker in-process {s1:.1f} s, 1 Dask worker {s1d:.1f} s, 2 Dask workers {s2:.1f} s "
                  f"(medians of {args.repeat}): speed-up {s1 / s2:.2f}x over in-process, {s1d / s2:.2f}x over 1 Dask worker (target 1.7x)")
            print(f"  {label}CPU per element (all processes) {med['one']['cpu_us_per_element']:.0f} / {med['one_dask']['cpu_us_per_element']:.0f} / "
                  f"{med['two']['cpu_us_per_element']:.0f} us; modelled wall on 2 idle cores {m1:.2f} / {m1d:.2f} / {m2:.2f} s: "
                  f"{m1 / m2:.2f}x over in-process, {m1d / m2:.2f}x over 1 Dask worker", flush=True)
            part = dict(elements=n, one_worker_s=s1, one_dask_worker_s=s1d, two_workers_s=s2, ratio=s1 / s2,
                        ratio_over_one_dask_worker=s1d / s2, modelled_s=[m1, m1d, m2], modelled_ratio=m1 / m2,
                        modelled_ratio_over_one_dask_worker=m1d / m2, runs_one=one, runs_one_dask=one_dask, runs_two=two)
            if src:
                res["baseline"] = dict(part, src=src)
            else:
                res.update(part)
    else:  # memory
        n = sizes[0]
        runs = [run(n, args.workers, args.method, tile=float(t)) for t in args.tile_sizes.split(",")]
        for r in runs:
            print(f"  tile {r['tile_size']:g}: {r['elements']:,} el, worker peak RSS {max(r['worker_maxrss_mb']):.0f} MB "
                  f"({r['elements'] / max(r['tiles'], 1):,.0f} el a tile)", flush=True)
        res.update(elements=n, runs=runs)
    res.update(load_average_end=os.getloadavg()[0], total_s=time.perf_counter() - t0)
    out = Path(__file__).parent / "results" / f"worlds_{args.only}_{args.method}.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(res, indent=1) + "\n")
    print(f"wrote {out} ({res['total_s']:.0f} s)")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sizes", default=None, help="comma-separated element counts of (a), e.g. 1e5,1e6,1e7")
    ap.add_argument("--seams", action="store_true", help="only the border-strip statistics (writes worlds_seams.json)")
    ap.add_argument("--synth-seams", action="store_true", help="only synth's border strips, tiled against untiled (writes worlds_synth_seams.json)")
    ap.add_argument("--seeds", default="3,4,5", help="seeds of --synth-seams")
    ap.add_argument("--only", choices=("scaling", "speedup", "memory"), help="one measurement of point 5 (see only())")
    ap.add_argument("--method", choices=("pack", "synth"), default="pack", help="--only: the world's method")
    ap.add_argument("--workers", type=int, default=2, help="--only scaling|memory: Dask workers (1: in-process)")
    ap.add_argument("--baseline-src", default=None, help="--only speedup: also run with strew imported from this src folder (a worktree of the code before)")
    ap.add_argument("--tile-sizes", default="50,100,200", help="--only memory: tile sides (pack; synth e.g. 100,200,400)")
    ap.add_argument("--classes", default="stones,two_sizes", help="--synth-seams: fidelity-suite classes")
    ap.add_argument("--before", action="store_true", help="--synth-seams: also the tiles' whole grown rectangles (the old region)")
    args = ap.parse_args()
    if args.synth_seams:
        t0 = time.perf_counter()
        seeds = tuple(int(v) for v in args.seeds.split(","))
        print("synth border strips (issue 19 point 4), tiled against untiled:")
        res = {"benchmark": "worlds --synth-seams", "command": " ".join(["python benchmarks/worlds.py", *sys.argv[1:]]),
               **synth_seams(seeds, tuple(args.classes.split(",")), before=args.before)}
        out = Path(__file__).parent / "results" / "worlds_synth_seams.json"
        out.parent.mkdir(exist_ok=True)
        out.write_text(json.dumps(res, indent=1) + "\n")
        print(f"wrote {out} ({time.perf_counter() - t0:.0f} s)")
        return
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
    if args.only:
        only(args, sizes)
        return
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

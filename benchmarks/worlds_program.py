"""Program worlds in tiles (issue 19.1, 19.5): cost of the tiles against one evaluation.

For a program script and world sides S (a square S x S), each measured in a fresh
subprocess (CPU seconds of ``time.process_time`` and the peak RSS above the same process
that only imported strew and ran the script once at a small size):

- ``untiled``: ``strew.program.run`` on the square (the baseline: the plain method);
- ``world``: :func:`strew.program._world.evaluate_world`, the whole world as one tile
  (the same sites and cells as the tiles);
- ``tiled``: :func:`strew.tiles.world` with ``workers`` (1: in this process, tiles one after
  the other; the elements are counted, not kept) at tile side ``--tile``.

It prints CPU per element and the ratios tiled / untiled in the same run, and the fitted
exponent of tiled CPU against elements (target: time per element constant, issue 19.5).

Run: ``python benchmarks/worlds_program.py [--script uniform|mosaic|FILE] [--sizes 1000,2000,4000]
[--tile 500] [--halo 125] [--workers 1]``.
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _runner import Bench, parse_args  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]

UNIFORM = """
from strew.program import *
p = set_weighted_face_labels(irregular_properties(0.0005), "a", 0.5, "b", 0.3)
cells = uniform_partition(p, KEEP_INSIDE)
def shrink(face):
    if random(face, 0, 1, 0) < 0.25:
        return nothing()
    return scale(contour(face), 0.7)
arrangement = union(cells, map_to_faces(shrink, cells))
"""

_CHILD = r"""
import json, sys, time
mode, script, size, tile, halo, workers = {mode!r}, {script!r}, {size!r}, {tile!r}, {halo!r}, {workers!r}
from strew.program import run
from strew.program._world import evaluate_world
from strew import tiles
run(script, (200.0, 200.0), rng=1)  # imports, warm-up
base = max(int(l.split()[1]) for l in open("/proc/self/status") if l.startswith("VmHWM:"))
out = {{}}
if mode != "base":
    t0, w0 = time.process_time(), time.perf_counter()
    if mode == "untiled":
        n = len(run(script, (size, size), rng=1))
    elif mode == "world":
        n = len(evaluate_world(script, (size, size), seed=1))
    else:
        info = tiles.world("program", script, (size, size), tile_size=tile, halo=halo, seed=1, workers=workers)
        n = int(info.counts.sum())
    out = dict(cpu=time.process_time() - t0, wall=time.perf_counter() - w0, elements=n)
out["rss_mb"] = (max(int(l.split()[1]) for l in open("/proc/self/status") if l.startswith("VmHWM:")) - base) / 1024
print(json.dumps(out))
"""


def child(mode: str, script: str, size: float, tile: float, halo: float, workers: int) -> dict[str, Any]:
    code = _CHILD.format(mode=mode, script=script, size=size, tile=tile, halo=halo, workers=workers)
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    if res.returncode:
        raise SystemExit(f"{mode} at {size:g} failed:\n{res.stderr[-3000:]}")
    return json.loads(res.stdout.strip().splitlines()[-1])


def main() -> None:
    def extra(p: Any) -> None:
        p.add_argument("--script", default="uniform", help="uniform (a Voronoi mosaic), mosaic (Fig. 11(d)) or a script file")
        p.add_argument("--sizes", default="1000,2000,4000", help="comma-separated world sides")
        p.add_argument("--tile", type=float, default=500.0, help="tile side")
        p.add_argument("--halo", type=float, default=125.0, help="tile halo (holds every cell that reaches into a tile)")
        p.add_argument("--workers", type=int, default=1, help="Dask workers of the tiled run (1: in-process)")
        p.add_argument("--no-untiled", action="store_true", help="skip the untiled baseline (large worlds)")

    args = parse_args(__doc__.splitlines()[0], extra=extra)
    tmp = Path(tempfile.mkdtemp())
    if args.script == "uniform":
        script = tmp / "uniform_world.py"
        script.write_text(UNIFORM)
    elif args.script == "mosaic":
        script = ROOT / "examples" / "program" / "fig11d_mosaic.py"
    else:
        script = Path(args.script)
    sizes = [float(v) for v in args.sizes.split(",")] if not args.quick else [600.0, 1200.0]
    bench = Bench("worlds_program", f"program worlds ({Path(script).name}): tiles of {args.tile:g} (halo {args.halo:g}, "
                  f"{args.workers} worker(s)) against one evaluation",
                  baseline="untiled strew.program.run on the same square, same run", json_path=args.json)
    tiled_cpu, tiled_n = [], []
    for size in sizes:
        modes = (["untiled"] if not args.no_untiled else []) + ["world", "tiled"]
        got = {}
        for mode in modes:
            got[mode] = child(mode, str(script), size, args.tile, args.halo, args.workers)
            g = got[mode]
            print(f"{mode:>8s} size {size:6g}  cpu {g['cpu']:7.2f} s  wall {g['wall']:7.2f} s  elements {g['elements']:7d}  "
                  f"{1e3 * g['cpu'] / max(g['elements'], 1):.3f} ms CPU/el  peak rss +{g['rss_mb']:.1f} MB", flush=True)
        t = got["tiled"]
        tiled_cpu.append(t["cpu"] if args.workers == 1 else t["wall"])
        tiled_n.append(t["elements"])
        row: dict[str, Any] = {f"{m}_{k}": v for m, g in got.items() for k, v in g.items()}
        if "untiled" in got:
            u = got["untiled"]
            row["cpu_per_el_ratio_tiled_vs_untiled"] = (t["cpu"] / t["elements"]) / (u["cpu"] / u["elements"])
            row["rss_ratio_tiled_vs_untiled"] = t["rss_mb"] / max(u["rss_mb"], 1e-9)
            print(f"   ratio tiled/untiled: CPU per element {row['cpu_per_el_ratio_tiled_vs_untiled']:.2f}x, "
                  f"peak RSS {row['rss_ratio_tiled_vs_untiled']:.2f}x", flush=True)
        bench.row(f"size {size:g}", **row)
    if len(sizes) > 1:
        k = float(np.polyfit(np.log(tiled_n), np.log(tiled_cpu), 1)[0])
        print(f"tiled: fitted exponent of {'CPU' if args.workers == 1 else 'wall'} time against elements "
              f"({tiled_n[0]}..{tiled_n[-1]}): {k:.3f}  (1.0: constant time per element)")
        bench.row("fit", tiled_exponent=k)
    bench.finish()


if __name__ == "__main__":
    main()

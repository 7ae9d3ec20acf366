"""Scaling of the planar map (issue 19.6): time and peak memory against segment count.

Induces the planar map of n random segments of fixed length in a square whose area grows
with n (the density of crossings stays the same), for n over a 10x range; prints n, CPU
seconds, the number of cells, and the peak memory per segment two ways:

- ``rss``: the peak resident set (``VmHWM`` of ``/proc/self/status``) of a fresh
  subprocess that builds the curves and induces the map, minus that of the same subprocess
  that builds the curves only (the baseline: imports, warm-up, the input). This counts
  GEOS' own C allocations, which ``tracemalloc`` does not see;
- ``traced``: the peak traced by ``tracemalloc`` (the Python heap only), as before.

and the exponent fitted to log time against log n. Targets: exponent at most 1.15, under
2 KB per segment (rss).

``--against REV`` also runs the planar map of git revision REV (its
``src/strew/program/_planar_map.py``, loaded beside the installed strew) in the same run,
for before/after figures.

A program script (``--script``, default Fig. 11(d)'s mosaic) is also run whole by
``strew.program.run_script`` at ``--script-sizes``: its peak RSS above the same script at
size 200 (every planar map it induces, and the arrangement).

Run: ``python benchmarks/program_scaling.py [--quick] [--against REV] [--script F --script-sizes S,S]``.
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
import tracemalloc
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _runner import Bench, parse_args  # noqa: E402

from strew.program import Curve, Curves, induce  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def random_segments(n: int, seed: int = 0) -> Curves:
    rng = np.random.default_rng(seed)
    side = 20.0 * np.sqrt(n)  # about the same crossings per segment at every n
    p = rng.uniform(0, side, (n, 2))
    ang = rng.uniform(0, 2 * np.pi, n)
    q = p + 30.0 * np.c_[np.cos(ang), np.sin(ang)]
    return Curves(tuple(Curve(np.stack([a, b])) for a, b in zip(p, q)))


_CHILD = r"""
import json, sys, time
sys.path.insert(0, {bench!r})
from program_scaling import random_segments
mod = {module!r}
if mod:
    import importlib.util
    spec = importlib.util.spec_from_file_location("pm_against", mod)
    pm_mod = importlib.util.module_from_spec(spec)
    sys.modules["pm_against"] = pm_mod
    spec.loader.exec_module(pm_mod)
    induce = pm_mod.induce
else:
    from strew.program import induce
script = {script!r}
out = {{}}
if script:
    # a whole `strew run` (every planar map it induces), with REV's induction swapped in
    import strew.program._planar_map as cur
    from strew.program import run_script
    if mod:
        cur._induce = pm_mod._induce
    run_script(script, size=200.0, seed=1)
    if {run}:
        t0 = time.process_time()
        pm, arr = run_script(script, size={n}, seed=1)
        out = dict(cpu=time.process_time() - t0, v=pm.n_vertices, e=pm.n_edges, f=pm.n_faces, elements=len(arr))
else:
    induce(random_segments(200))
    curves = random_segments({n})
    if {run}:
        t0 = time.process_time()
        pm = induce(curves)
        out = dict(cpu=time.process_time() - t0, v=pm.n_vertices, e=pm.n_edges, f=pm.n_faces)
# VmHWM: the peak RSS of this process's own memory since exec (ru_maxrss would also keep
# the parent's size at the fork, which hides everything below it)
out["maxrss_kb"] = max(int(line.split()[1]) for line in open("/proc/self/status") if line.startswith("VmHWM:"))
print(json.dumps(out))
"""


def child(n: float, run: bool, module: str = "", script: str = "") -> dict:
    code = _CHILD.format(bench=str(Path(__file__).parent), module=module, n=n, run=run, script=script)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def against_module(rev: str, tmp: Path) -> str:
    """REV's _planar_map.py, made importable beside the installed strew (absolute imports)."""
    src = subprocess.run(["git", "-C", str(ROOT), "show", f"{rev}:src/strew/program/_planar_map.py"],
                         capture_output=True, text=True, check=True).stdout
    src = src.replace("from .._errors", "from strew._errors").replace("from ._curves", "from strew.program._curves")
    src = src.replace("from ._context", "from strew.program._context")
    path = tmp / f"planar_map_{rev}.py"
    path.write_text(src)
    return str(path)


def main() -> None:
    def extra(p: Any) -> None:
        p.add_argument("--against", default=None, help="git revision whose planar map is measured in the same run")
        p.add_argument("--script", default=str(ROOT / "examples" / "program" / "fig11d_mosaic.py"),
                       help="a program script also run whole at --script-sizes (peak RSS in MB)")
        p.add_argument("--script-sizes", default="3000,6000", help="comma-separated sizes for --script ('' skips it)")

    args = parse_args(__doc__.splitlines()[0], extra=extra)
    ns = [2000, 6000, 20000] if args.quick else [10000, 30000, 100000]
    induce(random_segments(200))
    bench = Bench("program_scaling", "planar map of n random segments: time and memory vs n",
                  baseline=f"targets: exponent 1.15, 2 KB/segment (rss); against {args.against or 'nothing'}",
                  json_path=args.json)
    tmp = Path(tempfile.mkdtemp())
    codes = [("now", "")] + ([(args.against, against_module(args.against, tmp))] if args.against else [])
    for name, module in codes:
        ts = []
        for n in ns:
            base = child(n, False, module)["maxrss_kb"]
            got = child(n, True, module)
            rss = (got["maxrss_kb"] - base) / n
            ts.append(got["cpu"])
            traced = float("nan")
            if not module:
                curves = random_segments(n)
                tracemalloc.start()
                pm = induce(curves)
                traced = tracemalloc.get_traced_memory()[1] / n / 1024
                tracemalloc.stop()
                del pm, curves
            bench.row(f"{name} n {n}", cpu_s=got["cpu"], vertices=got["v"], edges=got["e"], faces=got["f"],
                      rss_kb_per_segment=rss, traced_kb_per_segment=traced)
            print(f"{name:>8s} n {n:7d}  cpu {got['cpu']:7.2f} s  V {got['v']}  E {got['e']}  F {got['f']}  "
                  f"peak rss {rss:.2f} KB/segment  traced {traced:.2f}", flush=True)
        k = np.polyfit(np.log(ns), np.log(ts), 1)[0]
        print(f"{name:>8s} fitted exponent (log cpu time vs log n, n {ns[0]}..{ns[-1]}): {k:.3f}  (target <= 1.15)")
        bench.row(f"{name} fit", exponent=float(k))
    script_sizes = [float(v) for v in args.script_sizes.split(",") if v.strip()]
    for name, module in codes:
        for size in script_sizes:
            base = child(size, False, module, args.script)["maxrss_kb"]
            got = child(size, True, module, args.script)
            mb = (got["maxrss_kb"] - base) / 1024
            bench.row(f"{name} {Path(args.script).name} size {size:g}", cpu_s=got["cpu"], vertices=got["v"], edges=got["e"],
                      faces=got["f"], elements=got["elements"], rss_mb=mb)
            print(f"{name:>8s} {Path(args.script).name} size {size:g}  cpu {got['cpu']:7.2f} s  V {got['v']}  E {got['e']}  "
                  f"F {got['f']}  elements {got['elements']}  peak rss above the script at size 200: {mb:.1f} MB", flush=True)
    bench.finish()


if __name__ == "__main__":
    main()

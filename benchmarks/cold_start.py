"""Cold start: the first run of each method on a fresh install against the second run.

    python benchmarks/cold_start.py [--quick] [--case NAME ...] [--top N] [--json PATH]
                                    [--prefill none|warmup|installed] [--python PY]

A fresh install has an empty numba cache, so the first command of each method compiles
its kernels. For every case this script starts a new Python process with an empty
``NUMBA_CACHE_DIR`` and times the work (imports included, as a user sees it: the whole
command), then starts a second process on the now filled cache and times the same work
again. Both runs go through the library's CLI entry point in-process (``strew.cli.main``),
or, for the studio, through a studio session handling a stroke's messages, so process
start-up is the same for both and cancels out of the ratio.

``--prefill warmup`` starts every case's cache as a copy of what ``python -m
strew._warmup`` compiles (the caches a wheel built by ``hatch_build.py`` ships, without
building one); ``--prefill installed`` copies the cache files an installed strew's wheel
shipped in its ``__pycache__`` folders (those its RECORD lists) (``--python`` names that environment's interpreter), laid
out where ``NUMBA_CACHE_DIR`` makes numba look, so each case starts from the state of a
fresh ``pip install .``. The default, ``none``, is a fresh install without shipped
caches.

Printed per case: the first and second times, their ratio, whether the first run meets
the target of issue 16 (first <= 2 x second + 1 s), and the kernels whose compilation
took longest (numba's ``numba:compile`` events, inclusive of the kernels they call).

The first run is never hidden behind a warm-up: it is the figure this script exists for.

Figures with the kernels compiled at build time (issue 16, ``hatch_build.py``): a fresh
venv, ``pip install .`` of 35beb59, every case run with ``--python VENV/bin/python``,
``--prefill none`` (no shipped caches: before) and ``--prefill installed`` (the wheel's
caches: after), load 10-13 on the shared 2-core machine; CPU seconds of the process:

==================  =====================  ==================  ============  ==================
case                first CPU s            second CPU s        kernels       target (CPU) met
                    before -> after        before -> after     compiled      before -> after
==================  =====================  ==================  ============  ==================
pack fill-gap       23.4 -> 1.17           1.07 -> 1.18        37 -> 0       no -> yes
pack naive          0.57 -> 0.67           0.58 -> 0.68        0 -> 0        yes -> yes
synth fill          19.9 -> 1.33           1.42 -> 1.47        35 -> 0       no -> yes
grow                4.25 -> 1.35           1.39 -> 1.37        6 -> 0        no -> yes
ornament dots       8.85 -> 1.66           1.72 -> 1.57        18 -> 0       no -> yes
ornament flowers    9.42 -> 2.15           2.22 -> 2.08        19 -> 0       no -> yes
ornament spirals    10.5 -> 3.38           3.55 -> 3.46        19 -> 0       no -> yes
ornament hierarchy  11.7 -> 3.19           3.31 -> 3.27        21 -> 0       no -> yes
run                 3.30 -> 1.42           1.51 -> 1.17        7 -> 0        yes -> yes
studio brush        20.3 -> 1.70           1.86 -> 1.79        35 -> 0       no -> yes
studio spray        9.37 -> 1.61           1.51 -> 1.63        21 -> 0       no -> yes
==================  =====================  ==================  ============  ==================

After, every first run is within 0.90-1.21x its second run in CPU (wall 0.87-1.43x,
except pack naive 2.8x: 22.5 vs 8.0 s wall for 0.67 s of CPU, the load). ``strew demo``
compiles nothing either (70.7 s CPU first, 70.9 s second). The build's warm-up (``python
-m strew._warmup``, 25 cases) costs about 85 s of CPU once, at ``pip install .``.

Figures of ``python benchmarks/cold_start.py --case 'pack fill-gap' --case 'synth fill'
--case grow --case run --case 'studio brush'``, at 574794a (before) and with the issue 16
compile-time rewrites of this session (after), each tree run on its own in a git worktree
of the same checkout, on the shared 2-core machine at load 8-10: wall times swing 2-5x
with the load, so compare the CPU seconds of the process (``first_cpu_s``, imports
included):

=============  ==================  ===================  =============  =========================
case           first CPU s         second CPU s         CPU ratio      target (CPU) met
               before -> after     before -> after      before->after  before -> after
=============  ==================  ===================  =============  =========================
pack fill-gap  27.4 -> 25.2        1.13 -> 0.99         24.2 -> 25.5   no -> no
synth fill     23.8 -> 17.8        1.62 -> 1.67         14.7 -> 10.7   no -> no
studio brush   23.9 -> 19.9        2.05 -> 1.90         11.7 -> 10.5   no -> no
grow           2.52 -> 2.77        1.32 -> 1.44         1.91 -> 1.93   yes -> yes
run            3.37 -> 3.25        1.29 -> 1.57         2.61 -> 2.06   yes -> yes (wall too)
=============  ==================  ===================  =============  =========================

Where the rest goes (numba 0.68, profile of a recompile of pack's ``_rounds`` with its
callees): about a third type inference (each call site of an overloaded function is
resolved through its templates), a quarter lowering, and the rest LLVM, half of that
machine-code emission. ``NUMBA_OPT=2`` (26.3 s) or no loop vectoriser (25.6 s) barely
change a cold pack (27.3 s), so the cost is numba's per-statement work, not LLVM's
optimisation level: a numba kernel costs about 0.1 s of CPU at the least, and pack,
synth and the studio compile 35 each. The target (first <= 2 x second + 1 s, about 3-5
s of CPU here) needs code that is compiled before the first run (an extension module
built by ``pip install .``), not fewer numba statements.

Earlier figures (previous session, ``--quick``, wall): pack fill-gap 44.3 s vs 2.05 s,
synth fill 56.6 vs 2.81 (before its ``sort_segments`` rewrite), grow 4.69 vs 2.46,
ornament dots 16.7 vs 2.86 (44 vs 4.3 before its LAPACK calls), studio brush 82.4 vs
6.46.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import Bench, parse_args  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"

# name -> strew CLI arguments (outputs go to a scratch folder named by {out})
CLI_CASES: dict[str, list[str]] = {
    "pack fill-gap": ["pack", str(EX / "shapes/concave.svg"), "--size", "200x160", "--seed", "1", "-o", "{out}/p.json"],
    "pack naive": ["pack", str(EX / "shapes/concave.svg"), "--size", "200x160", "--method", "naive", "--seed", "1", "-o", "{out}/n.json"],
    "synth fill": ["synth", str(EX / "exemplars/stones.svg"), "--size", "300x200", "--seed", "1", "-o", "{out}/s.json"],
    "grow": ["grow", str(EX / "exemplars/scales.svg"), "--count", "300", "--seed", "1", "-o", "{out}/g.json"],
    "ornament dots": ["ornament", "dots", "--size", "80x80", "--seed", "1", "-o", "{out}/od.json"],
    "ornament flowers": ["ornament", "flowers", "--size", "80x80", "--seed", "1", "-o", "{out}/of.json"],
    "ornament spirals": ["ornament", "spirals", "--size", "80x80", "--seed", "1", "-o", "{out}/os.json"],
    "ornament hierarchy": ["ornament", "hierarchy", "--size", "80x80", "--seed", "1", "-o", "{out}/oh.json"],
    "run": ["run", str(EX / "program/fig03_two_scales.py"), "-o", "{out}/r.json"],
}
QUICK = ("pack fill-gap", "synth fill", "grow", "ornament dots", "studio brush")

# the studio's first stroke: the messages a browser sends, handled by a session
STUDIO = """
from strew.studio._session import Session
s = Session(project, size=(500, 400))
s.handle({"type": "load_exemplar", "example": "scales.svg"})
pts = [[60.0 + 6.0 * i, 200.0 + 40.0 * ((i % 20) / 20.0)] for i in range(61)]
s.handle({"type": "stroke_start", "tool": TOOL, "radius": 60, "points": pts[:1]})
for p in pts[1:]:
    s.handle({"type": "stroke_move", "points": [p]})
s.handle({"type": "stroke_end"})
"""
STUDIO_CASES = {"studio brush": "brush", "studio spray": "spray"}

DRIVER = textwrap.dedent(
    """
    import json, sys, time
    t0 = time.perf_counter()
    c0 = time.process_time()
    import numba.core.event as ev
    case = json.loads(sys.argv[1])
    with ev.install_recorder("numba:compile") as rec:
        if case["kind"] == "cli":
            from strew.cli import main
            rc = main(case["argv"] + ["-q"])
            assert rc == 0, f"exit {rc}"
        else:
            project, TOOL = case["project"], case["tool"]
            exec(case["code"])
    total = time.perf_counter() - t0
    cpu = time.process_time() - c0
    # compile time per kernel: inclusive (nested compiles counted in their callers too)
    # and self (less the nested compiles), from numba's start/end events
    starts, per, own, outer = {}, {}, {}, 0.0
    stack = []
    for t, e in rec.buffer:
        d = e.data["dispatcher"]
        name = f"{d.py_func.__module__}.{d.py_func.__qualname__}"
        key = (name, id(e.data))
        if e.is_start:
            starts[key] = t
            stack.append([key, 0.0])
        else:
            t_start = starts.pop(key)
            _, nested = stack.pop()
            dt = t - t_start
            per[name] = per.get(name, 0.0) + dt
            own[name] = own.get(name, 0.0) + dt - nested
            if stack:
                stack[-1][1] += dt
            else:
                outer += dt
    print(json.dumps({"total": total, "cpu": cpu, "compile": outer, "kernels": per, "self": own}))
    """
)


def run_once(case: dict, cache: str, python: str = sys.executable) -> dict:
    env = dict(os.environ, NUMBA_CACHE_DIR=cache)
    proc = subprocess.run([python, "-c", DRIVER, json.dumps(case)], env=env, capture_output=True, text=True, timeout=900)
    if proc.returncode != 0:
        raise RuntimeError(f"{case}: {proc.stderr[-2000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


# the numba cache files an installed strew's wheel shipped (its RECORD: not those that
# later runs compiled into the same __pycache__ folders)
INSTALLED = (
    "import importlib.metadata as m\n"
    "for f in m.files('strew'):\n"
    "    if f.suffix in ('.nbi', '.nbc'):\n"
    "        print(f.locate().resolve())\n"
)


def prefill_warmup(template: Path, python: str) -> dict:
    """Compile into ``template`` what ``python -m strew._warmup`` does (the build's
    warm-up); returns its wall and CPU seconds (children included)."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(template))
    before = os.times()
    t0 = time.perf_counter()
    proc = subprocess.run([python, "-m", "strew._warmup"], env=env, capture_output=True, text=True, timeout=3600)
    wall = time.perf_counter() - t0
    after = os.times()
    if proc.returncode != 0:
        raise RuntimeError(f"warm-up failed: {proc.stdout[-2000:]}{proc.stderr[-2000:]}")
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return {"wall_s": wall, "cpu_s": cpu}


def prefill_installed(template: Path, python: str) -> int:
    """Copy the numba cache files an installed strew ships in its ``__pycache__`` folders
    into ``template``, where ``NUMBA_CACHE_DIR=template`` makes numba look for them
    (``<folder name>_<sha1 of the folder's path>``, numba's user-provided locator);
    returns the number of files copied."""
    listed = subprocess.run([python, "-c", INSTALLED], capture_output=True, text=True, check=True).stdout.split("\n")
    n = 0
    for f in sorted(Path(p) for p in listed if p.strip()):
        src = str(f.parent.parent)  # <package folder>/__pycache__/<file>
        dest = template / f"{f.parent.parent.name}_{hashlib.sha1(src.encode()).hexdigest()}"
        dest.mkdir(parents=True, exist_ok=True)
        shutil.copy2(f, dest / f.name)
        n += 1
    return n


def main() -> None:
    def extra(p):
        p.add_argument("--case", action="append", default=None, help="run only this case (repeatable), e.g. --case 'pack fill-gap'")
        p.add_argument("--top", type=int, default=10, help="print the N slowest kernel compiles (self time) per case")
        p.add_argument("--prefill", choices=("none", "warmup", "installed"), default="none", help="what each case's cache starts with (see the module's docstring)")
        p.add_argument("--python", default=sys.executable, help="interpreter that runs the cases (e.g. a fresh venv's, with --prefill installed)")

    args = parse_args(__doc__.splitlines()[0], extra)
    bench = Bench(
        "cold_start",
        f"first run on a fresh install (numba cache prefilled: {args.prefill}) vs the second run (new process, filled cache)",
        baseline="second run; target first <= 2 x second + 1 s",
        json_path=args.json,
    )
    names = list(CLI_CASES) + list(STUDIO_CASES)
    if args.case:
        unknown = [c for c in args.case if c not in names]
        if unknown:
            raise SystemExit(f"--case: unknown case {unknown}; cases: {names}")
        names = [n for n in names if n in args.case]
    elif args.quick:
        names = [n for n in names if n in QUICK]
    per_kernel: list[str] = []
    compiles: dict[str, dict[str, list[float]]] = {}
    prefill: dict = {"mode": args.prefill, "python": args.python}
    with tempfile.TemporaryDirectory() as tmp:
        template = Path(tmp) / "template-cache"
        template.mkdir()
        if args.prefill == "warmup":
            prefill.update(prefill_warmup(template, args.python))
            print(f"warm-up (what the wheel build runs): {prefill['wall_s']:.1f} s wall, {prefill['cpu_s']:.1f} s CPU")
        elif args.prefill == "installed":
            prefill["files"] = prefill_installed(template, args.python)
            print(f"{prefill['files']} cache files shipped in the installed strew")
        prefill["files"] = sum(1 for f in template.rglob("*") if f.is_file())
        for name in names:
            out = Path(tmp) / name.replace(" ", "_")
            out.mkdir()
            if name in CLI_CASES:
                case = {"kind": "cli", "argv": [a.format(out=out) for a in CLI_CASES[name]]}
            else:
                (out / "project").mkdir()
                case = {"kind": "studio", "project": str(out / "project"), "tool": STUDIO_CASES[name], "code": STUDIO}
            cache = str(out / "numba-cache")
            shutil.copytree(template, cache)
            first = run_once(case, cache, args.python)
            second = run_once(case, cache, args.python)
            top = sorted(first["kernels"].items(), key=lambda kv: -kv[1])[:3]
            bench.row(
                name,
                first_s=first["total"],
                second_s=second["total"],
                ratio=first["total"] / second["total"],
                first_cpu_s=first["cpu"],
                second_cpu_s=second["cpu"],
                cpu_ratio=first["cpu"] / second["cpu"],
                compile_s=first["compile"],
                compile_2nd_s=second["compile"],
                kernels=len(first["kernels"]),
                meets_target=first["total"] <= 2 * second["total"] + 1.0,
                meets_cpu=first["cpu"] <= 2 * second["cpu"] + 1.0,
                slowest=", ".join(f"{k.rsplit('.', 1)[-1]} {v:.1f}s" for k, v in top),
            )
            compiles[name] = {k: [round(v, 3), round(first["kernels"][k], 3)] for k, v in sorted(first["self"].items(), key=lambda kv: -kv[1])}
            per_kernel.append(f"{name}: slowest compiles, self seconds (inclusive)")
            for k, v in sorted(first["self"].items(), key=lambda kv: -kv[1])[: args.top]:
                per_kernel.append(f"  {v:7.2f}  ({first['kernels'][k]:6.2f})  {k}")
    bench.finish()
    print("\n".join(per_kernel))
    # the JSON also keeps every kernel's compile seconds of the first run: [self, inclusive]
    payload = json.loads(bench.json_path.read_text())
    payload["compile_s_self_inclusive"] = compiles
    payload["prefill"] = prefill
    bench.json_path.write_text(json.dumps(payload, indent=2) + "\n")


if __name__ == "__main__":
    main()

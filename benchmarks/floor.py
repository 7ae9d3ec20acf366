"""Issue 15 point 5: the shared kernel floor (strew._kernels) keeps pack's and ornament's
speed: CPU seconds against a baseline revision, measured in the same run.

Each case runs in a fresh subprocess, alternately with the working tree's strew and with
the baseline's (``--base PATH``: the ``src`` folder of another revision, e.g. ``git
archive 26be9c7 src | tar -x -C /tmp/base``), ``--repeat`` times each; every worker
compiles (or loads) its kernels on a small warm-up first, then times the case with
``time.process_time``, the median of ``--inner`` runs (the machine is shared: CPU time,
not wall time). Printed: the median over workers of those CPU seconds for both, their ratio (new / base; target <= 1.10) and the element
counts (equal when the outputs are identical).

    python benchmarks/floor.py --base /tmp/base/src [--repeat 3] [--inner 5] [--only pack:hook,ornament:dots]

Figures against 26be9c7 (the session start, before strew._kernels), load average about 9,
CPU ratio new / base (benchmarks/results/floor.json); every count equal:

================  =====  ================  =====
case              ratio  case              ratio
================  =====  ================  =====
pack:leaf         0.99   pack:periodic     1.07
pack:hook         0.97   poisson           1.01
pack:concave3     0.90   ornament:dots     0.91
pack:stones-fit   1.02   ornament:flowers  0.95
================  =====  ================  =====

(pack and poisson ``--repeat 3 --inner 5``; ornament ``--repeat 4 --inner 1``, after it
moved to the shared incremental grid.)

When poisson_disk moved from its own SplitMix64 stream to the shared xoshiro256+ one
(issue 15 point 5), ``--base`` 60f40b9 ``--only poisson``: ratio 0.95 (24,704 points
against 24,628: another point set for the seed, the same distribution); the pack rows
then compare different layouts, so their counts differ too.
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

from _runner import SKIPPED, Bench, parse_args

ROOT = Path(__file__).resolve().parents[1]
CASES = ["pack:leaf", "pack:hook", "pack:concave3", "pack:stones-fit", "pack:periodic", "poisson", "ornament:dots", "ornament:flowers"]

WORKER = r"""
import json, sys, time
from pathlib import Path
import shapely
from strew import Region, load_shapes
case, root = sys.argv[1], Path(sys.argv[2])
ex = root / "examples"
if case.startswith("pack:") or case == "poisson":
    from strew.pack import pack, poisson_disk
    hook = load_shapes(ex / "pack" / "hook.json")
    pack(hook, Region.rectangle(100, 100), rng=0)  # compile or load the kernels
    pack(hook, Region.rectangle(100, 100), rng=0, periodic=True)
    poisson_disk((1, 1), 0.05, rng=0)
    name = case[5:]
    if name == "leaf":
        run = lambda: pack(load_shapes(ex / "pack" / "leaf.json"), Region.rectangle(600, 520), rng=1)
    elif name == "hook":
        run = lambda: pack(hook, Region.rectangle(600, 520), rng=1, scale=(0.75, 0.75))
    elif name == "concave3":
        shapes = {}
        for n in ("concave", "tree", "elongated"):
            shapes.update(load_shapes(ex / "shapes" / f"{n}.svg"))
        l_shape = Region(shapely.Polygon([(0, 0), (400, 0), (400, 200), (200, 200), (200, 400), (0, 400)]))
        run = lambda: pack(shapes, l_shape, rng=1, scale=(0.25, 0.25))
    elif name == "stones-fit":
        run = lambda: pack(load_shapes(ex / "pack" / "stones.json"), Region.rectangle(600, 520), rng=1, scale=(0.5, 1.0), scale_choice="fit")
    elif name == "periodic":
        run = lambda: pack(hook, Region.rectangle(400, 300), rng=1, periodic=True)
    else:
        run = lambda: poisson_disk((1, 1), 0.005, rng=1)
else:
    from strew.ornament import grow_elements
    grow_elements("dots", Region.rectangle(20, 20), rng=0)
    name = case[9:]
    size = 300 if name == "dots" else 100
    run = lambda: grow_elements(name, Region.rectangle(size, size), rng=0)
cpus = []
for _ in range(int(sys.argv[3])):
    t = time.process_time()
    out = run()
    cpus.append(time.process_time() - t)
n = len(out) if not hasattr(out, "elements") else len(out.elements)
print(json.dumps({"n": n, "cpu_s": sorted(cpus)[len(cpus) // 2]}))
"""


def run(src: str, case: str, inner: int) -> dict:
    env = {**os.environ, "PYTHONPATH": src}
    out = subprocess.run([sys.executable, "-c", WORKER, case, str(ROOT), str(inner)], env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    def extra(p) -> None:
        p.add_argument("--base", required="--quick" not in sys.argv, help="src folder of the baseline revision")
        p.add_argument("--only", default=None, help="cases, comma-separated: " + ",".join(CASES))
        p.add_argument("--inner", type=int, default=5, help="runs of the case inside each worker (their median counts)")

    args = parse_args(__doc__.splitlines()[0], extra)
    if args.base is None:  # --quick without --base
        print("floor: skipped: it times this tree against a baseline revision's src folder (--base PATH), which has no default")
        sys.exit(SKIPPED)
    cases = args.only.split(",") if args.only else CASES
    bench = Bench("floor", "pack / ornament CPU s, working tree vs a baseline revision, same run", baseline=f"strew at {args.base}", json_path=args.json)
    new_src = str(ROOT / "src")
    for case in cases:
        new, base, counts = [], [], set()
        for _ in range(args.repeat):
            for src, acc in ((args.base, base), (new_src, new)):
                r = run(src, case, args.inner)
                acc.append(r["cpu_s"])
                counts.add((src == new_src, r["n"]))
        tb, tn = statistics.median(base), statistics.median(new)
        nb = sorted(n for is_new, n in counts if not is_new)
        nn = sorted(n for is_new, n in counts if is_new)
        bench.row(case, base_cpu_s=round(tb, 4), new_cpu_s=round(tn, 4), ratio=round(tn / tb, 3), base_n=nb, new_n=nn)
        print(f"  {case:18s} base {tb:8.4f} s   new {tn:8.4f} s   ratio {tn / tb:.3f}   n base {nb} new {nn}", flush=True)
    bench.finish()


if __name__ == "__main__":
    main()

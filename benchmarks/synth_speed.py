"""Issue 13 point 6: synth's elements per CPU second against an older version of strew,
measured in the same run.

Each case (the four ``strew.synth._exemplars`` of ``benchmarks/synth.py`` at its quick
sizes, and the fidelity suite's classes at 3.5x their frame's side) is filled by
``new_state`` + ``fill`` (horizon optimisation) in a fresh subprocess, alternately with
the working tree's strew and with the baseline's (``--base PATH``: a ``src`` folder of
another revision, e.g. ``git archive REV src | tar -x -C /tmp/base``), ``--repeat``
times each; CPU seconds (``time.process_time``, numba compiled before timing) are
used, not wall time, because the machine is shared. Printed: elements/s of both, their
ratio (new / base), and the targets (>= 5,000 el/s on grid and stripes; no case below
0.5 of the baseline).

    python benchmarks/synth_speed.py --base /tmp/base/src [--repeat 3] [--only grid,stripes]
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
QUICK = {"rings": (300, 260), "grid": (400, 400), "stripes": (320, 320), "apples": (300, 300)}
SUITE = ("stones", "two_sizes", "clusters", "three_sizes", "rings", "stripes", "sparse_voids", "hex_lattice", "rows_noisy", "bricks", "scales")

WORKER = r"""
import importlib.util, json, sys, time
from strew import Region
from strew.synth import fill, new_state
case = sys.argv[1]
if case.startswith("suite:"):
    spec = importlib.util.spec_from_file_location("mk", sys.argv[2] + "/examples/fidelity/make.py")
    mk = importlib.util.module_from_spec(spec); spec.loader.exec_module(mk)
    ex = mk.make_exemplar(case[6:])
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
else:
    from strew.synth._exemplars import EXEMPLARS
    ex = EXEMPLARS[case]()
    w, h = json.loads(sys.argv[3])
    region = Region.rectangle(w, h)
fill(new_state(ex, Region.rectangle(60, 60) if case == "grid" else region, rng=0))  # compile
t = time.process_time()
st = new_state(ex, region, rng=1)
fill(st)
print(json.dumps({"n": st.n, "cpu_s": time.process_time() - t}))
"""


def run(src: str, case: str) -> dict:
    env = {**os.environ, "PYTHONPATH": src}
    size = json.dumps(QUICK.get(case, (0, 0)))
    out = subprocess.run([sys.executable, "-c", WORKER, case, str(ROOT), size], env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    def extra(p) -> None:
        p.add_argument("--base", required="--quick" not in sys.argv, help="src folder of the baseline revision")
        p.add_argument("--only", default=None, help="cases, comma-separated (grid, stripes, rings, apples, suite:NAME)")

    args = parse_args(__doc__.splitlines()[0], extra)
    if args.base is None:  # --quick without --base
        print("synth_speed: skipped: it times this tree against a baseline revision's src folder (--base PATH), which has no default")
        sys.exit(SKIPPED)
    cases = args.only.split(",") if args.only else ["grid", "stripes", "rings", "apples"] + [f"suite:{n}" for n in SUITE]
    bench = Bench("synth_speed", "synth el/CPU s, working tree vs a baseline revision, same run", baseline=f"strew at {args.base}", json_path=args.json)
    new_src = str(ROOT / "src")
    for case in cases:
        new, base = [], []
        for _ in range(args.repeat):
            for src, acc in ((args.base, base), (new_src, new)):
                r = run(src, case)
                acc.append(r["n"] / r["cpu_s"])
        nb, nn = statistics.median(base), statistics.median(new)
        bench.row(case, base_el_per_s=round(nb), new_el_per_s=round(nn), ratio=round(nn / nb, 2))
        print(f"  {case:20s} base {nb:8.0f} el/s   new {nn:8.0f} el/s   ratio {nn / nb:.2f}", flush=True)
    bench.finish()
    for r in bench.rows:
        ok = r["ratio"] >= 0.5 and (r["case"] not in ("grid", "stripes") or r["new_el_per_s"] >= 5000)
        print(f"  {r['case']:20s} {'OK' if ok else 'MISSED'}")


if __name__ == "__main__":
    main()

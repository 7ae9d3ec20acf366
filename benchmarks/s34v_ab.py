"""Helper s34v: CPU el/s of synth (``new_state`` + ``fill``, as ``benchmarks/synth_speed.py``
times it) over several seeds per process, alternately with this tree's src and a
baseline's, to damp the noise of a shared machine.

    python benchmarks/s34v_ab.py --base /tmp/base/src [--cases grid,stripes] [--seeds 1,2,3,4] [--rounds 3]

Prints per case and round the el/CPU s of both trees and their ratio (new / base), then
the ratio of the summed elements over the summed CPU seconds.
"""
import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
WORKER = r"""
import json, sys, time
from strew import Region
from strew.synth import fill, new_state
from strew.synth._exemplars import EXEMPLARS
QUICK = {"rings": (300, 260), "grid": (400, 400), "stripes": (320, 320), "apples": (300, 300)}
case = sys.argv[1]
ex = EXEMPLARS[case]()
region = Region.rectangle(*QUICK[case])
fill(new_state(ex, Region.rectangle(60, 60) if case == "grid" else region, rng=0))  # compile
n, cpu = 0, 0.0
for seed in json.loads(sys.argv[2]):
    t = time.process_time()
    st = new_state(ex, region, rng=seed)
    fill(st)
    cpu += time.process_time() - t
    n += st.n
print(json.dumps({"n": n, "cpu_s": cpu}))
"""

ap = argparse.ArgumentParser()
ap.add_argument("--base", required=True)
ap.add_argument("--cases", default="grid,stripes")
ap.add_argument("--seeds", default="1,2,3,4")
ap.add_argument("--rounds", type=int, default=3)
args = ap.parse_args()
seeds = json.dumps([int(s) for s in args.seeds.split(",")])
for case in args.cases.split(","):
    tot = {"base": [0, 0.0], "new": [0, 0.0]}
    for k in range(args.rounds):
        got = {}
        for name, src in (("base", args.base), ("new", str(ROOT / "src"))):
            out = subprocess.run([sys.executable, "-c", WORKER, case, seeds], env={**os.environ, "PYTHONPATH": src}, capture_output=True, text=True, check=True)
            r = json.loads(out.stdout.strip().splitlines()[-1])
            got[name] = r["n"] / r["cpu_s"]
            tot[name][0] += r["n"]
            tot[name][1] += r["cpu_s"]
        print(f"{case:8s} round {k + 1}: base {got['base']:.0f} el/s  new {got['new']:.0f} el/s  ratio {got['new'] / got['base']:.2f}", flush=True)
    b, n = tot["base"][0] / tot["base"][1], tot["new"][0] / tot["new"][1]
    print(f"{case:8s} all rounds: base {b:.0f} el/s  new {n:.0f} el/s  ratio {n / b:.2f}  (CPU per element {b / n:.2f} of base's)", flush=True)

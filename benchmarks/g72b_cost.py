"""Helper g72b: grow's CPU seconds (fixed mode, seed 1) on a lattice exemplar at region sides
3.5x, 7x and 14x the exemplar frame's, with the regularity deficit; run once per source tree
(PYTHONPATH) and compare. Writes JSON to benchmarks/results/g72b_cost_TAG.json.

    PYTHONPATH=src:benchmarks python benchmarks/g72b_cost.py TAG [bricks:v45,...]
"""
import json
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar

import strew
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

tag = sys.argv[1]
specs = (sys.argv[2] if len(sys.argv) > 2 else "bricks:v45").split(",")
mk = fidelity_suite()
rows = []
grow(exemplar(mk, "bricks", "v45"), region=Region.rectangle(100, 100), rng=1)  # warm the kernels
for spec in specs:
    ex = exemplar(mk, *spec.split(":"))
    x0, y0, x1, y1 = ex.region.bounds
    for f in (3.5, 7.0, 14.0):
        t0 = time.process_time()
        out = grow(ex, region=Region.rectangle(f * (x1 - x0), f * (y1 - y0)), mode="fixed", rng=1)
        cpu = time.process_time() - t0
        reg = fidelity(ex, out, eq5=False, local=False).metrics["regularity"].value if f <= 7 else float("nan")
        rows.append(dict(spec=spec, side=f, n=len(out), cpu_s=round(cpu, 2), regularity=reg))
        print(f"{tag} {spec} side {f}x n={len(out)} cpu {cpu:.2f}s regularity deficit {reg:.4f}", flush=True)
json.dump({"benchmark": "g72b_cost", "tag": tag, "src": strew.__file__, "rows": rows}, open(f"benchmarks/results/g72b_cost_{tag}.json", "w"), indent=1)

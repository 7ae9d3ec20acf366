"""Helper s72c (copy of integ39_area_scale.py; JSON per tree: s72c_area_scale_{main,branch}.json). Cost of s70h's two-class density rule (``strew.synth._grow._TWO_CLASS_AREA``) against the
output's size: the fidelity suite's two_sizes exemplar synthesised at 3.5x to 14x its side,
rule off (baseline) and on, seed 1; prints CPU seconds and the ratio on/off. JSON to
``benchmarks/results/s72c_area_scale_{main,branch}.json`` (main: strew imported from /tmp/s72c/main).

    PYTHONPATH=src:benchmarks:tests python benchmarks/s72c_area_scale.py 3.5 7 14
"""
import json
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from _runner import fidelity_suite

import strew.synth._grow as G
from strew import Region
from strew.synth import synthesize

TAG = "main" if "/tmp/s72c/main" in __import__("strew").__file__ else "branch"
cls = "two_sizes"
ex = fidelity_suite().make_exemplar(cls, rng=1)
x0, y0, x1, y1 = ex.region.bounds
rows = []
for scale in [float(s) for s in (sys.argv[1:] or ["3.5", "7", "14"])]:
    cpu, n = {}, {}
    for on in (False, True):
        G._TWO_CLASS_AREA = on
        t = time.process_time()
        out = synthesize(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=1)
        cpu[on], n[on] = time.process_time() - t, len(out)
    rows.append({"scale": scale, "n_off": n[False], "n_on": n[True], "cpu_off": cpu[False], "cpu_on": cpu[True],
                 "ratio": cpu[True] / cpu[False]})
    print(f"scale {scale:5.1f} n off {n[False]:6d} on {n[True]:6d} cpu off {cpu[False]:6.1f} on {cpu[True]:6.1f} "
          f"ratio {cpu[True] / cpu[False]:.2f}", flush=True)
Path(__file__).parent.joinpath("results", "s72c_area_scale_" + TAG + ".json").write_text(json.dumps(rows, indent=1))

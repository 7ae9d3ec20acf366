"""Cost of s70p's thinning choice (``strew.synth._thin._match_nn``) against the output's size.

On ``--varied`` two_sizes p4s43 (where the choice acts), synthesises regions 3.5x to 14x the
exemplar's side with ``THIN_MATCH_NN`` off (the baseline, nearest first) and on, seed 1, and
prints the CPU seconds of each synthesis, the ratio on/off, the seconds spent in
``_match_nn`` and whether it acted (under ``MATCH_NN_WORK``). JSON to
``benchmarks/results/integ39_thin_scale.json``.

    PYTHONPATH=src:benchmarks:tests python benchmarks/integ39_thin_scale.py 3.5 5 7 14
"""
import json
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import _variants
from _runner import fidelity_suite

import strew.synth._thin as T
from strew import Region
from strew.synth import synthesize

mk = fidelity_suite()
kw = (_variants.VARIED["two_sizes"] + _variants.EDGE.get("two_sizes", []))[4]
ex = mk.make_exemplar("two_sizes", rng=43, **kw)
x0, y0, x1, y1 = ex.region.bounds
calls = []
orig = T._match_nn


def wrapped(state, vis, of_k, ins, cand, chosen, k):
    t = time.process_time()
    r = orig(state, vis, of_k, ins, cand, chosen, k)
    calls.append({"chosen": len(chosen), "cand": len(cand), "n_k": int(of_k.sum()), "acted": r is not chosen,
                  "cpu": time.process_time() - t})
    return r


T._match_nn = wrapped
rows = []
for scale in [float(s) for s in (sys.argv[1:] or ["3.5", "5", "7", "14"])]:
    cpu = {}
    for on in (False, True):
        T.THIN_MATCH_NN = on
        calls.clear()
        t = time.process_time()
        out = synthesize(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=1)
        cpu[on] = time.process_time() - t
    row = {"scale": scale, "n": len(out), "cpu_off": cpu[False], "cpu_on": cpu[True], "ratio": cpu[True] / cpu[False],
           "match_nn_cpu": sum(c["cpu"] for c in calls), "acted": any(c["acted"] for c in calls), "calls": list(calls)}
    rows.append(row)
    print(f"scale {scale:5.1f} n {len(out):6d} cpu off {cpu[False]:6.1f} on {cpu[True]:6.1f} ratio {row['ratio']:.2f} "
          f"match_nn {row['match_nn_cpu']:.2f} s acted {row['acted']}", flush=True)
Path(__file__).parent.joinpath("results", "integ39_thin_scale.json").write_text(json.dumps(rows, indent=1))

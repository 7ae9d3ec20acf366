"""Cost and effect of the thinning choice (``strew.synth._thin._match_nn``) against the output's size.

Helper s72m (successor of ``integ39_thin_scale.py``). On ``--varied`` two_sizes p4s43 (where
the choice acts), synthesises regions 3.5x to 20x the exemplar's side with ``THIN_MATCH_NN``
off (the baseline, nearest first) and on, seed 1 (after one warm-up synthesis), and prints
per size: the CPU seconds of each synthesis and their ratio, the CPU seconds spent in
``_match_nn`` (every call, acted or not) and the rounds it scored in, whether it acted, and
nn[pebble>pebble] (the judge's value / tolerance, eq5 and local off) on and off. Then the
exponent of ``_match_nn``'s cost against the output's count over the sizes (least squares on
logs) and its ratio per doubling of count. JSON to
``benchmarks/results/s72m_thin_scale.json`` (or ``..._<tag>.json`` with ``TAG=``).

    PYTHONPATH=src:benchmarks:tests python benchmarks/s72m_thin_scale.py 3.5 5 7 14 20

``BATCH=<int>`` sets ``MATCH_NN_BATCH`` (a huge value: one removal per round, s70p's greedy
exactly); ``SEED=<int>`` the synthesis seed (default 1).
"""
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
import _variants
from _runner import fidelity_suite

import strew.synth._thin as T
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

if "BATCH" in os.environ:
    T.MATCH_NN_BATCH = int(os.environ["BATCH"])
seed = int(os.environ.get("SEED", "1"))
mk = fidelity_suite()
kw = (_variants.VARIED["two_sizes"] + _variants.EDGE.get("two_sizes", []))[4]
ex = mk.make_exemplar("two_sizes", rng=43, **kw)
x0, y0, x1, y1 = ex.region.bounds
calls = []
orig = T._match_nn


def wrapped(state, vis, of_k, ins, cand, chosen, k):
    r0 = list(getattr(T, "MATCH_NN_COUNT", [0, 0]))
    t = time.process_time()
    r = orig(state, vis, of_k, ins, cand, chosen, k)
    r1 = list(getattr(T, "MATCH_NN_COUNT", [0, 0]))
    calls.append({"chosen": len(chosen), "cand": len(cand), "n_k": int(of_k.sum()), "acted": r is not chosen,
                  "rounds": r1[0] - r0[0], "scores": r1[1] - r0[1], "cpu": time.process_time() - t})
    return r


def nn_metric(out):
    m = fidelity(ex, out, eq5=False, local=False).metrics["nn[pebble>pebble]"]
    return float(m.value), float(m.tolerance)


T._match_nn = wrapped
synthesize(ex, region=Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0)), rng=seed)  # warm-up (kernels, caches)
rows = []
for scale in [float(s) for s in (sys.argv[1:] or ["3.5", "5", "7", "14"])]:
    cpu, nn, n, mcalls = {}, {}, {}, {}
    for on in (False, True):
        T.THIN_MATCH_NN = on
        calls.clear()
        t = time.process_time()
        out = synthesize(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=seed)
        cpu[on] = time.process_time() - t
        nn[on] = nn_metric(out)
        n[on] = len(out)
        mcalls[on] = list(calls)
    c = mcalls[True]
    row = {"scale": scale, "n_off": n[False], "n_on": n[True], "cpu_off": cpu[False], "cpu_on": cpu[True],
           "ratio": cpu[True] / cpu[False], "match_nn_cpu": sum(x["cpu"] for x in c), "rounds": sum(x["rounds"] for x in c),
           "acted": any(x["acted"] for x in c), "nn_off": nn[False], "nn_on": nn[True], "calls": c}
    rows.append(row)
    print(f"scale {scale:5.1f} n {n[True]:6d} cpu off {cpu[False]:6.2f} on {cpu[True]:6.2f} ratio {row['ratio']:.3f} "
          f"match_nn {row['match_nn_cpu']:.3f} s rounds {row['rounds']:3d} acted {row['acted']} "
          f"nn[pebble>pebble] off {nn[False][0]:.4f} on {nn[True][0]:.4f} / {nn[True][1]:.3f}", flush=True)
if len(rows) > 1:
    x = np.log([r["n_on"] for r in rows])
    y = np.log([max(r["match_nn_cpu"], 1e-6) for r in rows])
    a = float(np.polyfit(x, y, 1)[0])
    print(f"exponent of _match_nn's CPU against the output's count: {a:.3f} "
          f"(pairwise: {', '.join(f'{(y[i+1]-y[i])/(x[i+1]-x[i]):.2f}' for i in range(len(rows)-1))})")
    rows.append({"exponent": a})
tag = os.environ.get("TAG")
name = f"s72m_thin_scale{'_' + tag if tag else ''}.json"
Path(__file__).parent.joinpath("results", name).write_text(json.dumps(rows, indent=1))

"""Helper s60c: per stage of synth's grow(), the fidelity metrics a row fails (clusters p3s25 / p3s32).

    PYTHONPATH=src:benchmarks python benchmarks/s60c_probe.py CLASS:LABEL:SEEDS [--metrics nn[disc>disc],empty_circle,density[dot]]

At the end of growth's loop and after each later pass, the state's arrangement is judged
(fidelity, eq5 and local off, as the audit) and the chosen metrics printed with the counts.
"""
import argparse
import sys
import time

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar

import strew.synth._displace as DP
import strew.synth._farmix as FM
import strew.synth._grow as G
import strew.synth._pebbles as PB
import strew.synth._shell as SH
import strew.synth._swap as SW
import strew.synth._thin as TH
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

LOG = []
EX = [None]
MET = []


def judge(state, label):
    arr = state.to_arrangement()
    rep = fidelity(EX[0], arr, eq5=False, local=False)
    vals = " ".join(f"{k}={rep.metrics[k].value:.3f}" for k in MET if k in rep.metrics)
    fails = [k for k, m in rep.metrics.items() if m.applicable and not m.passed]
    cnt = {k: int(np.sum(arr.kind == i)) for i, k in enumerate(arr.kinds)}
    LOG.append(f"   {label:24s} n={len(arr)} {cnt} {vals} fails={fails}")


def wrap(mod, name):
    f = getattr(mod, name)

    def g(state, *a, **k):
        if name == "_complete_anchor_rings":
            judge(state, "growth loop")
        r = f(state, *a, **k)
        judge(state, name)
        return r

    setattr(mod, name, g)


for mod, name in [(G, "_complete_anchor_rings"), (DP, "fill_displaced"), (SH, "fill_beside_largest"), (FM, "trade_far_small"), (FM, "trade_far_top"),
                  (SH, "fill_beside_far_small"), (G, "fill_room"), (PB, "fill_partners"), (SW, "fill_swapped"), (G, "fill_holes"), (TH, "thin_small")]:
    wrap(mod, name)

ap = argparse.ArgumentParser()
ap.add_argument("specs", nargs="+")
ap.add_argument("--scale", type=float, default=3.5)
ap.add_argument("--metrics", default="nn[disc>disc],empty_circle,density[dot],density[disc]")
args = ap.parse_args()
MET[:] = args.metrics.split(",")
mk = fidelity_suite()
for spec in args.specs:
    cls, label, seeds = spec.split(":")
    ex = exemplar(mk, cls, label)
    EX[0] = ex
    x0, y0, x1, y1 = ex.region.bounds
    for seed in [int(s) for s in seeds.split(",")]:
        LOG.clear()
        t = time.process_time()
        out = synthesize(ex, Region.rectangle(args.scale * (x1 - x0), args.scale * (y1 - y0)), rng=seed, measure=False)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        print(f"== {spec} seed {seed} n={len(out)} faithful={rep.faithful} {fails} cpu={time.process_time() - t:.0f}s", flush=True)
        print("\n".join(LOG), flush=True)

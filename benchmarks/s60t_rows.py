"""Helper s60t: fresh17_rows.py / syn13z_rows.py-style six-seed rows with ``_grow.OWN_AHEAD_Z``
(env S60T_Z; S60T_ADD=1: added to the slack, s46t's form) and ``OWN_AHEAD`` (env S60T_OWN=0: off) set, so a Z sweep needs no source edit.

    S60T_Z=0.5 PYTHONPATH=src:benchmarks python benchmarks/s60t_rows.py p4s29,h6s29 1-6
"""
import os
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from s60t_ahead_probe import exemplar
from synth_variants import run

import strew
import strew.synth._grow as G
from strew.metrics import fidelity

if "S60T_Z" in os.environ:
    G.OWN_AHEAD_Z = float(os.environ["S60T_Z"])
if os.environ.get("S60T_ADD") == "1":
    # s46t's form: the margin added to the slack (SLACK x want + Z sqrt(want))
    G._ahead_bound = lambda want: G.OWN_AHEAD_SLACK * want + G.OWN_AHEAD_Z * float(want) ** 0.5
if os.environ.get("S60T_OWN") == "0":
    G.OWN_AHEAD = False
seeds = _variants.ints(sys.argv[2])
tot = n = 0
for label in sys.argv[1].split(","):
    ex = exemplar(label)
    res = []
    for seed in seeds:
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        res.append(int(rep.faithful))
        print(f"  synth three_sizes:{label} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {' '.join(fails)}", flush=True)
    print(f"synth three_sizes:{label} {sum(res)}/{len(res)}", flush=True)
    tot += sum(res)
    n += len(res)
print(f"total {tot}/{n}  Z={getattr(G, 'OWN_AHEAD_Z', None)} ({strew.__file__})", flush=True)

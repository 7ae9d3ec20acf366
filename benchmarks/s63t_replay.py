"""Helper s63t: from a log of ``s60t_ahead_probe.py --run`` taken with the rule unable to act
(``S60T_Z=1e9``: main's trajectory, main's output), the first growth call at which each form of
``_grow._ahead_bound`` would own the largest class. A form that never would leaves main's output
byte for byte (the rule is the only change; ``_farmix.TOP_DRAW`` waits for it).

    PYTHONPATH=src:benchmarks python benchmarks/s63t_replay.py LOG LABEL [LOG LABEL ...]
"""
import re
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np

from s60t_ahead_probe import exemplar

import strew.synth._grow as G
from strew.synth._api import new_state

S = G.OWN_AHEAD_SLACK


def forms(fano):
    return {
        "poisson_max(s60t)": lambda w: max(S * w, w + np.sqrt(w)),
        "poisson_add": lambda w: S * w + np.sqrt(w),
        "spread_max": lambda w: max(S * w, w + np.sqrt(fano * w)),
        "spread_add(s63t)": lambda w: S * w + np.sqrt(fano * w),
        "slack_alone(s46t)": lambda w: S * w,
    }


args = sys.argv[1:]
for path, label in zip(args[::2], args[1::2]):
    prep = new_state(exemplar(label)).prep
    _t, _a, cover, _r = G._own_setup(prep)
    fano = float(G._top_spread(prep)[cover > 0].max()) if (cover > 0).any() else 1.0
    seed = None
    rows = {}
    head = {}
    for line in open(path):
        m = re.match(r"(\S+) seed (\d+): (\S+) n=(\d+)(.*)", line)
        if m:
            if m.group(1) != label:
                seed = None
                continue
            seed = int(m.group(2))
            rows[seed] = []
            head[seed] = f"{m.group(3)} n={m.group(4)}{m.group(5).split('acted=0')[-1]}"
            continue
        m = re.search(r"want=\s*([\d.]+) have=\s*(\d+)", line)
        if m and seed is not None:
            rows[seed].append((float(m.group(1)), int(m.group(2))))
    print(f"{label} fano={fano:.3f}")
    for seed, calls in rows.items():
        first = {}
        for name, bound in forms(fano).items():
            hit = [i for i, (w, h) in enumerate(calls) if w > 0 and h > bound(w)]
            first[name] = f"call {hit[0] + 1}/{len(calls)} ({calls[hit[0]][1]} vs {calls[hit[0]][0]:.1f})" if hit else "never"
        print(f"  seed {seed} main: {head[seed].strip()}")
        for name, v in first.items():
            print(f"    {name:20s} first owns: {v}")

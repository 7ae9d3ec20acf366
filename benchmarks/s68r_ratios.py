"""Helper s68r: inner density ratios (synth output / exemplar, as ``_room_cap`` counts) of three sizes
--harder h8s41 (100:150:10, variant seed 41) at a given scale and seeds, and how often fill_room's gate
(``_larger_short``) held.

    PYTHONPATH=src:benchmarks:tests python benchmarks/s68r_ratios.py 2.0 1,2,3
"""
import sys

from strew_testing import fidelity_suite, synth_inner_density_ratios

import strew.synth._grow as G

_short = G._larger_short
HELD = [0, 0]


def larger_short(state):
    r = _short(state)
    HELD[0] += int(r)
    HELD[1] += 1
    return r


G._larger_short = larger_short
ex = fidelity_suite().make_exemplar("three_sizes", rng=41, counts=(100, 150, 10))
scale = float(sys.argv[1])
for seed in [int(x) for x in sys.argv[2].split(",")]:
    HELD[:] = [0, 0]
    r = synth_inner_density_ratios(ex, rng=seed, scale=scale)
    print(f"h8s41 scale {scale} seed {seed}: " + " ".join(f"{k} {v:.3f}" for k, v in r.items()) + f" | gate held {HELD[0]} of {HELD[1]}", flush=True)

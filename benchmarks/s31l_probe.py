"""Helper s31l (issue 13 point 1): small and large stones of a --harder three sizes row at a
given scale and seeds, per 1e4 area 20 in from the output's frame, against the exemplar's.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s31l_probe.py CLASS:H:V SCALE SEEDS
"""
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from syn13z_rows import counts
from synth_variants import _harder, run

from strew.metrics import fidelity

name, i, v = sys.argv[1].split(":")
scale = float(sys.argv[2])
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
print("exemplar", counts(ex, 0))
for seed in [int(x) for x in sys.argv[3].split(",")]:
    t0 = time.process_time()
    out, _ = run(ex, scale, seed, None)
    rep = fidelity(ex, out, eq5=False, local=False)
    print(f"seed {seed} n={len(out)} cpu {time.process_time() - t0:.1f} {'pass' if rep.faithful else 'FAIL'} {rep.failures} out {counts(out, 20)}", flush=True)

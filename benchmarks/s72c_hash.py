"""Helper s72c: digests of synth outputs (positions, kinds, rotations) over the rows that the
two-class density rule (``strew.synth._grow._TWO_CLASS_AREA``) reaches, to show its faster
grown core byte-identical to main's: the suite's two_sizes exemplar at 3.5x and 7x and
--varied two_sizes p2s33, p3s30, p4s43 at 3.5x, seeds 1 and 2.

    PYTHONPATH=src:benchmarks python benchmarks/s72c_hash.py            # this tree
    PYTHONPATH=/path/to/main/src:benchmarks python benchmarks/s72c_hash.py   # main
"""
import hashlib
import sys
import time

sys.path.insert(0, "benchmarks")
import _variants
import numpy as np
from _runner import fidelity_suite
from synth_variants import run

import strew

ROWS = [("v1", 3.5), ("v1", 7.0), ("p2s33", 3.5), ("p3s30", 3.5), ("p4s43", 3.5)]
mk = fidelity_suite()
cls = "two_sizes"
print("strew from", strew.__file__, flush=True)
for label, scale in ROWS:
    if label.startswith("v"):
        ex = mk.make_exemplar(cls, rng=int(label[1:]))
    else:
        i, _, v = label[1:].partition("s")
        assert int(v) < 47  # held-out variant seeds are not ours to run
        ex = mk.make_exemplar(cls, rng=int(v), **(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)])
    for seed in (1, 2):
        t = time.process_time()
        out, _ = run(ex, scale, seed, None)
        cpu = time.process_time() - t
        h = hashlib.sha1(np.ascontiguousarray(out.xy).tobytes() + np.ascontiguousarray(out.kind).tobytes()
                         + np.ascontiguousarray(out.rotation).tobytes()).hexdigest()[:12]
        print(f"{cls}:{label}:{scale}:{seed} n {len(out)} {h} cpu {cpu:.1f}", flush=True)

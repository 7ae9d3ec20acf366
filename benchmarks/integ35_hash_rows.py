"""Coordinator, stop 60: hash synth outputs (positions, kinds, rotations) of chosen rows, to show a refactor byte-identical.

    PYTHONPATH=src:benchmarks python benchmarks/integ35_hash_rows.py clusters:p3s25:1,clusters:h2s30:1,rings:v1:1

LABEL v9, p2s10 (--varied set 2) or h2s30 (--harder set 2), then the seed.
"""
import hashlib
import sys

sys.path.insert(0, "benchmarks")
import _variants
import numpy as np
from _runner import SKIPPED, fidelity_suite
from synth_variants import _harder, run

if len(sys.argv) < 2 or sys.argv[1].startswith("--"):
    sys.exit(SKIPPED)  # needs its rows (run_all.py --quick passes none)
mk = fidelity_suite()
H = _harder()
for spec in sys.argv[1].split(","):
    cls, label, seed = spec.split(":")
    if label.startswith("v"):
        ex = mk.make_exemplar(cls, rng=int(label[1:]))
    elif label.startswith("p"):
        i, _, v = label[1:].partition("s")
        ex = mk.make_exemplar(cls, rng=int(v), **(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)])
    else:
        i, _, v = label[1:].partition("s")
        ex = mk.make_exemplar(cls, rng=int(v), **H[cls][int(i)])
    out, _ = run(ex, 3.5, int(seed), None)
    h = hashlib.sha1(np.ascontiguousarray(out.xy).tobytes() + np.ascontiguousarray(out.kind).tobytes() + np.ascontiguousarray(out.rotation).tobytes()).hexdigest()[:12]
    print(spec, len(out), h, flush=True)

"""Helper s47p: hashes of synth outputs (seed 1, 3.5x) on rows where the change does not act;
run on both trees (PYTHONPATH=TREE/src:benchmarks) and compare."""
import hashlib
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run

mk = fidelity_suite()
for lab in sys.argv[1:] or ["two_sizes:p3s29", "three_sizes:p4s29", "three_sizes:p0s31"]:
    c, lbl = lab.split(":")
    ex = exemplar(mk, c, lbl)
    out, _ = run(ex, 3.5, 1, None)
    h = hashlib.sha1(np.ascontiguousarray(np.asarray(out.xy)).tobytes() + np.asarray(out.kind).tobytes()).hexdigest()[:12]
    print(lab, len(out), h, flush=True)

"""s65c: n and a sha1 of the output's columns (kind, x, y, rotation, scale) of chosen ``--varied``
rows, synth seed 1 at 3.5x, to compare bytes between trees (run it in each).

    PYTHONPATH=src:benchmarks python benchmarks/s65c_bytes.py clusters:p2s36,two_sizes:v7
"""
import hashlib
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run

import strew.synth._grow as G

mk = fidelity_suite()
REFUSED = [0]
_orig = getattr(G, "_ring_full", None)


def _count(state, pts, src, caps):
    out = _orig(state, pts, src, caps)
    REFUSED[0] += int(out.sum())
    return out


if hasattr(G, "_ring_full"):
    G._ring_full = _count
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    REFUSED[0] = 0
    out, _ = run(exemplar(mk, cls, label), 3.5, 1, None)
    h = hashlib.sha1()
    for a in (np.asarray(out.kind_names).astype(str), out.x, out.y, out.rotation, out.scale):
        h.update(np.ascontiguousarray(a).tobytes())
    print(f"{spec} n={len(out)} sha1={h.hexdigest()[:16]} ring-cap refusals={REFUSED[0] if hasattr(G, '_ring_full') else '-'}", flush=True)

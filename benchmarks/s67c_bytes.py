"""s67c: n and a sha1 of the output's columns (kind, x, y, rotation, scale) of chosen rows
(``--varied`` v/p labels and ``--harder`` h labels), synth seed 1 at 3.5x, to compare bytes
between trees (run it in each; as benchmarks/s65c_bytes.py, with h labels), and the
number of ring-cap refusals where the tree has the cap.

    PYTHONPATH=src:benchmarks python benchmarks/s67c_bytes.py three_sizes:h6s19,clusters:p4s38
"""
import hashlib
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._grow as G

REFUSED = [0]
_orig = getattr(G, "_ring_full", None)


def _count(state, pts, src, caps):
    out = _orig(state, pts, src, caps)
    REFUSED[0] += int(out.sum())
    return out


if _orig is not None:
    G._ring_full = _count
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    v = int(label[1:]) if label.startswith("v") else int(label.rsplit("s", 1)[1])
    assert v <= 40, "held-out variant seeds"
    if label.startswith("h"):
        i, _, vv = label[1:].partition("s")
        ex = _harder_suite().make_exemplar(cls, rng=int(vv), **_harder()[cls][int(i)])
    else:
        ex = exemplar(fidelity_suite(), cls, label)
    REFUSED[0] = 0
    out, _ = run(ex, 3.5, 1, None)
    h = hashlib.sha1()
    for a in (np.asarray(out.kind_names).astype(str), out.x, out.y, out.rotation, out.scale):
        h.update(np.ascontiguousarray(a).tobytes())
    print(f"{spec} n={len(out)} sha1={h.hexdigest()[:16]} ring-cap refusals={REFUSED[0] if _orig is not None else '-'}", flush=True)

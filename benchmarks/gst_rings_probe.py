"""Helper gst: grow rings (default parameters) at a variant seed: the judge's
orientation.relative histograms (result against exemplar) and, with ``phase``, the same
output with each copied ring turned by a uniform phase within its tiles' period.

    PYTHONPATH=src python benchmarks/gst_rings_probe.py [VARIANT=14] [SEEDS=1]
"""
import os
import sys
from types import SimpleNamespace

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite
from grow_variants import run

from strew import _fidelity
from strew.metrics import fidelity

_calls = []
_disc = _fidelity._discrepancies


def _spy(a, b, kinds, s, **kw):
    _calls.append((a, b))
    return _disc(a, b, kinds, s, **kw)


_fidelity._discrepancies = _spy

mk = fidelity_suite()
v = int(sys.argv[1]) if len(sys.argv) > 1 else 14
seeds = [int(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "1").split(",")]
ex = mk.make_exemplar("rings", rng=v)
for s in seeds:
    out, _ = run(ex, 3.5, s, SimpleNamespace(mode="fixed", times=10.0))
    _calls.clear()
    rep = fidelity(ex, out, eq5=False, local=False)
    a, b = _calls[0]
    m = rep.metrics["orientation.relative"]
    print(f"seed {s}: orientation.relative {m.value:.4f}/{m.tolerance:.4f}")
    print("  result  ", np.round(a.rel, 3))
    print("  exemplar", np.round(b.rel, 3))
    print("  diff    ", np.round(a.rel - b.rel, 3))

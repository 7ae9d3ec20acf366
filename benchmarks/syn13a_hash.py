"""Helper syn13a: digests of synth outputs outside the largest-class ownership rule (2x, seed 1), to compare two trees:

    PYTHONPATH=TREE/src python benchmarks/syn13a_hash.py
"""
import hashlib
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.synth import synthesize

mk = _harder_suite()
for name, h, v in [("two_sizes", 4, 7), ("clusters", None, 0), ("stones", None, 0), ("rings", None, 0), ("three_sizes", None, 0), ("three_sizes", 7, 7)]:
    ex = mk.make_exemplar(name) if h is None else mk.make_exemplar(name, rng=v, **HARDER[name][h])
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    print(name, h, len(out), hashlib.sha1(np.ascontiguousarray(np.c_[out.xy, out.kind, out.rotation]).tobytes()).hexdigest()[:16])

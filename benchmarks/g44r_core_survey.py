"""Helper g44r: the nearest-neighbour distances of every audit exemplar under the spread
test (``GAP_LATTICE_CV``), where ``lattice_like``'s hard-core test decides, saved for the
shape statistics of ``benchmarks/g44r_core_stats.py`` (suite + v/p/h sets).

    PYTHONPATH=src:benchmarks python benchmarks/g44r_core_survey.py OUT.npz [CLASSES=all] [SEEDS=1-30]
"""
import os
import sys
import warnings

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
warnings.filterwarnings("ignore")
import _variants
from grow_variants import HARDER, _harder_suite

from strew.grow._growth import GAP_LATTICE_CV

mk = _harder_suite()
out = sys.argv[1]
only = sys.argv[2].split(",") if len(sys.argv) > 2 and sys.argv[2] != "all" else list(mk.EXEMPLARS)
vs = _variants.ints(sys.argv[3]) if len(sys.argv) > 3 else list(range(1, 31))
assert not {31, 32} & set(vs), "31, 32 are held out"
keep = {}
n_all = 0
for cls in only:
    exs = [("suite", {}, None)] + [(f"v{v}", {}, v) for v in vs]
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    exs += [(f"p{i}s{s}", kw, s) for i, kw in enumerate(sets) for s in vs]
    exs += [(f"h{i}s{s}", kw, s) for i, kw in enumerate(HARDER.get(cls, [])) for s in vs]
    for label, kw, v in exs:
        ex = mk.make_exemplar(cls, rng=v, **kw) if v is not None else mk.make_exemplar(cls, **kw)
        n_all += 1
        if len(ex) < 3:
            continue
        nn = cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]
        if float(nn.std()) >= GAP_LATTICE_CV * float(nn.mean()):
            continue
        keep[f"{cls}:{label}"] = nn
    print(cls, n_all, len(keep), flush=True)
    np.savez_compressed(out, **keep)  # after each class: a long survey can be read as it goes
print(f"{n_all} exemplars, {len(keep)} under the spread test")

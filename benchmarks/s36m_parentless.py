"""Helper s36m: parentless elements cut to -3 (_prepare.parents, no-parent branch) per kind, and their
nearest larger element over the kind's median parent distance.

    PYTHONPATH=src:benchmarks python benchmarks/s36m_parentless.py three_sizes:6:24 three_sizes:8:24 ...
"""
import sys
sys.path.insert(0, "benchmarks")
import numpy as np
from grow_variants import _harder_suite
from synth_variants import _harder
from strew.synth import as_selection
from strew.synth import _prepare as P
for spec in sys.argv[1:]:
    name, i, v = spec.split(":")
    ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
    p = P.prepare(as_selection(ex))
    raw = P.parents(p.pos, p.size_class, p.source, p.void, None, p.kind)
    kn = np.asarray(ex.kind_names)
    out = []
    for k in sorted(set(kn)):
        m = np.flatnonzero(kn == k)
        has = raw[m] >= 0
        if not has.any() or p.size_class[m].min() == p.size_class.max(): continue
        med = np.median(np.hypot(*(p.pos[raw[m[has]]] - p.pos[m[has]]).T))
        cut = m[(p.parent[m] == -3) & (raw[m] == -1)]
        larger = np.flatnonzero(p.size_class > p.size_class[m[0]])
        dl = np.array([np.hypot(*(p.pos[larger] - p.pos[e]).T).min() for e in cut])
        out.append(f"{k}: parentless-cut {len(cut)} of {len(m)}, median pd {med:.1f}, nearest-larger/med {np.round(np.sort(dl/med),2).tolist()}")
    print(spec, " | ".join(out))

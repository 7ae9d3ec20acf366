"""Helper s42k: prepare-only census of the hard-core endpoint bound and its JAMMED_CORE gate.

    PYTHONPATH=src:benchmarks python benchmarks/s42k_census.py 7-28 [CLASS,...] [--harder]

Per row (``--varied`` labels v<s>, p<i>s<s>; with ``--harder`` h<i>s<s>): whether
``prepare`` sets any min_dist above 0.95 of the closest approach, with the gate
(``JAMMED_CORE`` 1.02) and without it (s37k's bound), and the exemplar's lowest nn decile
over its least nn distance (q10/x1). Prints one line per row where either acts, then counts.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
from scipy.spatial import cKDTree

import _variants
from _runner import fidelity_suite
from strew.synth import as_selection, prepare
from strew.synth import _prepare as P

harder = "--harder" in sys.argv
args = [a for a in sys.argv[1:] if a != "--harder"]
variants = _variants.ints(args[0])
if harder:
    from grow_variants import _harder_suite
    from synth_variants import _harder
    mk, sets_of = _harder_suite(), (lambda c: [(f"h{i}", kw) for i, kw in enumerate(_harder().get(c, []))])
else:
    mk = fidelity_suite()
    sets_of = lambda c: [("v", {})] + [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(c, []) + _variants.EDGE.get(c, []))]
names = args[1].split(",") if len(args) > 1 else list(mk.NAMES)


def acts(ex, jam):
    P.JAMMED_CORE = jam
    p = prepare(as_selection(ex))
    raw = P.closest_approach(p.pos, p.skind, p.source)
    ok = np.isfinite(raw)
    return bool(np.any(p.min_dist[ok] > 0.95 * raw[ok] * (1 + 1e-9))), float((p.min_dist[ok] / raw[ok]).max()) if ok.any() else 0.0


tot = {}
for cls in names:
    for lab, kw in sets_of(cls):
        for v in variants:
            ex = mk.make_exemplar(cls, rng=v, **kw)
            d = cKDTree(np.asarray(ex.xy, float)).query(np.asarray(ex.xy, float), k=2)[0][:, 1]
            q = float(np.quantile(d, 0.1) / d.min())
            g, gb = acts(ex, 1.02)
            u, ub = acts(ex, np.inf)
            t = tot.setdefault(cls, [0, 0, 0])
            t[0] += 1; t[1] += g; t[2] += u
            if g or u:
                print(f"{cls:12s} {lab}s{v}: q10/x1 {q:.3f} gated {'ACTS' if g else '-   '} {gb:.3f}  ungated {'ACTS' if u else '-   '} {ub:.3f}", flush=True)
for cls, (n, g, u) in tot.items():
    print(f"TOTAL {cls:12s} rows {n:4d} gated acts {g:4d} ungated acts {u:4d}")
print(f"TOTAL all rows {sum(t[0] for t in tot.values())} gated {sum(t[1] for t in tot.values())} ungated {sum(t[2] for t in tot.values())}")

"""Helper g42s: which exemplars (classes x draws 0, 23-28; --varied and EDGE sets) would change
pair_close if the own-kind distance rule also applied to kinds whose own nearest distances
are not lattice-like (OWN_HARD_CORE, a switch of the rejected diff
benchmarks/results/g42s_stripes_own_hard_core.diff; needs it applied).
"""
import sys, numpy as np
sys.path.insert(0, "benchmarks")
import _variants
from _runner import fidelity_suite
import strew.grow._growth as GG
from strew.grow import analyze
from strew import Region
mk = fidelity_suite()
try:
    import grow_variants as GV
    H = {c: v for c, v in _variants.HARDER.items()} if hasattr(_variants, "HARDER") else {}
except Exception:
    H = {}
flips = []
n = 0
for cls in mk.NAMES:
    sets = [None] + _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    for v in [0] + list(range(23, 29)):
        for i, kw in enumerate(sets):
            lab = f"v{v}" if kw is None else f"p{i-1}s{v}"
            try:
                ex = mk.make_exemplar(cls, rng=v, **(kw or {}))
                ref = analyze(ex)
            except Exception as e:
                continue
            n += 1
            res = []
            for flag in (False, True):
                GG.OWN_HARD_CORE = flag
                g = GG._Grower(ref, GG.GrowParams(region=Region.rectangle(300, 300)), np.random.default_rng(1))
                res.append(g.pair_close.copy())
            if not np.array_equal(*res):
                flips.append(f"{cls}:{lab}")
print(n, "exemplars;", len(flips), "change:", flips)

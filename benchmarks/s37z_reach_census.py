"""Helper s37z: which exemplars the hub reach of ``_prepare._far_hubs`` changes (prepare only, no synthesis).

    PYTHONPATH=src:benchmarks python benchmarks/s37z_reach_census.py [VARIANTS] [CLASSES]

For every class of the fidelity suite (default parameters), every ``VARIED`` + ``EDGE`` set
(``p<i>``) and every ``--harder`` set (``h<i>``) at variant seeds VARIANTS (default 1-30),
prints the exemplars where ``_far_hubs`` extends the reach (hubs, elements, hubs' nearest
other hub against their reach). Where it does not, n(e) and every synthesis are as on main.
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import numpy as np
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import _prepare, new_state

HIT = []
_orig = _prepare._far_hubs


def _rec(pos, reach, cls, own):
    a, m = _orig(pos, reach, cls, own)
    if len(a) >= 2:
        from scipy.spatial import cKDTree
        d, _ = cKDTree(pos[a]).query(pos[a], k=2)
        HIT.append(f"hubs {len(a)} elements {len(m)} hub nn {np.median(d[:, 1]):.1f} reach {np.median(reach[a]):.1f}")
    return a, m


_prepare._far_hubs = _rec
variants = _variants.ints(sys.argv[1]) if len(sys.argv) > 1 else list(range(1, 31))
only = sys.argv[2].split(",") if len(sys.argv) > 2 else None
mk, hk = fidelity_suite(), _harder_suite()
classes = [c for c in mk.NAMES if only is None or c in only]
hits = tot = 0
for cls in classes:
    sets = [("v", mk, {})] + [(f"p{i}", mk, kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]
    sets += [(f"h{i}", hk, kw) for i, kw in enumerate(_harder().get(cls, []))]
    for lab, m, kw in sets:
        for v in variants:
            try:
                ex = m.make_exemplar(cls, rng=v, **kw)
            except Exception as e:  # noqa: BLE001 - a generator that refuses a set
                print(f"{cls} {lab}s{v}: no exemplar ({e})")
                continue
            HIT.clear()
            new_state(ex, Region.rectangle(10, 10), rng=1)
            tot += 1
            if v == variants[-1]:
                print(f"{cls} {lab}: done", flush=True)
            if HIT:
                hits += 1
                print(f"{cls} {lab}s{v}: {'; '.join(HIT)}", flush=True)
print(f"{hits} of {tot} exemplars changed")

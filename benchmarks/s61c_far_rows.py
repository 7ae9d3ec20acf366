"""Helper s61c: which clusters rows (--varied vN/pIsN, --harder hIsN) have far hubs (``_prepare._far_hubs``), the only
rows ``fill_far_hub_rooms`` acts on (``_far_hub_room`` is None elsewhere, and so the pass is never called).

    PYTHONPATH=src:benchmarks python benchmarks/s61c_far_rows.py 27-34
"""
import sys
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from synth_variants import _harder
from strew import Region
from strew.synth import new_state

mk = fidelity_suite()
H = _harder()["clusters"]
sets = _variants.VARIED.get("clusters", []) + _variants.EDGE.get("clusters", [])
far = []
for v in _variants.ints(sys.argv[1]):
    rows = [(f"v{v}", {})] + [(f"p{i}s{v}", kw) for i, kw in enumerate(sets)] + [(f"h{i}s{v}", kw) for i, kw in enumerate(H)]
    for lab, kw in rows:
        ex = mk.make_exemplar("clusters", rng=v, **kw)
        prep = new_state(ex, Region.rectangle(200, 200), rng=1).prep
        f = getattr(prep, "_far_hubs", None)
        if f is not None and f.any():
            far.append(lab)
print("far-hub rows:", " ".join(far))

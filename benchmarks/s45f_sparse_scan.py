"""Helper s45f: which two/three sizes exemplars leave their smallest class far from
saturation (exemplar's rooms for one more > ROOM_SPARSE_SHARE x its count: the kinds
``ROOM_SPARSE_SHARE`` acts on). Exemplar only, no synthesis.

    PYTHONPATH=src:benchmarks python benchmarks/s45f_sparse_scan.py 7-30 [CLASS[,CLASS]] [SET[,SET]]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from synth_variants import _harder

import strew.synth._grow as G
from strew.synth._api import new_state


def main():
    vs = _variants.ints(sys.argv[1])
    mk = fidelity_suite()
    H = _harder()
    only = sys.argv[3].split(",") if len(sys.argv) > 3 else None
    for cls in (sys.argv[2].split(",") if len(sys.argv) > 2 else ("two_sizes", "three_sizes")):
        sets = [("v", {})] + [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]
        sets += [(f"h{i}", kw) for i, kw in enumerate(H.get(cls, []))]
        for lab, kw in sets:
            if only and lab not in only:
                continue
            hits = []
            for v in vs:
                ex = mk.make_exemplar(cls, rng=v, **kw)
                prep = new_state(ex, None).prep
                r1 = G._room_rate(prep, smallest=True, share=np.inf)
                sparse = ~np.isfinite(G._room_rate(prep, smallest=True, share=G.ROOM_SPARSE_SHARE)) & np.isfinite(r1)
                far = G._smallest_reach(prep)
                act = sparse & np.isfinite(far[:, -1])
                if act.any():
                    hits.append(v)
            print(f"{cls} {lab}: sparse smallest at {len(hits)}/{len(vs)} {hits}", flush=True)


if __name__ == "__main__":
    main()

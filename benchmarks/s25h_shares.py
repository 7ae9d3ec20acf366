"""Helper s25h: the exemplar's rooms for one more smallest-class element over its count
(``_grow._room_rate``'s share test, ROOM_SHARE) for every --harder set of CLASSES at VARIANTS.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s25h_shares.py two_sizes,three_sizes 15,16
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from s25h_small_rooms import exemplar_rooms
from synth_variants import _harder
from strew.synth._prepare import prepare
from strew.synth._api import as_selection

mk = _harder_suite()
for cls in sys.argv[1].split(","):
    for v in [int(x) for x in sys.argv[2].split(",")]:
        for h, kw in enumerate(_harder()[cls]):
            ex = mk.make_exemplar(cls, rng=v, **kw)
            prep = prepare(as_selection(ex, None))
            r = exemplar_rooms(prep)
            sc = {int(k): int(prep.size_class[prep.skind == k][0]) for k in r}
            print(f"{cls} h{h}s{v}", {ex.kinds[k] if k < len(ex.kinds) else k: (sc[k], round(c, 2)) for k, (a, b, c) in r.items()}, flush=True)

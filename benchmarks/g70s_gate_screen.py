"""Helper g70s: on which exemplars does the hard-core own-kind gate fire (``hard_core_own``)?

    PYTHONPATH=src:benchmarks python benchmarks/g70s_gate_screen.py two_sizes,three_sizes 1-44 [--suite]
Builds each --harder set, --varied set and default exemplar of the classes at the variant
seeds, sets up a grower (count 1, fixed mode) and records the kinds the gate turned on
that the 5 % spread test alone left off (the only places where the branch can differ).
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite
import _variants

import strew.grow._growth as G
from strew import Region
from strew.grow import grow

hits = []
orig = G.hard_core


def spy(nn):
    r = orig(nn)
    if sys._getframe(1).f_code.co_name == "__init__":
        m = np.asarray(nn, float)
        lo, med = float(m.min()), float(np.median(m))
        hits.append((r, med - lo < 0.05 * med))
    return r


G.hard_core = spy
mk = _harder_suite()
a, _, b = sys.argv[2].partition("-")
vs = [v for v in range(int(a), int(b) + 1) if v < 45]
tot = fired = 0
for cls in sys.argv[1].split(","):
    sets = [(f"h{i}", kw) for i, kw in enumerate(HARDER.get(cls, []))]
    sets += [(f"p{i}", kw) for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))]
    sets.append(("s", {}))
    for v in vs:
        for lab, kw in sets:
            ex = mk.make_exemplar(cls, rng=v, **kw)
            hits.clear()
            x0, y0, x1, y1 = ex.region.bounds
            grow(ex, region=Region.rectangle(x1 - x0, y1 - y0), rng=1, count=1)
            tot += 1
            new = [h for h in hits if h[0] and h[1]]
            if new:
                fired += 1
                print(f"  {cls} {lab}s{v}: gate fires on {len(new)} kind(s) (spread test off)", flush=True)
if "--suite" in sys.argv:
    # the fidelity suite's own draws (rng None: benchmarks/fidelity.py, grow_hashes.py
    # modes) and grow_hashes.py fixed's exemplars
    from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

    exs = [(f"{c} suite", mk.make_exemplar(c)) for c in sys.argv[1].split(",")]
    exs += [(f.__name__, f()) for f in (stone_exemplar, tile_exemplar, hex_exemplar)]
    for lab, ex in exs:
        hits.clear()
        grow(ex, count=1, rng=1)
        tot += 1
        new = [h for h in hits if h[0] and h[1]]
        print(f"  {lab}: gate {'fires on %d kind(s)' % len(new) if new else 'off'}", flush=True)
        fired += bool(new)
print(f"{fired} of {tot} exemplars", flush=True)

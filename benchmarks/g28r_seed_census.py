"""g28r: where a --harder row's kind shares come from: seeds made, placed and killed per kind.

Counts, in one growth, the seeds made per kind (ring slots that became seeds), those
killed while still seeds, those placed as each kind (``_Place.place``), and the kind
share of the elements at the end of the growth proper (before the post-passes) and in
the output. Monkey-patches ``_Grower`` methods for the count only.

    PYTHONPATH=src python benchmarks/g28r_seed_census.py two_sizes 4 17,18,19,20 1
"""
import collections
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import _growth, grow
from strew.grow._objects import SEED

G = _growth._Grower
C = collections.Counter()
_new, _kill, _place = G._new_object, G.kill, G.place


def new_object(self, x, y, kind):
    C["made", int(kind)] += 1
    return _new(self, x, y, kind)


def kill(self, i):
    if self.state[i] == SEED:
        C["killed", int(self.kind[i])] += 1
    return _kill(self, i)


def place(self, s, a, k, th, reach=None):
    own = int(self.kind[s])
    ok = _place(self, s, a, k, th, reach)
    C["tried", own] += 1
    if ok:
        C["placed", int(self.kind[s])] += 1
        if int(self.kind[s]) != own:
            C["converted", own, int(self.kind[s])] += 1
    return ok


G._new_object, G.kill, G.place = new_object, kill, place
mk = _harder_suite()
cls, i = sys.argv[1], int(sys.argv[2])
for v in [int(x) for x in sys.argv[3].split(",")]:
    ex = mk.make_exemplar(cls, rng=v, **HARDER[cls][i])
    names = list(ex.shapes)
    ke = np.asarray(ex.kind)
    for s in [int(x) for x in sys.argv[4].split(",")]:
        C.clear()
        x0, y0, x1, y1 = ex.region.bounds
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=s)
        ko = np.asarray(out.kind)
        K = len(names)
        made = [C["made", q] for q in range(K)]
        placed = [C["placed", q] for q in range(K)]
        killed = [C["killed", q] for q in range(K)]
        tried = [C["tried", q] for q in range(K)]
        sh = lambda a: " ".join(f"{x / max(sum(a), 1):.3f}" for x in a)
        print(f"h{i}s{v} s{s} ex {sh([int(np.sum(ke == q)) for q in range(K)])} made {made} ({sh(made)}) placed {placed} ({sh(placed)}) "
              f"killed {killed} tried {tried} out {sh([int(np.sum(ko == q)) for q in range(K)])} conv "
              + str({k[1:]: c for k, c in C.items() if k[0] == "converted"}), flush=True)

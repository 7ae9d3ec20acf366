"""Per-call CPU of GrowIndex.near (near_one) against 00c3e6f's near (hash_near with one-element
query arrays) on 3,000 random queries of a grown pattern of 2,000 stones, answers
checked equal; 8 interleaved rounds. Run: ``PYTHONPATH=src python benchmarks/spd15_nearcall.py``."""
import sys
import time

sys.path.insert(0, str(__import__("pathlib").Path(__file__).parent))
import numpy as np
from spd15_inproc import base_near

from strew.grow import _growth, _index, analyze, grow
from strew.grow._exemplars import stone_exemplar

ref = analyze(stone_exemplar())
seen = {}
orig = _growth._Grower.settle
def keep(self):
    seen["g"] = self; return orig(self)
_growth._Grower.settle = keep
grow(ref, count=2000, rng=1, relax=True)
g = seen["g"]; ix = g.index
rng = np.random.default_rng(1)
pts = g.pos[rng.integers(0, len(g.order), 3000)]
rs = rng.uniform(0.5, 2.5, 3000) * g.l
near = _index.GrowIndex.near
a = [near(ix, float(x), float(y), float(r), 6) for (x, y), r in zip(pts, rs)]
b = [base_near(ix, float(x), float(y), float(r), 6) for (x, y), r in zip(pts, rs)]
assert a == b
for rep in range(8):
    for name, f in (("near_one", near), ("base", base_near)):
        c = time.process_time()
        for (x, y), r in zip(pts.tolist(), rs.tolist()):
            f(ix, x, y, r, 6)
        print(name, f"{(time.process_time() - c) / 3000 * 1e6:.2f} us/call")

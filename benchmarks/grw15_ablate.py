"""grw15 probe: the --harder rows with the slot rule of _Place._over_smaller_seeds as it is
(base), off (noover), or held to the largest kind's share of the reference (sharegate,
monkeypatched; the rejected form is benchmarks/results/grw15_top_share_rejected.patch):
per row the kinds' shares over the exemplar's, empty_circle and the failing metrics.

    PYTHONPATH=TREE/src python benchmarks/grw15_ablate.py two_sizes:11:* 1 base|noover|sharegate
    (class:set:variant, variant '*' for 7-10; seeds comma-separated)
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

import strew.grow._growth as G
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

cls = next(v for v in vars(G).values() if isinstance(v, type) and hasattr(v, "advance") and hasattr(v, "settle"))
variant = sys.argv[3]
kw = {}
if variant == "noover":
    oi = cls.__init__
    def init(self, *a, **k):
        oi(self, *a, **k); self.over_smaller = False
    cls.__init__ = init
elif variant == "sharegate":
    from strew.grow._objects import ELEMENT
    oi = cls.__init__
    def init(self, *a, **k):
        oi(self, *a, **k)


        lv = self.size_level
        top = np.flatnonzero(lv == lv.max())
        self._top_kinds = top
        self._top_share = float(np.isin(np.asarray(self.ex_kind), top).mean())
    def over(self):
        if not self._over_static:
            return False
        n = len(self.order)
        if n < 20:
            return True
        st = self.state[: self.n] == ELEMENT
        t = int(np.count_nonzero(st & np.isin(self.kind[: self.n], self._top_kinds)))
        return t < self._top_share * int(np.count_nonzero(st))
    cls.__init__ = init
    cls.over_smaller = property(over, lambda self, v: setattr(self, "_over_static", v))
elif variant == "nocanopy":
    kw = {"canopy_quantile": None}
elif variant == "noprio":
    kw = {"priority": {}}
mk = _harder_suite()
for spec in sys.argv[1].split(","):
    c, i, v = spec.split(":")
    if v == "*":
        vs = [7, 8, 9, 10]
    else:
        vs = [int(v)]
    for v in vs:
      ex = mk.make_exemplar(c, rng=int(v), **HARDER[c][int(i)])
      ek = np.bincount(np.asarray(ex.kind)); share = ek / ek.sum()
      x0, y0, x1, y1 = ex.region.bounds
      npass = 0
      for seed in [int(s) for s in sys.argv[2].split(",")]:
          out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, **kw)
          cnt = np.bincount(np.asarray(out.kind), minlength=len(ek))
          rep = fidelity(ex, out, eq5=False, local=False)
          fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
          npass += rep.faithful
          print(f"{variant} {c}:{i}:{v} s{seed} n {len(out)} share/ex {np.round(cnt/cnt.sum()/share,3)} ec {rep.metrics['empty_circle'].value:.3f} {fails}", flush=True)
      print(f"{variant} {c}:{i}:{v} pass {npass}")

"""Helper g34d: A/B of an "each element keeps its reference's nearest distance" placement rule, judged.

    PYTHONPATH=src python benchmarks/g34d_ab.py CLASS:LABEL[,CLASS:LABEL...] SEEDS VARIANT[,VARIANT...]

VARIANT ``main`` (unpatched) or ``nnF`` / ``nnFu``: monkeypatched placement refusal when a
placed element lies nearer than F times the larger of the two elements' reference
nearest-neighbour distances in the exemplar (``u``: only elements the new one's matching
did not pair, i.e. not in w(e_tar)). The tree's own rule (strew.grow._spacing, h/g34d) is
turned off here (``reference_nn`` patched to None), so ``main`` is main's growth and
``nn1.0`` the same rule forced on every exemplar. Run and judged as the audit (fresh17_rows: 3.5x,
eq5 and local off). Prints density ratio, empty_circle and the failing metrics.
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants  # noqa: E402
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402

import strew.grow._growth as gr  # noqa: E402
from strew.grow._objects import ELEMENT  # noqa: E402
from strew.metrics import fidelity  # noqa: E402

CFG = {"f": 0.0, "u": False}
O_place, O_tc, O_init = gr._Grower.place, gr._Grower.too_close_in_kind, gr._Grower.__init__


def init(self, ref, p, rng):
    O_init(self, ref, p, rng)
    xy = np.asarray(ref.exemplar.xy, dtype=float)
    self._g34_enn = cKDTree(xy).query(xy, k=2)[0][:, 1]


def place(self, s, a, *r, **k):
    self._g34_a = a
    return O_place(self, s, a, *r, **k)


def tc(self, x, y, kind, s, states=None, placing=False):
    hit = O_tc(self, x, y, kind, s, states, placing) if states is not None else O_tc(self, x, y, kind, s, placing=placing)
    if hit or not placing or CFG["f"] <= 0:
        return hit
    rs = self._g34_enn[int(self.ref_ids[self._g34_a])]
    seen = set(self._last_nb.tolist()) if CFG["u"] else set()
    R = CFG["f"] * float(self._g34_enn.max())
    for o in self.near(x, y, R, (ELEMENT,)):
        if o == s or o in seen:
            continue
        ro = self._g34_enn[int(self.sub[o])]
        if (self.xy[o][0] - x) ** 2 + (self.xy[o][1] - y) ** 2 < (CFG["f"] * max(rs, ro)) ** 2:
            return True
    return False


gr._Grower.__init__, gr._Grower.place, gr._Grower.too_close_in_kind = init, place, tc
if hasattr(gr, "reference_nn"):
    gr.reference_nn = lambda *a, **k: None


def main():
    from types import SimpleNamespace

    from grow_variants import run

    specs, seeds, variants = sys.argv[1], _variants.ints(sys.argv[2]), sys.argv[3].split(",")
    mk = fidelity_suite()
    for spec in specs.split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        for v in variants:
            CFG["f"] = 0.0 if v == "main" else float(v[2:].rstrip("u"))
            CFG["u"] = v.endswith("u")
            for seed in seeds:
                out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
                rep = fidelity(ex, out, eq5=False, local=False)
                fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
                dens = {k: f"{m.value:.3f}" for k, m in rep.metrics.items() if k.startswith("density") and m.applicable}
                ec = rep.metrics.get("empty_circle")
                print(f"  {spec} {v} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} density {dens} "
                      f"empty_circle {ec.value:.3f}/{ec.tolerance:.3f} {' '.join(fails)}", flush=True)


if __name__ == "__main__":
    main()

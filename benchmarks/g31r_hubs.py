"""Helper g31r: where cluster hubs come nearer than the exemplar's least hub distance.

    PYTHONPATH=src python benchmarks/g31r_hubs.py clusters:p0s22 1-3

Grows the ``--varied`` row as ``grow_variants.py`` does and records, for every hub of the
hubs' growth (``_clusters.grow_clusters``), the distance to its nearest placed hub at the
moment it is placed (``_Place.place``) and at the end (after every relaxation window and
hole refill). Prints the exemplar's least hub distance ``lo`` and, at placement and at the
end, the quantiles of nearest distances over ``lo`` and the share below ``lo``; and how
many hubs were placed by the refill (``fill_void_holes``).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from types import SimpleNamespace

import numpy as np
from _runner import fidelity_suite
from _variants import ints
from fresh17_rows import exemplar
from grow_variants import run
from scipy.spatial import cKDTree

import strew.grow._growth as G
import strew.grow._place as P
import strew.grow._void_holes as V
from strew.grow._objects import ELEMENT

LOG = {}


def main():
    spec, seeds = sys.argv[1], ints(sys.argv[2])
    cls, label = spec.split(":")
    ex = exemplar(fidelity_suite(), cls, label)
    grows = []
    orig_place = P._Place.place

    def place(self, s, a, k, th, reach=None):
        ok = orig_place(self, s, a, k, th, reach)
        if ok and getattr(self, "_g31r", False):
            hx = np.array([self.xy[i] for i in range(self.n) if self.state[i] == ELEMENT and i != s])
            d = float(np.min(np.hypot(*(hx - np.asarray(self.xy[s])).T))) if len(hx) else np.inf
            self._g31r_at[s] = (d, self._g31r_phase, tuple(self.xy[s]))
        return ok

    P._Place.place = place
    orig_init = G._Grower.__init__

    def init(g, *a, **k):
        orig_init(g, *a, **k)
        g._g31r, g._g31r_at, g._g31r_phase = True, {}, "grow"
        grows.append(g)

    G._Grower.__init__ = init
    orig_fill = V.fill_void_holes

    def fill(g, *a, **k):
        g._g31r_phase = "refill"
        return orig_fill(g, *a, **k)

    V.fill_void_holes = fill
    kinds = np.asarray(ex.kind)
    hub = np.bincount(kinds).argmin()
    hxy = ex.xy[kinds == hub]
    lo = float(cKDTree(hxy).query(hxy, k=2)[0][:, 1].min())
    print(f"{spec}: exemplar hubs {len(hxy)}, least hub distance lo={lo:.2f}")
    for seed in seeds:
        grows.clear()
        run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
        g = grows[-1]
        idx = [i for i in range(g.n) if g.state[i] == ELEMENT]
        xy = np.array([g.xy[i] for i in idx])
        dend = cKDTree(xy).query(xy, k=2)[0][:, 1] / lo
        at = np.array([g._g31r_at.get(i, (np.nan, ""))[0] for i in idx]) / lo
        p0 = np.array([g._g31r_at[i][2] if i in g._g31r_at else g.xy[i] for i in idx])
        dpl = cKDTree(p0).query(p0, k=2)[0][:, 1] / lo
        moved = np.hypot(*(xy - p0).T) / lo
        ph = np.array([g._g31r_at.get(i, (np.nan, "?"))[1] for i in idx])
        q = [0, 0.05, 0.1, 0.25, 0.5]
        print(f" seed {seed}: hubs {len(idx)} (refill {int((ph == 'refill').sum())})")
        print(f"   at placement: q{q} {np.round(np.nanquantile(at, q), 3)} below lo {np.nanmean(at < 0.999):.3f}")
        print(f"   at the end:   q{q} {np.round(np.quantile(dend, q), 3)} below lo {np.mean(dend < 0.999):.3f}")
        print(f"   placed positions, all hubs at the end: q {np.round(np.quantile(dpl, q), 3)} below lo {np.mean(dpl < 0.999):.3f}; moved by relaxation (/lo) median {np.median(moved):.3f} q90 {np.quantile(moved, .9):.3f}")
        for p in ("grow", "refill"):
            m = ph == p
            if m.any():
                print(f"   {p}: placed {m.sum()}, end below lo {np.mean(dend[m] < 0.999):.3f}, placed below lo {np.nanmean(at[m] < 0.999):.3f}")


if __name__ == "__main__":
    main()

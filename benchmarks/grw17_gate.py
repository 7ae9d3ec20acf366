"""grw17 probe: rows (class:set:variant, or class:suite:V) at seeds with the slot rule of
_Place._over_smaller_seeds as it is (base) or held to the largest size level's share of
the reference counted by minus sampling (cropfree, monkeypatched): pass counts, the
kinds' densities against the exemplar's (the judge's), empty_circle.

    PYTHONPATH=TREE/src python benchmarks/grw17_gate.py two_sizes:3:10,two_sizes:suite:1 1-8 base|cropfree|whole
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
import shapely
from grow_variants import HARDER, _harder_suite

import strew.grow._growth as G
from strew import Region
from strew.grow import grow
from strew.grow._objects import ELEMENT
from strew.metrics import fidelity

cls = G._Grower
variant = sys.argv[3]


def cropfree_share(ex, top):
    from strew._fidelity import _wall_reach

    xy = np.asarray(ex.xy, float)
    kind = np.asarray(ex.kind)
    radius = np.array([ex.shapes[k].radius for k in ex.kinds])[kind] * np.asarray(ex.scale)
    geom = ex.region.geometry
    d = _wall_reach(xy, kind, radius, geom)
    edge = shapely.distance(geom.boundary, shapely.points(xy))
    c = edge >= d
    return float(np.isin(kind[c], top).mean())


if variant in ("cropfree", "whole"):
    oi = cls.__init__

    def init(self, *a, **k):
        oi(self, *a, **k)
        lv = self.size_level
        top = np.flatnonzero(lv == lv.max())
        self._top_kinds = top
        two = len(np.unique(lv)) == 2
        if not two:
            self._top_share = np.inf
        elif variant == "whole":
            self._top_share = float(np.isin(np.asarray(self.ex_kind), top).mean())
        else:
            self._top_share = cropfree_share(self.ref.exemplar, top)

    def over(self):
        if not self._over_static or not np.isfinite(self._top_share):
            return self._over_static
        st = self.state[: self.n] == ELEMENT
        t = int(np.count_nonzero(st & np.isin(self.kind[: self.n], self._top_kinds)))
        return t < self._top_share * int(np.count_nonzero(st))

    cls.__init__ = init
    cls.over_smaller = property(over, lambda self, v: setattr(self, "_over_static", v))
if variant.startswith("holes"):
    import strew.grow._void_holes as VH

    o_irr = cls._irregular

    def irregular(self):
        ex = self.ref.exemplar
        if bool(self.void_kind.any()) or len(ex) < 4:
            return False
        return float(self.size_level.max()) > float(self.size_level.min()) or o_irr(self)

    cls._irregular = irregular
    of = VH._fill_one

    def ref_far(g, a):
        """per kind b: the reference's largest nearest-b distance of an element of a (border corrected)"""
        from scipy.spatial import cKDTree

        ex = g.ref.exemplar
        xy = np.asarray(ex.xy, float)
        kd = np.asarray(g.ex_kind)
        geom = ex.region.geometry
        A = xy[kd == a]
        te = shapely.distance(geom.boundary, shapely.points(A))
        out = np.full(g.n_kinds, np.inf)
        for b in range(g.n_kinds):
            B = xy[kd == b]
            if len(B) < 2:
                continue
            d, _ = cKDTree(B).query(A, k=2 if a == b else 1)
            d = d[:, 1] if a == b else d
            d = d[d <= te]
            if len(d):
                out[b] = d.max() if variant == "holes_far" else np.quantile(d, 0.9)
        return out

    def fill_one(g, cx, cy, rad, lim, kind, removed_all, bare=False):
        lv = g.size_level
        if not float(lv.max()) > float(lv.min()):
            return of(g, cx, cy, rad, lim, kind, removed_all, bare)
        small = int(np.flatnonzero(lv == lv.min())[0])
        if variant in ("holes_far", "holes_q90"):
            far = getattr(g, "_far", None)
            if far is None:
                far = g._far = ref_far(g, small)
            for b in range(g.n_kinds):
                if not np.isfinite(far[b]):
                    continue
                near = [o for o in g.near(cx, cy, far[b], (ELEMENT,)) if int(g.kind[o]) == b]
                if not near:
                    return False
        return of(g, cx, cy, rad, lim, small, removed_all, bare)

    VH._fill_one = fill_one
mk = _harder_suite()
a, _, b = sys.argv[2].partition("-")
seeds = range(int(a), int(b or a) + 1)
tot = 0
for spec in sys.argv[1].split(","):
    c, i, v = spec.split(":")
    ex = mk.make_exemplar(c, rng=int(v)) if i == "suite" else mk.make_exemplar(c, rng=int(v), **HARDER[c][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    npass = 0
    for seed in seeds:
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        dens = [rep.metrics[f"density[{k}]"] for k in ex.kinds]
        dr = [round((m.result or 0) / (m.exemplar or 1), 3) for m in dens]
        npass += rep.faithful
        print(f"{variant} {spec} s{seed} n {len(out)} dens/ex {dr} ec {rep.metrics['empty_circle'].value:.3f} {fails}", flush=True)
    print(f"{variant} {spec} pass {npass}/{len(seeds)}", flush=True)
    tot += npass
print(f"{variant} total {tot}", flush=True)

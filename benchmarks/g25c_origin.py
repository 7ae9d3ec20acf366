"""Helper g25c: where a --harder three_sizes row's large stones come from (canopy vs growth).

For each row and seed (grow, fixed mode, region 3.5x): the reference's large count inside the
canopy's wall (the share gate's sample, ``_Grower._canopy_share_setup``) and whether the gate
is on; the output's large stones placed by a canopy conversion (``_Place.try_larger``) vs the
rest; the large density per 1e4 over the output's interior (>= 1.5 s from the edge) vs the
exemplar's interior; and the verdict (fidelity, eq5 and local off).

    PYTHONPATH=src python benchmarks/g25c_origin.py three_sizes:5:16,three_sizes:4:15 1-2 [MIN_REF=20] [param=value ...]
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite
from scipy.spatial import cKDTree

import strew.grow._growth as GR
import strew.grow._place as P
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

kw = {}
for a in sys.argv[3:]:
    k, v = a.split("=", 1)
    if k == "MIN_REF":
        GR.CANOPY_MIN_REF = int(v)
    else:
        kw[k] = eval(v)
if kw:
    from dataclasses import replace

    _init = GR._Grower.__init__

    def _patched(self, ref, params, *a, **k):
        _init(self, ref, replace(params, **kw), *a, **k)

    GR._Grower.__init__ = _patched
conv = []
info = {}
orig_try = P._Place.try_larger


def try_larger(self, s):
    out = orig_try(self, s)
    if out:
        conv.append(s)
    info["g"] = self
    return out


P._Place.try_larger = try_larger


def idens(xy, names, box, s, kind):
    x0, y0, x1, y1 = box
    edge = np.minimum.reduce([xy[:, 0] - x0, x1 - xy[:, 0], xy[:, 1] - y0, y1 - xy[:, 1]])
    m = 1.5 * s
    return 1e4 * float(((names == kind) & (edge >= m)).sum()) / ((x1 - x0 - 2 * m) * (y1 - y0 - 2 * m))


mk = _harder_suite()
a, _, b = sys.argv[2].partition("-")
for c in sys.argv[1].split(","):
    cls, i, v = c.split(":")
    ex = mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    exy = np.c_[ex.x, ex.y]
    s = np.median(cKDTree(exy).query(exy, k=2)[0][:, 1])
    en = np.asarray(ex.kind_names)
    for seed in range(int(a), int(b or a) + 1):
        conv.clear()
        W, H = 3.5 * (x1 - x0), 3.5 * (y1 - y0)
        out = grow(ex, region=Region.rectangle(W, H), rng=seed)
        g = info["g"]
        L = int(np.argmax(g.size_level))
        share = g.canopy_ref_share
        nL = int((en == "large").sum())
        cs = set(conv)
        nconv = sum(1 for o in g.order if o in cs and int(g.kind[o]) == L)
        on = share is not None and np.isfinite(share[L])
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        on_ = np.asarray(out.kind_names)
        print(f"{c} s{seed}: ref large {nL} gate {share[L] if on else 'off'} | out large {(on_ == 'large').sum()} of which canopy {nconv}"
              f" | interior large/1e4 {idens(np.c_[out.x, out.y], on_, (0, 0, W, H), s, 'large'):.2f}"
              f" vs ex {idens(exy, en, ex.region.bounds, s, 'large'):.2f} | {'pass' if rep.faithful else 'FAIL'} {fails}", flush=True)

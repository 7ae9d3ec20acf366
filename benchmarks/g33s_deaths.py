"""Helper g33s: which seeds die in grow's fixed mode (per kind, by distance from the frame), measured.

    PYTHONPATH=src python benchmarks/g33s_deaths.py CLASS:LABEL SEED [off]

Wraps ``_Grower.run`` to keep the grower; after the growth counts per kind the objects
that ended DEAD (seeds refused) against those placed, and the dead seeds' distance from
the region's frame (interior > 40). ``off``: the void-hole pass's limit patched to 0.
Grow is run as the audit's first attempt (3.5x, 10x elements target).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402

import strew.grow._growth as gr  # noqa: E402
import strew.grow._void_holes as vh  # noqa: E402
from strew import Region  # noqa: E402
from strew.grow import grow  # noqa: E402
from strew.grow._objects import DEAD, ELEMENT  # noqa: E402

kept = []
orig = gr._Grower.run


def run(self, *a, **k):
    kept.append(self)
    return orig(self, *a, **k)


gr._Grower.run = run
why = {}
o_choose, o_place = gr._Grower.choose, gr._Grower.place


def choose(self, s, *a, **k):
    r = o_choose(self, s, *a, **k)
    if r is None:
        why[s] = "no match"
    return r


def place(self, s, *a, **k):
    r = o_place(self, s, *a, **k)
    if not r:
        why[s] = "placement refused"
    return r


gr._Grower.choose, gr._Grower.place = choose, place


def main():
    spec, seed = sys.argv[1], int(sys.argv[2])
    if len(sys.argv) > 3 and sys.argv[3] == "off":
        vh.reference_visible_gap = lambda g: 0.0
    cls, label = spec.split(":")
    ex = exemplar(fidelity_suite(), cls, label)
    x0, y0, x1, y1 = ex.region.bounds
    W, H = 3.5 * (x1 - x0), 3.5 * (y1 - y0)
    out = grow(ex, region=Region.rectangle(W, H), mode="fixed", rng=seed)
    g = kept[-1]
    n = g.n
    st, kd, p = g.state[:n], g.kind[:n], g.pos[:n]
    db = np.minimum.reduce([p[:, 0], W - p[:, 0], p[:, 1], H - p[:, 1]])
    print(f"{spec} seed {seed} ({sys.argv[3] if len(sys.argv) > 3 else 'main'}): out n={len(out)} objects {n}")
    for k, name in enumerate(ex.kinds):
        m = kd == k
        dead, el = m & (st == DEAD), m & (st == ELEMENT)
        reasons = {}
        occ = {}
        els = np.flatnonzero(st == ELEMENT)
        from scipy.spatial import cKDTree

        t = cKDTree(p[els])
        for i in np.flatnonzero(dead):
            r = why.get(int(i), "other (domain, far, outranked...)")
            reasons[r] = reasons.get(r, 0) + 1
            if r == "placement refused" and db[i] > 40:
                _, j = t.query(g.xy[i])
                nm = ex.kinds[int(kd[els[j]])]
                occ[nm] = occ.get(nm, 0) + 1
        print(f"  {name:8s} death reasons {reasons}; interior refused seeds' nearest element (at the seed's point): {occ}")
        print(f"  {name:8s} placed {int(el.sum()):5d} dead {int(dead.sum()):5d} ({dead.sum() / max(dead.sum() + el.sum(), 1):.0%} of its seeds); dead in interior (>40 from frame) {int((dead & (db > 40)).sum())}")


if __name__ == "__main__":
    main()

"""Helper grw14s: where the far pairs of a failing --harder nn[a>b] row come from (grow, fixed mode).

For one ``--harder`` row, grows the output as the audit does (3.5x the frame's side) and,
for the elements of kind ``a`` away from the region's edge, splits them by the origin of
the seed they were placed from: the ring of a placed element of kind K (§5.4, ``ring K``),
or the lone-larger swap (``swap``: ``grow/_lone_larger.py``, a seed at a larger element's
centre, and the seeds that element's ring put out while it was placed), and gives per origin the share whose nearest ``b`` lies beyond the reference's
95th percentile distance (its elements at least ``--margin`` from the frame). Also: the
swaps made (from kind, to kind, placed), and the seeds of kind ``a`` that died on placing
because an element of another kind was too close (``too_close_in_kind``, by that kind).
``--no-lone`` turns the lone-larger swap off (``LONE_FACTOR = None``) for comparison.

Measured at 313948f (seeds 1 and 2): the swapped-in elements lay beyond the reference's
95th percentile 61/68 % (h7s7 small>medium), 57/74 % (h9s7 medium>medium), 75/71 %
(h9s8 small>large) of the time, against 11-18 %, 0-22 % and 16-40 % for the elements
grown from rings; they were 35-55 % of the far elements.

    PYTHONPATH=src python benchmarks/grw14s_origin.py three_sizes:7:7 small medium --seeds 1,2
    PYTHONPATH=src python benchmarks/grw14s_origin.py three_sizes:9:7 medium medium --seeds 1 --no-lone
"""
import argparse
import collections
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

import strew.grow._lone_larger as L
from strew import Region
from strew.grow import _growth as G
from strew.grow import grow
from strew.grow._objects import ELEMENT
from strew.metrics import fidelity


def nn_to(arr, A, B, margin):
    x0, y0, x1, y1 = arr.region.bounds
    ia = np.flatnonzero(arr.kind == A)
    d = cKDTree(arr.xy[arr.kind == B]).query(arr.xy[ia], k=2 if A == B else 1)[0]
    if A == B:
        d = d[:, 1]
    ins = (arr.x[ia] > x0 + margin) & (arr.x[ia] < x1 - margin) & (arr.y[ia] > y0 + margin) & (arr.y[ia] < y1 - margin)
    return ia[ins], d[ins]


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("row", help="case:index:variant, e.g. three_sizes:9:7")
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--seeds", default="1")
    p.add_argument("--margin", type=float, default=30.0)
    p.add_argument("--no-lone", action="store_true")
    o = p.parse_args()
    if o.no_lone:
        L.LONE_FACTOR = None
    Gr = G._Grower
    st: dict = {}

    place0, new0, swap0, res0, close0 = Gr.place, Gr.new_object, L._swap_one, Gr.result, Gr.too_close_in_kind

    def place(self, s, a, k, th, reach=None):
        st["par"].append(int(self.ex_kind[int(self.ref_ids[a])]))
        try:
            ok = place0(self, s, a, k, th, reach)
        finally:
            st["par"].pop()
        if ok:
            st["origin"][s] = st["born"].get(s, "?")
        return ok

    def new_object(self, x, y, kind):
        i = new0(self, x, y, kind)
        st["born"][i] = ("swap" if st["swapping"] else f"ring {self.ref.exemplar.kinds[st['par'][-1]]}") if (st["par"] or st["swapping"]) else "other"
        return i

    def swap_one(g, oo, a):
        b = int(g.kind[oo])
        st["swapping"] = True
        try:
            ok = swap0(g, oo, a)
        finally:
            st["swapping"] = False
        st["swaps"][(g.ref.exemplar.kinds[b], g.ref.exemplar.kinds[a], ok)] += 1
        return ok

    def too_close(self, x, y, kind, s, states=None, placing=False):
        r = close0(self, x, y, kind, s, states, placing) if states is not None else close0(self, x, y, kind, s, placing=placing)
        if r and placing and kind == st["A"]:
            ps = self.pair_close
            hit = [int(self.kind[q]) for q in self.near(x, y, float(self.pair_close_max[kind]), (ELEMENT,))
                   if self.orig_of[q] != s and self.kind[q] >= 0 and (self.xy[q][0] - x) ** 2 + (self.xy[q][1] - y) ** 2 < ps[kind, self.kind[q]] ** 2]
            st["refused"][self.ref.exemplar.kinds[min(hit)] if hit else "?"] += 1
        return r

    def result(self, meta):
        st["order"] = list(self.order)
        return res0(self, meta)

    Gr.place, Gr.new_object, Gr.result, Gr.too_close_in_kind = place, new_object, result, too_close
    L._swap_one = swap_one
    mk = _harder_suite()
    name, i, v = o.row.split(":")
    ex = mk.make_exemplar(name, rng=int(v), **(HARDER[name][int(i)] if i != "suite" else {}))  # "suite": the default parameters
    A, B = ex.kinds.index(o.a), ex.kinds.index(o.b)
    st["A"] = A
    _, de = nn_to(ex, A, B, o.margin)
    thr = float(np.quantile(de, 0.95))
    x0, y0, x1, y1 = ex.region.bounds
    print(f"{o.row} nn[{o.a}>{o.b}] reference deciles {np.round(np.quantile(de, np.linspace(0.1, 0.9, 9)), 1)}, 95th percentile {thr:.1f}", flush=True)
    for seed in [int(s) for s in o.seeds.split(",")]:
        st.update(par=[], born={}, origin={}, swapping=False, swaps=collections.Counter(), refused=collections.Counter())
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        order = st["order"]
        ia, do = nn_to(out, A, B, o.margin)
        far = do > thr
        print(f" seed {seed}: n={len(out)} {'pass' if rep.faithful else 'FAIL'} {fails}")
        print(f"   output deciles {np.round(np.quantile(do, np.linspace(0.1, 0.9, 9)), 1)}; beyond {thr:.1f}: {far.mean():.3f} of {len(do)}")
        if len(order) != len(out):
            print("   (output rows differ from the growth order: origins not given)")
            continue
        org = [st["origin"].get(order[j], "?") for j in ia]
        for key in sorted(set(org)):
            m = np.array([x == key for x in org])
            print(f"   from {key:>12}: {int(m.sum()):5d} elements, {far[m].mean():.2f} beyond")
        print(f"   swaps (from, to, placed): {dict(st['swaps'])}")
        print(f"   seeds of {o.a} refused on placing, too close to: {dict(st['refused'])}", flush=True)


if __name__ == "__main__":
    main()

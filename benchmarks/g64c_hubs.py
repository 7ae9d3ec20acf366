"""Helper g64c: the hubs' growth of ``grow_clusters`` on ``--varied`` clusters p2s37 (grow, fixed): the hubs'
reference (interior hubs, their 1-rings), the hub hole radius, and hubs placed after growth and after each
void-hole refill, with their bounding box, by wrapping ``_void_holes.fill_void_holes`` (src untouched).

    PYTHONPATH=src:benchmarks python benchmarks/g64c_hubs.py clusters:p2s37 1
"""
import sys
from types import SimpleNamespace

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import strew.grow._clusters as C
import strew.grow._void_holes as VH
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run
from strew.grow._growth import ELEMENT

LOG = []
_fvh = VH.fill_void_holes


def _wrap_fvh(g, hole, **kw):
    before = int(np.sum(np.asarray(g.state)[: len(g.order)] == ELEMENT)) if len(g.order) else 0
    r = _fvh(g, hole, **kw)
    LOG.append(f"    fill_void_holes(hole={hole:.1f}) -> {r}; hubs in order {len(g.order)} (elements before {before})")
    return r


VH.fill_void_holes = _wrap_fvh
_hr = C.hub_reference


def _wrap_hr(hx):
    ref = _hr(hx)
    if ref is not None:
        inter = getattr(ref, "interior", None)
        LOG.append(f"    hub_reference: {len(hx)} hubs, interior {None if inter is None else np.flatnonzero(inter).tolist()}, attrs {[a for a in dir(ref) if not a.startswith('_')][:30]}")
    return ref


C.hub_reference = _wrap_hr
_hh = C.hub_hole


def _wrap_hh(hx, close=None):
    h = _hh(hx, close)
    LOG.append(f"    hub_hole(close={close}) = {h:.1f}")
    return h


C.hub_hole = _wrap_hh
_adv = None


def main():
    import strew.grow._growth as GR
    global _adv
    _adv = GR._Grower.advance

    def adv(self, rep, target):
        r = _adv(self, rep, target)
        st = np.asarray(self.state)[: len(self.order)]
        xy = np.asarray(self.xy)[: len(self.order)][st == ELEMENT]
        if len(xy):
            LOG.append(f"    advance: {len(xy)} hubs placed, bbox x {xy[:, 0].min():.0f}-{xy[:, 0].max():.0f} y {xy[:, 1].min():.0f}-{xy[:, 1].max():.0f}; "
                       f"x+y range {(xy[:, 0] + xy[:, 1]).min():.0f}-{(xy[:, 0] + xy[:, 1]).max():.0f}; heap {len(self.heap)}")
        return r

    GR._Grower.advance = adv
    KILL = []
    CH = {"none": 0, "pick": 0}
    _kill, _choose = GR._Grower.kill, GR._Grower.choose

    def kill(self, s):
        if getattr(self, "_g64c_hubs", False):
            KILL.append((float(self.xy[s][0]), float(self.xy[s][1]), bool(self.in_domain(*self.xy[s])), CH["last"]))
        return _kill(self, s)

    def choose(self, s):
        r = _choose(self, s)
        CH["last"] = "choose None" if r is None else "place refused"
        return r

    GR._Grower.kill = kill
    GR._Grower.choose = choose
    _begin = GR._Grower.begin

    def begin(self, start):
        self._g64c_hubs = self.p.own_kind_close and self.p.keep_close  # the hubs' grower (grow_clusters' hp)
        CH["last"] = "out of domain / other"
        return _begin(self, start)

    GR._Grower.begin = begin
    mk = fidelity_suite()
    cls, label = sys.argv[1].split(":")
    ex = exemplar(mk, cls, label)
    for seed in _variants.ints(sys.argv[2]):
        LOG.clear()
        KILL.clear()
        out, sc = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
        print(f" seed {seed}: n={len(out)} scale {sc:.2f}")
        print("\n".join(LOG))
        import collections
        k = np.array([(a, b) for a, b, _, _ in KILL])
        print(f"    hub seeds killed: {len(KILL)}; reasons {collections.Counter((d, r) for _, _, d, r in KILL)}")
        if len(k):
            sx = k[:, 0] + k[:, 1]
            print(f"    killed seeds' x+y deciles {np.percentile(sx, np.arange(0, 101, 10)).round(0)}")
        KILL.clear()


if __name__ == "__main__":
    main()

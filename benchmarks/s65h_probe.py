"""Helper s65h: kind balance of synth --harder rows (labels hIsV): the exemplar's counts, its frame
(synth's ``frame_window``, the metric's wall reach), kind density inside synth's inner frame and over the
whole domain, the metric's signed fraction / density (output minus exemplar), and per stage of
``_grow.grow`` each kind's count per area inside the output's inner frame over the exemplar's inner
density (as syn15_stages.py) and over the whole frame's.

    PYTHONPATH=src:benchmarks python benchmarks/s65h_probe.py two_sizes:h5s38[,two_sizes:h0s32] 1-2 [--stages]
"""
import sys

import numpy as np
import shapely

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew._fidelity as F
import strew.synth._displace as DP
import strew.synth._farmix as FM
import strew.synth._grow as G
import strew.synth._pebbles as PB
import strew.synth._shell as SH
import strew.synth._swap as SW
import strew.synth._thin as TH
from strew.metrics import fidelity
from strew.synth._palette import Palette
from strew.synth._prepare import prepare

BRIEF = "--brief" in sys.argv  # with --stages: only the growth line
STAGES = "--stages" in sys.argv or BRIEF
LOG = []
CAP = {}
_disc = F._discrepancies
_wr = F._wall_reach


def disc(a, b, *args, **kw):
    CAP.setdefault("ab", []).append((a, b))
    return _disc(a, b, *args, **kw)


def wr(*a):
    CAP.setdefault("reach", []).append(_wr(*a))
    return CAP["reach"][-1]


F._discrepancies = disc
F._wall_reach = wr


def whole_density(prep):
    mine = prep.selected_elements & ~prep.void & (prep.source == 0)
    S = int(prep.skind.max()) + 1
    return np.bincount(prep.skind[mine], minlength=S)[:S] / float(prep.domains[0].area)


def counts(state):
    prep = state.prep
    margin = 2.0 * float(prep.rc.max())
    inner = state.region.geometry.buffer(-margin)
    vis = np.flatnonzero(~prep.void[state.src])
    p = state.pos[vis]
    S = int(prep.skind.max()) + 1
    ins = shapely.contains_xy(inner, p[:, 0], p[:, 1])
    ci = np.bincount(prep.skind[state.src[vis[ins]]], minlength=S)[:S] / inner.area
    cw = np.bincount(prep.skind[state.src[vis]], minlength=S)[:S] / state.region.geometry.area
    return ci / DP._inner_density(prep, margin), ci / whole_density(prep), cw / whole_density(prep)


def wrap(mod, name):
    f = getattr(mod, name)

    def g(state, *a, **k):
        if name == "_complete_anchor_rings":
            LOG.append(("growth", counts(state), state.n))
        r = f(state, *a, **k)
        LOG.append((name, counts(state), state.n))
        return r

    setattr(mod, name, g)


if STAGES:
    for mod, names in ((G, ["_complete_anchor_rings", "fill_room", "fill_holes", "fill_hub_rooms", "fill_far_hub_rooms"]),
                       (DP, ["fill_displaced"]), (SH, ["fill_beside_largest", "fill_beside_far_small"]),
                       (FM, ["trade_far_small", "trade_far_top"]), (PB, ["fill_partners"]), (SW, ["fill_swapped"]),
                       (TH, ["thin_small", "thin_orphans", "thin_crowded", "thin_edge_strays"])):
        for n in names:
            if hasattr(mod, n):
                wrap(mod, n)

np.set_printoptions(precision=3, suppress=True, linewidth=200)
mk = _harder_suite()
H = _harder()
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    i, _, v = label[1:].partition("s")
    ex = mk.make_exemplar(cls, rng=int(v), **H[cls][int(i)])
    prep = prepare(Palette({"ex": ex}).select("ex"))
    S = int(prep.skind.max()) + 1
    names = [ex.kinds[int(prep.kind[prep.skind == q][0])] for q in range(S)]
    margin = 2.0 * float(prep.rc.max())
    di, dw = DP._inner_density(prep, margin), whole_density(prep)
    cnt = np.bincount(prep.skind[~prep.void], minlength=S)[:S]
    cls_ = [int(prep.size_class[prep.skind == q][0]) for q in range(S)]
    print(f"== {spec} kinds {names} counts {cnt.tolist()} size classes {cls_} rc {[round(float(prep.rc[prep.skind == q].max()), 2) for q in range(S)]}"
          f" frame_window {bool(prep.frame_window[0]) if len(prep.frame_window) else None} margin {margin:.1f}"
          f" domain area {prep.domains[0].area:.0f} inner/whole density {np.round(di / dw, 3)}", flush=True)
    for seed in _variants.ints(sys.argv[2]):
        LOG.clear()
        CAP.clear()
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        a, b = CAP["ab"][0]
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        oc = [int(np.sum(np.asarray(out.kind) == ex.kinds.index(n))) if hasattr(ex, "kinds") else 0 for n in names]
        print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} counts {oc} metric wall reach {np.round(CAP['reach'], 2)}"
              f" fraction out-ex {np.round(a.fraction[:S] - b.fraction[:S], 4)} (ex {np.round(b.fraction[:S], 4)})"
              f" density out/ex-1 {np.round(a.density[:S] / b.density[:S] - 1, 3)} {' '.join(fails)}", flush=True)
        for lab, (ri, rwi, rw), n in LOG[:1] if BRIEF else LOG:
            print(f"   {lab:22s} n={n:5d} inner/ex-inner {ri} inner/ex-whole {rwi} whole/ex-whole {rw}")

"""Helper s67h: where the larger size class's share goes between growth and the judge, on
synth rows of two size classes (labels hIsV for --harder, pIsV / vV for --varied).

Per row: the share owed_classes reads (selection's visible elements, whole frame) and its
bound (+ SHARE_MARGIN se), the judge's counted share of the exemplar (minus sampling
beyond its wall reach). Per seed and stage of synth's passes: the output's share of each
class over the whole output (what owed_classes reads) and inside the inner frame, and
finally the judge's counted share and signed density.

    PYTHONPATH=src:benchmarks python benchmarks/s67h_probe.py two_sizes:h5s38,two_sizes:p3s31 1-2 [--stages]
"""
import sys

import numpy as np
import shapely

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
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

STAGES = "--stages" in sys.argv
LOG = []
CAP = {}
_disc = F._discrepancies


def disc(a, b, *args, **kw):
    CAP.setdefault("ab", []).append((a, b))
    return _disc(a, b, *args, **kw)


F._discrepancies = disc


def shares(state):
    """Larger class's share: whole output (owed_classes' reading) and inside 2 rc_max."""
    prep = state.prep
    sel = prep.selected_elements & ~prep.void
    src = state.src
    keep = sel[src]
    cls = prep.size_class[src[keep]]
    p = state.pos[keep]
    inner = state.region.geometry.buffer(-2.0 * float(prep.rc.max()))
    ins = shapely.contains_xy(inner, p[:, 0], p[:, 1])
    top = cls.max() if len(cls) else 0
    return float(np.mean(cls == top)), float(np.mean(cls[ins] == top)), int(np.sum(cls == top)), len(cls)


def wrap(mod, name):
    f = getattr(mod, name)

    def g(state, *a, **k):
        if name == "_complete_anchor_rings":
            LOG.append(("growth", shares(state)))
        r = f(state, *a, **k)
        LOG.append((name, shares(state)))
        return r

    setattr(mod, name, g)


for mod, names in ((G, ["_complete_anchor_rings", "fill_room", "fill_holes", "fill_hub_rooms", "fill_far_hub_rooms"]),
                   (DP, ["fill_displaced"]), (SH, ["fill_beside_largest", "fill_beside_far_small"]),
                   (FM, ["trade_far_small", "trade_far_top"]), (PB, ["fill_partners"]), (SW, ["fill_swapped"]),
                   (TH, ["thin_small", "thin_orphans", "thin_crowded", "thin_edge_strays"])):
    for n in names:
        if hasattr(mod, n):
            wrap(mod, n)


def exemplar(cls, label):
    i, _, v = label[1:].partition("s")
    if label.startswith("h"):
        return _harder_suite().make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    mk = fidelity_suite()
    if label.startswith("v"):
        return mk.make_exemplar(cls, rng=int(label[1:]))
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    return mk.make_exemplar(cls, rng=int(v), **sets[int(i)])


np.set_printoptions(precision=3, suppress=True, linewidth=200)
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(cls, label)
    prep = prepare(Palette({"ex": ex}).select("ex"))
    sel = prep.selected_elements & ~prep.void
    ncls = int(prep.size_class.max()) + 1
    top = ncls - 1
    n = int(sel.sum())
    p = float(np.mean(prep.size_class[sel] == top))
    se = np.sqrt(p * (1 - p) / n)
    topkinds = sorted({ex.kinds[int(k)] for k in prep.kind[sel & (prep.size_class == top)]})
    print(f"== {spec} classes {ncls} top {topkinds} n_top {int(np.sum(prep.size_class[sel] == top))} n {n}"
          f" frame_window {bool(prep.frame_window[0])} p {p:.3f} se {se:.4f} bound {p + G.SHARE_MARGIN * se:.3f} (2se/p {G.SHARE_MARGIN * se / p:.2f})", flush=True)
    for seed in _variants.ints(sys.argv[2]):
        LOG.clear()
        CAP.clear()
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        a, b = CAP["ab"][0]
        ti = [ex.kinds.index(k) for k in topkinds]
        exc = float(np.sum(b.fraction[ti]))
        outc = float(np.sum(a.fraction[ti]))
        dens = {k: round(float(a.density[ex.kinds.index(k)] / b.density[ex.kinds.index(k)] - 1), 3) for k in ex.kinds if ex.kinds.index(k) < len(b.density)}
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        g = LOG[0][1] if LOG else (np.nan, np.nan, 0, 0)
        fin = LOG[-1][1] if LOG else (np.nan, np.nan, 0, 0)
        print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} judge ex share {exc:.3f} out {outc:.3f}"
              f" | growth whole {g[0]:.3f} inner {g[1]:.3f} ({(g[0] - p) / se:+.2f} se) | last pass whole {fin[0]:.3f} inner {fin[1]:.3f}"
              f" | judge out-ex {outc - exc:+.3f} ex_judge-p {exc - p:+.3f} dens {dens} {' '.join(fails)}", flush=True)
        if STAGES:
            for lab, s in LOG:
                print(f"   {lab:22s} whole {s[0]:.3f} inner {s[1]:.3f} top {s[2]} n {s[3]}")

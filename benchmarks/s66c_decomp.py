"""Helper s66c: decomposition of g[disc,dot] of clusters rows for the exemplar, synth's output and the
exemplar's own generator drawn at the output's size (svar13i_oracle.big_params, layout seed V + 1000 (d + 1)).
Per arrangement: window area, n/|W| and cell density per kind, discs inside the window, raw (disc, dot) pairs
per window disc in the bins r/s 1.2-1.4 and 1.4-1.6 (both ends in the window), dots per disc ring (dots within 25
of their nearest disc), dots in the window not on any ring, and g[disc,dot] at those two bins. src untouched.

    PYTHONPATH=src:benchmarks python benchmarks/s66c_decomp.py clusters:p4s39 1,2 [--big 2] [--no-synth]
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from svar13i_oracle import big_params
from synth_variants import run

import strew._fidelity as F
from strew.metrics import fidelity

if "--hub-gap" in sys.argv or "--ring-cv" in sys.argv:
    import s66c_cf  # noqa: F401  (the counterfactual of fill_holes, s66c_cf.py)

CAP = []
_orig = F._discrepancies


def _wrap(a, b, kinds, s, **kw):
    CAP.append((a, b))
    return _orig(a, b, kinds, s, **kw)


F._discrepancies = _wrap
WIN = []
_ow = F._stats


def _sw(sm, raw, K, s, window, **kw):
    WIN.append(window)
    return _ow(sm, raw, K, s, window, **kw)


F._stats = _sw


def decomp(arr, st, window, s, tag, g):
    window = next((w for w in WIN if abs(w.area - st.area) < 1e-6 * st.area), window)  # the window of these stats
    P = np.c_[arr.x, arr.y]
    kind = np.asarray(arr.kind)
    ins = shapely.contains_xy(window, P[:, 0], P[:, 1])
    disc = P[(kind == 0) & ins]
    td = cKDTree(P[kind == 1])
    lo, mid, hi = 1.2 * s, 1.4 * s, 1.6 * s
    a = np.array([len(x) for x in td.query_ball_point(disc, mid)]) - np.array([len(x) for x in td.query_ball_point(disc, lo)])
    b = np.array([len(x) for x in td.query_ball_point(disc, hi)]) - np.array([len(x) for x in td.query_ball_point(disc, mid)])
    d, j = cKDTree(P[kind == 0]).query(P[kind == 1])
    per = np.bincount(j[d < 25.0], minlength=int(np.sum(kind == 0)))
    ringd = d[d < 25.0]
    lam = st.counts[:2] / st.area
    print(f"  {tag}: window {st.area:.0f} n(disc,dot) in W {st.counts[:2]} lambda {lam[0]:.3e} {lam[1]:.3e} cell density {st.density[0]:.3e} {st.density[1]:.3e}"
          f" lambda/cell {lam[0] / st.density[0]:.3f} {lam[1] / st.density[1]:.3f}")
    print(f"    dots per W-disc in r/s [1.2,1.4) {a.mean():.3f} [1.4,1.6) {b.mean():.3f} (hist {np.bincount(a).tolist()}); dots per W-dot-area: {st.counts[1] / st.counts[0]:.3f} dots per disc in W;"
          f" ring dots/all dots {np.mean(d < 25.0):.3f}; ring radius p5/50/95 {np.percentile(ringd, [5, 50, 95]).round(2)}; frac ring dots beyond r/s 1.4 {np.mean(ringd >= mid):.3f}")
    print(f"    rings (all discs) hist {np.bincount(per).tolist()} mean {per.mean():.2f}; g[disc,dot] bins 1.3/1.5 {g[6]:.2f} {g[7]:.2f};"
          f" predicted g13 = a/(lambda_dot ring) = {a.mean() / lam[1] / (np.pi * (mid ** 2 - lo ** 2)):.2f}")


def main():
    np.set_printoptions(precision=3, suppress=True, linewidth=220)
    mk = fidelity_suite()
    cls, label = sys.argv[1].split(":")
    ex = exemplar(mk, cls, label)
    nbig = int(sys.argv[sys.argv.index("--big") + 1]) if "--big" in sys.argv else 0
    outs = []
    if "--no-synth" not in sys.argv:
        outs += [(f"synth s{seed}", run(ex, 3.5, seed, None)[0]) for seed in _variants.ints(sys.argv[2])]
    if nbig:
        i, _, v = label[1:].partition("s")
        kw = (_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)]
        bp = big_params(cls, kw, 3.5)
        outs += [(f"generator d{d}", mk.make_exemplar(cls, rng=int(v) + 1000 * (d + 1), **bp)) for d in range(nbig)]
    first = True
    for tag, out in outs:
        CAP.clear()
        WIN.clear()
        rep = fidelity(ex, out, eq5=False, local=False)
        a, b = CAP[0]
        if first:
            decomp(ex, b, WIN[1], rep.s, "exemplar", rep.g_exemplar["disc,dot"])
            first = False
        m = rep.metrics["g[disc,dot]"]
        print(f" {tag}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} g[disc,dot]={m.value:.3f}/{m.tolerance:.3f} fails {rep.failures}")
        decomp(out, a, WIN[0], rep.s, tag, rep.g_result["disc,dot"])


if __name__ == "__main__":
    main()

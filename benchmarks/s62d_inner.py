"""Helper s62d: for --harder rows of synth (labels hIsV), the exemplar's kind counts inside synth's inner
frame (margin two of the largest collision radii, ``_displace._inner_density``) against its whole frame, the
target density that gives (inner) against the whole frame's, and synth's result at one seed: the metric's
density ratio out/ex (signed) and nn[stone>pebble] with the sign of its mean decile error.

    PYTHONPATH=src:benchmarks python benchmarks/s62d_inner.py two_sizes 8,9 25-34,36 1
"""
import sys
import numpy as np
import shapely
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import strew._fidelity as F
import strew.synth._displace as DP
from grow_variants import _harder_suite
from synth_variants import _harder, run
from strew.metrics import fidelity

CAP, DIS = [], []
_orig, _od = DP._inner_density, F._discrepancies


def _wrap(prep, margin):
    out = _orig(prep, margin)
    if not CAP:
        s = int(np.flatnonzero(prep.selected)[0])
        dom = prep.domains[s]
        inner = dom.buffer(-margin)
        sel = prep.selected_elements & ~prep.void & (prep.source == s)
        ids = np.flatnonzero(sel)
        ins = shapely.contains_xy(inner, prep.pos[ids, 0], prep.pos[ids, 1])
        S = len(out)
        n_all = np.bincount(prep.skind[ids], minlength=S)
        n_in = np.bincount(prep.skind[ids[ins]], minlength=S)
        p = inner.area / dom.area
        CAP.append((n_all, n_in, p, out, n_all / dom.area, margin))
    return out


def _wd(a, b, kinds, s, **kw):
    DIS.append((a, b, s))
    return _od(a, b, kinds, s, **kw)


DP._inner_density = _wrap
F._discrepancies = _wd
mk = _harder_suite()
H = _harder()
cls = sys.argv[1]
for h in _variants.ints(sys.argv[2]):
    for v in _variants.ints(sys.argv[3]):
        ex = mk.make_exemplar(cls, rng=v, **H[cls][h])
        for seed in _variants.ints(sys.argv[4]):
            CAP.clear(); DIS.clear()
            out, _ = run(ex, 3.5, seed, None)
            rep = fidelity(ex, out, eq5=False, local=False)
            a, b, s = DIS[0]
            n_all, n_in, p, dens, whole, margin = CAP[0]
            kinds = list(ex.kinds)
            m = rep.metrics["nn[stone>pebble]"]
            sgn = np.mean((a.nn[0, 1] - b.nn[0, 1]) / s) if kinds == ["stone", "pebble"] else float("nan")
            dp = a.density[1] / b.density[1]
            ds = a.density[0] / b.density[0]
            # inner/whole for the pebbles, and its binomial z (n_in against p * n_all)
            z = (n_in[1] - p * n_all[1]) / np.sqrt(max(n_all[1] * p * (1 - p), 1e-9))
            zs = (n_in[0] - p * n_all[0]) / np.sqrt(max(n_all[0] * p * (1 - p), 1e-9))
            print(f"h{h}s{v} seed {seed}: {'pass' if rep.faithful else 'FAIL'} ex stone {n_in[0]}/{n_all[0]} (z {zs:+.1f}) pebble {n_in[1]}/{n_all[1]} (z {z:+.1f}) inside/all, frame share p={p:.2f}; "
                  f"inner/whole density stone {dens[0] / whole[0]:.2f} pebble {dens[1] / whole[1]:.2f} | out/ex density stone {ds:.3f} pebble {dp:.3f} ({rep.metrics['density[pebble]'].tolerance:.3f}) "
                  f"nn[s>p] {m.value:.3f}/{m.tolerance:.3f} mean signed {sgn:+.3f}", flush=True)
            me = [rep.metrics[f"density[{k}]"].exemplar for k in kinds]
            print(f"    metric's exemplar density / synth's inner target: stone {me[0] / dens[0]:.3f} pebble {me[1] / dens[1]:.3f}; / whole-frame count: stone {me[0] / whole[0]:.3f} pebble {me[1] / whole[1]:.3f}", flush=True)

"""Helper s70t counterfactual (probe, src untouched): ``_displace._inner_density`` with the LARGEST size class
capped at its whole-frame count per area where its inner frame holds more than its area share of the class by
more than SE binomial standard errors (the mirror of MIDDLE_WHOLE for the largest class: a count-limited class
thrown first whose centres keep off the frame crowds the inner frame). Logs where the cap acts.

    PYTHONPATH=src:benchmarks python benchmarks/s70t_topcap.py SE three_sizes:11:44:1,2,3 [...]   (SE=inf: main)
"""
import sys

import numpy as np
import shapely

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from syn13z_rows import counts, nnq
from synth_variants import _harder, run

import strew.synth._displace as DP
from strew.metrics import fidelity

SE = float(sys.argv[1])
_orig = DP._inner_density
ACT = []


def capped(prep, margin):
    out = _orig(prep, margin)
    S = len(out)
    sel = prep.selected_elements & ~prep.void
    for s, dom in enumerate(prep.domains):
        if not prep.selected[s]:
            continue
        inner = dom.buffer(-margin)
        if inner.is_empty or inner.area <= 0.25 * dom.area:
            continue
        mine = sel & (prep.source == s)
        top = np.unique(prep.skind[mine & (prep.size_class == prep.size_class[mine].max())])
        ids = np.flatnonzero(mine)
        ids = ids[shapely.contains_xy(inner, prep.pos[ids, 0], prep.pos[ids, 1])]
        n_all = np.bincount(prep.skind[mine], minlength=S)[top].astype(float)
        n_in = np.bincount(prep.skind[ids], minlength=S)[top].astype(float)
        p = float(inner.area) / float(dom.area)
        over = n_in > p * n_all + SE * np.sqrt(n_all * p * (1.0 - p))
        if over.any():
            ACT.append(1)
        out[top] = np.where(over, np.minimum(out[top], n_all / float(dom.area)), out[top])
    return out


DP._inner_density = capped
mk = _harder_suite()
for spec in sys.argv[2:]:
    cls, h, v, seeds = spec.split(":")
    ex = mk.make_exemplar(cls, rng=int(v), **_harder()[cls][int(h)])
    for s in [int(x) for x in seeds.split(",")]:
        ACT.clear()
        out, _ = run(ex, 3.5, s, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        key = "nn[medium>medium]"
        m = rep.metrics.get(key)
        mm = f"{m.value:.3f}/{m.tolerance:.3f}" if m is not None else "-"
        print(f"SE={SE} {cls} h{h}s{v} seed {s}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} cap_acted={bool(ACT)} nn[m>m] {mm} {' '.join(fails)}"
              f" inner20 {counts(out, 20)}", flush=True)

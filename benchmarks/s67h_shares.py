"""Helper s67h: prepare only. For two-class synth rows: the larger class's share that
owed_classes reads (p, whole frame), its share inside the inner frame (domain shrunk by
2 rc_max, as _displace._inner_density counts; p_in), the judge's counted share (minus
sampling beyond its wall reach; p_j), se, se_in (of p_in, over the inner frame's count),
and the bounds p + 2 se, p_in + 1 se and p_in + 1 se_in.

    PYTHONPATH=src:benchmarks python benchmarks/s67h_shares.py two_sizes:h5s38,two_sizes:p3s31,two_sizes:v1
"""
import sys

import numpy as np
import shapely

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from s67h_probe_ex import exemplar

import strew._fidelity as F
from strew.metrics import fidelity
from strew.synth._palette import Palette
from strew.synth._prepare import prepare

CAP = []
_disc = F._discrepancies


def disc(a, b, *args, **kw):
    CAP.append(b)
    return _disc(a, b, *args, **kw)


F._discrepancies = disc

for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(cls, label)
    prep = prepare(Palette({"ex": ex}).select("ex"))
    sel = prep.selected_elements & ~prep.void
    ncls = int(prep.size_class.max()) + 1
    if ncls != 2:
        print(f"{spec:22s} classes {ncls}")
        continue
    top = sel & (prep.size_class == 1)
    n = int(sel.sum())
    p = top.sum() / n
    se = np.sqrt(p * (1 - p) / n)
    inner = prep.domains[0].buffer(-2.0 * float(prep.rc.max()))
    ins = sel & shapely.contains_xy(inner, prep.pos[:, 0], prep.pos[:, 1])
    p_in = (ins & top).sum() / max(ins.sum(), 1)
    se_in = np.sqrt(p_in * (1 - p_in) / max(ins.sum(), 1))
    CAP.clear()
    fidelity(ex, ex, eq5=False, local=False)
    b = CAP[0]
    tk = sorted({int(k) for k in prep.kind[top]})
    p_j = float(np.sum(b.fraction[tk]))
    print(f"{spec:22s} wall {not bool(prep.frame_window[0])} n {n} n_in {int(ins.sum())} top {int(top.sum())} p {p:.3f} p_in {p_in:.3f} p_j {p_j:.3f}"
          f" se {se:.4f} (p_in-p)/se {(p_in - p) / se:+.2f} (p_j-p)/se {(p_j - p) / se:+.2f} 2se/p {2 * se / p:.2f}"
          f" bound_main {p + 2 * se:.3f} p_in+1se {p_in + se:.3f} se_in {se_in:.4f} p_in+1se_in {p_in + se_in:.3f} (p_in+se_in)-(p+2se) {p_in + se_in - p - 2 * se:+.3f}", flush=True)

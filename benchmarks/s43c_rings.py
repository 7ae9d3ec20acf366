"""Helper s43c: ring sizes (dots a disc by nearest disc), strays > 22 from any disc, dot-dot nn quantiles, nn[dot>dot].

    PYTHONPATH=src:benchmarks python benchmarks/s43c_rings.py p2s29 1,2
"""
import sys; sys.path.insert(0,'benchmarks')
import numpy as np
from scipy.spatial import cKDTree
from fresh17_rows import exemplar
from _runner import fidelity_suite
from synth_variants import run
from strew.metrics import fidelity
import strew
ex = exemplar(fidelity_suite(), "clusters", sys.argv[1])
def st(a, tag):
    k = np.asarray(a.kind_names); d = a.xy[k=="disc"]; t = a.xy[k=="dot"]
    dd, j = cKDTree(d).query(t)
    per = np.bincount(j, minlength=len(d))
    nd = cKDTree(t).query(t, k=2)[0][:,1]
    print(f" {tag}: discs {len(d)} dots {len(t)} dots/disc {len(t)/len(d):.2f} ring sizes {np.bincount(per)[3:10].tolist()} (3..9) strays>22 {(dd>22).sum()} dot-dot nn q10/50/90 {np.quantile(nd,[.1,.5,.9]).round(2).tolist()}")
st(ex, "exemplar")
for s in sys.argv[2].split(","):
    out,_ = run(ex, 3.5, int(s), None)
    st(out, f"seed {s}")
    rep = fidelity(ex, out, eq5=False, local=False); m = rep.metrics.get("nn[dot>dot]")
    print("   ", "pass" if rep.faithful else "FAIL", f"nn[dot>dot]={m.value:.3g}/{m.tolerance:.3g}" if m else "", strew.__file__)

"""Helper s43c: discs placed by growth and by fill_holes, their final ring sizes and their exemplar source's ring size.

    PYTHONPATH=src:benchmarks python benchmarks/s43c_fill_holes_discs.py p2s29 1
"""
import sys; sys.path.insert(0,'benchmarks')
import numpy as np
from scipy.spatial import cKDTree
from fresh17_rows import exemplar
from _runner import fidelity_suite
from synth_variants import run
import strew.synth._grow as G
ex = exemplar(fidelity_suite(), "clusters", sys.argv[1])
rec = {}
f = G.fill_holes
def w(state, *a, **k):
    n0 = state.n; r = f(state, *a, **k); rec.setdefault("fh", []).append((n0, state.n)); rec["state"] = state; return r
G.fill_holes = w
out,_ = run(ex, 3.5, int(sys.argv[2]), None)
st = rec["state"]; n = st.n
prep = st.prep
kind = prep.kind[st.src[:n]]; pos = st.pos[:n]
disc = np.flatnonzero(kind == 0); dot = np.flatnonzero(kind == 1)
j = cKDTree(pos[disc]).query(pos[dot])[1]
per = np.bincount(j, minlength=len(disc))
fh = np.zeros(n, bool)
for a, b in rec["fh"]: fh[a:b] = True
# exemplar ring size of each output disc's source
edisc = np.flatnonzero(prep.kind == 0); edot = np.flatnonzero(prep.kind == 1)
ej = cKDTree(prep.pos[edisc]).query(prep.pos[edot])[1]; eper = dict(zip(edisc, np.bincount(ej, minlength=len(edisc))))
for tag, m in (("growth", ~fh[disc]), ("fill_holes", fh[disc])):
    print(f"{tag}: discs {m.sum()} ring sizes (final) {np.bincount(per[m], minlength=10)[3:10].tolist()} source ring sizes {np.bincount([eper[s] for s in st.src[disc[m]]], minlength=10)[3:10].tolist()}")

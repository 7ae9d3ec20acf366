"""Helper s67h: trace of _grow.owed_classes during growth (calls, the larger class's
output share at each call, whether it is owed), per row and seed; with --main-bound the
branch's rule is switched off (TWO_CLASS_INNER False: main's bound).

    PYTHONPATH=src:benchmarks python benchmarks/s67h_owed_trace.py two_sizes:p3s31 1,2 [--main-bound]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from s67h_probe_ex import exemplar
from synth_variants import run

import strew.synth._grow as G

if "--main-bound" in sys.argv and hasattr(G, "TWO_CLASS_INNER"):
    G.TWO_CLASS_INNER = False
TR = []
_owed = G.owed_classes


def owed(state):
    r = _owed(state)
    prep = state.prep
    sel = prep.selected_elements & ~prep.void
    src = state.src[sel[state.src]]
    settled = sel[state.src] & ~np.asarray(state.horizon[: state.n], bool)
    ss = prep.size_class[state.src[settled]] == prep.size_class.max()
    TR.append((len(src), float(np.mean(prep.size_class[src] == prep.size_class.max())), bool(r[-1]), float(np.mean(ss)) if len(ss) else np.nan))
    return r


G.owed_classes = owed
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(cls, label)
    for seed in _variants.ints(sys.argv[2]):
        TR.clear()
        out, _ = run(ex, 3.5, seed, None)
        t = np.array(TR)
        k = len(t)
        idx = np.unique(np.linspace(0, k - 1, 16).astype(int))
        owed_frac = float(np.mean(t[:, 2])) if k else np.nan
        print(f"{spec} seed {seed}: calls {k} owed in {owed_frac:.2f} of calls; n/share/owed/settled share (not on the horizon) at 16 points:")
        print("   " + " ".join(f"{int(t[i, 0])}/{t[i, 1]:.3f}/{'o' if t[i, 2] else '-'}/{t[i, 3]:.3f}" for i in idx), flush=True)

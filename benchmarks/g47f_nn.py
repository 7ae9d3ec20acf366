"""Helper g47f: signed nearest-neighbour decile errors (result - exemplar, in units of the
exemplar's median nn spacing s) for one kind pair, grow against the generator ("oracle":
the same class drawn 3.5x larger, ``svar13i_oracle.big_params``), over --varied draws.

    PYTHONPATH=src:benchmarks python benchmarks/g47f_nn.py two_sizes:p2 7-32 [SEEDS=1] [--no-oracle]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from types import SimpleNamespace

import _variants
import numpy as np
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run
from svar13i_oracle import big_params

import strew
from strew import _fidelity as F
from strew.metrics import fidelity

CAP = {}
_d = F._discrepancies


def _disc(a, b, kinds, s, **k):
    if "a" not in CAP:  # the first call: the result against the exemplar
        CAP["a"], CAP["b"], CAP["s"], CAP["kinds"] = a, b, s, kinds
    return _d(a, b, kinds, s, **k)


F._discrepancies = _disc
if os.environ.get("OWN_TAIL_Q") == "none":  # main's rule (the median's excess)
    from strew.grow import _growth as G

    G.OWN_TAIL_Q = None
PAIR = os.environ.get("PAIR", "stone>stone")


def signed(ex, out):
    CAP.clear()
    rep = fidelity(ex, out, eq5=False, local=False)
    a, b, s, kinds = CAP["a"], CAP["b"], CAP["s"], CAP["kinds"]
    i, j = (kinds.index(x) for x in PAIR.split(">"))
    d = (a.nn[i, j] - b.nn[i, j]) / s
    m = rep.metrics.get(f"nn[{PAIR}]")
    fr = {k: rep.metrics[k].value for k in rep.metrics if k.startswith("density")}
    return rep, d, m, fr


def main():
    cls, lab = sys.argv[1].split(":")
    vs = _variants.ints(sys.argv[2])
    seeds = _variants.ints(os.environ.get("SEEDS", "1"))
    oracle = "--no-oracle" not in sys.argv
    mk = fidelity_suite()
    args = SimpleNamespace(mode="fixed", times=10.0)
    G, O = [], []
    for v in vs:
        label = f"{lab}s{v}" if lab.startswith("p") else f"v{v}"
        ex = exemplar(mk, cls, label)
        for seed in seeds:
            out, _ = run(ex, 3.5, seed, args)
            rep, d, m, fr = signed(ex, out)
            G.append(d)
            print(f"{cls}:{label} grow seed {seed} {'pass' if rep.faithful else 'FAIL'} n={len(out)} nn={m.value:.3f}/{m.tolerance:.3f} signed mean {np.mean(d):+.3f} deciles {np.array2string(d, precision=2, suppress_small=True)} dens {', '.join(f'{k}={x:.3f}' for k, x in fr.items())}", flush=True)
        if oracle:
            kw = dict(ex.params) if getattr(ex, "params", None) else None
            i, _, vv = label[1:].partition("s")
            sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
            kw = dict(sets[int(i)]) if label.startswith("p") else {}
            big = mk.make_exemplar(cls, rng=int(vv) if label.startswith("p") else int(label[1:]), **big_params(cls, kw, 3.5))
            rep, d, m, fr = signed(ex, big)
            O.append(d)
            print(f"{cls}:{label} ORACLE {'pass' if rep.faithful else 'FAIL'} n={len(big)} nn={m.value:.3f}/{m.tolerance:.3f} signed mean {np.mean(d):+.3f} deciles {np.array2string(d, precision=2, suppress_small=True)}", flush=True)
    G = np.array(G)
    print(f"grow   mean signed deciles over {len(G)}: {np.array2string(np.nanmean(G, 0), precision=3)}  mean {np.nanmean(G):+.4f}")
    if O:
        O = np.array(O)
        print(f"oracle mean signed deciles over {len(O)}: {np.array2string(np.nanmean(O, 0), precision=3)}  mean {np.nanmean(O):+.4f}")
    print(strew.__file__)


if __name__ == "__main__":
    main()

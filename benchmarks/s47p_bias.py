"""Helper s47p: signed nn[A>B] decile error of synth against the exemplar, beside the
generator drawn at the output's size (svar13i's oracle), over many variant seeds of one
--varied set (in units of the exemplar's median nn, s; mean over the deciles, and per decile).

    PYTHONPATH=src:benchmarks python benchmarks/s47p_bias.py CLASS:SET VSEEDS [--seed 1] [--pairs small>small]
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from svar13i_oracle import big_params
from synth_variants import run

from strew import _fidelity
from strew.metrics import fidelity

got = []
_orig = _fidelity._stats


def _keep(*a, **k):
    st = _orig(*a, **k)
    got.append(st)
    return st


_fidelity._stats = _keep


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("spec")
    ap.add_argument("vseeds")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--pairs", default="small>small")
    ap.add_argument("--no-oracle", action="store_true")
    a = ap.parse_args()
    cls, _, setno = a.spec.partition(":")
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    kw = dict(sets[int(setno[1:])]) if setno else {}
    mk = fidelity_suite()
    pairs = a.pairs.split(",")
    acc = {p: {"out": [], "orc": []} for p in pairs}
    for v in _variants.ints(a.vseeds):
        ex = mk.make_exemplar(cls, rng=v, **kw)
        s = _fidelity._median_nn(ex.xy)
        kinds = [k for i, k in enumerate(ex.kinds) if np.any(ex.kind == i)]
        res = {}
        got.clear()
        out, _ = run(ex, 3.5, a.seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        res["out"] = (rep, got[0], got[1], len(out))
        if not a.no_oracle:
            big = big_params(cls, kw, 3.5)
            got.clear()
            arr = mk.make_exemplar(cls, rng=v, **big)
            rep2 = fidelity(ex, arr, eq5=False, local=False)
            res["orc"] = (rep2, got[0], got[1], len(arr))
        line = [f"{cls}:{setno}s{v}"]
        for p in pairs:
            ka, kb = p.split(">")
            i, j = kinds.index(ka), kinds.index(kb)
            for who, (rep_, es, rs, n) in res.items():
                m = rep_.metrics[f"nn[{p}]"]
                d = (np.asarray(rs.nn[i, j]) - np.asarray(es.nn[i, j])) / s
                acc[p][who].append(d)
                line.append(f"{who} nn[{p}] {m.value:.3f}/{m.tolerance:.3f} {'ok' if m.passed else 'X'} signed {d.mean():+.3f} [{' '.join(f'{x:+.2f}' for x in d)}] faithful={rep_.faithful} n={n}")
        print("\n   ".join(line), flush=True)
    for p in pairs:
        for who, ds in acc[p].items():
            if not ds:
                continue
            D = np.array(ds)
            print(f"{p} {who}: mean signed {D.mean():+.4f} (per draw > 0: {(D.mean(1) > 0).sum()}/{len(D)}); per decile " + " ".join(f"{x:+.3f}" for x in D.mean(0)), flush=True)


if __name__ == "__main__":
    main()

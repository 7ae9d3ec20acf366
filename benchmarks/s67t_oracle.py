"""Helper s67t: the exemplar of a --harder row, its own generator drawn 3.5x larger (svar13i's oracle,
variant seed + 1000 d) and synth's output, side by side: per-kind count per 1e4 inside the frame less
``margin`` (the exemplar and the output alike), the whole frame's, the judge's density / fraction and
nn[a>a] values, and nn[a>a] deciles (syn13z_rows.nnq).

    PYTHONPATH=src:benchmarks python benchmarks/s67t_oracle.py three_sizes:h8s41 [--draws 2] [--synth 1,2] [--kind small]
"""
import sys

import numpy as np
import shapely

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from syn13z_rows import nnq
from synth_variants import _harder, run

import strew._fidelity as F
from strew.metrics import fidelity

CAP = []
_disc = F._discrepancies


def disc(a, b, *args, **kw):
    CAP.append((a, b))
    return _disc(a, b, *args, **kw)


F._discrepancies = disc


def per1e4(arr, margin):
    g = arr.region.geometry.buffer(-margin)
    xy = np.asarray(arr.xy)
    kn = np.asarray(arr.kind_names)
    ins = shapely.contains_xy(g, xy[:, 0], xy[:, 1])
    return {k: round(float(np.sum(ins & (kn == k)) / g.area * 1e4), 2) for k in sorted(set(kn))}


def line(tag, ex, arr, kind, margin):
    CAP.clear()
    rep = fidelity(ex, arr, eq5=False, local=False)
    a, b = CAP[0]
    S = len(a.density)
    m = rep.metrics[f"nn[{kind}>{kind}]"]
    fails = [f"{k}={x.value:.3g}/{x.tolerance:.3g}" for k, x in rep.metrics.items() if x.applicable and not x.passed]
    dec = nnq(arr, kind, kind)
    print(f"  {tag:14s} {'pass' if rep.faithful else 'FAIL'} n={len(arr)} inner({margin}) {per1e4(arr, margin)} whole {per1e4(arr, 0)}"
          f" judge density out/ex-1 {np.round(a.density[:S] / b.density[:S] - 1, 3)} fraction out {np.round(a.fraction[:S], 4)} ex {np.round(b.fraction[:S], 4)}"
          f" nn[{kind}>{kind}] {m.value:.4f}/{m.tolerance:.4f} deciles {np.round(dec, 2)} {' '.join(fails)}", flush=True)
    return dec


def main():
    spec = sys.argv[1]
    draws = int(sys.argv[sys.argv.index("--draws") + 1]) if "--draws" in sys.argv else 2
    seeds = [int(x) for x in sys.argv[sys.argv.index("--synth") + 1].split(",")] if "--synth" in sys.argv else []
    kind = sys.argv[sys.argv.index("--kind") + 1] if "--kind" in sys.argv else "small"
    margin = 26.8
    cls, label = spec.split(":")
    i, _, v = label[1:].partition("s")
    mk = _harder_suite()
    kw = _harder()[cls][int(i)]
    ex = mk.make_exemplar(cls, rng=int(v), **kw)
    print(f"== {spec} params {kw} exemplar n={len(ex)} inner({margin}) {per1e4(ex, margin)} whole {per1e4(ex, 0)}"
          f" nn[{kind}>{kind}] deciles {np.round(nnq(ex, kind, kind), 2)}", flush=True)
    big = big_params(cls, kw, 3.5)
    for d in range(draws):
        arr = mk.make_exemplar(cls, rng=int(v) + 1000 * d, **big)
        line(f"oracle d{d}", ex, arr, kind, margin)
    for s in seeds:
        out, _ = run(ex, 3.5, s, None)
        line(f"synth seed {s}", ex, out, kind, margin)


if __name__ == "__main__":
    main()

"""Helper syn18 (issue 13 point 1): is a --harder exemplar's nn unusual for its own generator?

The generator drawn at the output size (3.5x side, counts x 12.25: svar13i_oracle.big_params), with the
exemplar's very outlines (the shape draws come from the exemplar's variant seed; the layout from
another seed), judged against the exemplar as synth's output is; and the exemplar's nn deciles set
against the big draws' (in units of the exemplar's s).

    PYTHONPATH=TREE/src python benchmarks/syn18_oracle.py CLASS:H:V A>B [--draws 8]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from syn13z_rows import nnq
from synth_variants import _harder

from strew.metrics import fidelity

args = [a for a in sys.argv[1:] if not a.startswith("--")]
draws = int(sys.argv[sys.argv.index("--draws") + 1]) if "--draws" in sys.argv else 8
args = [a for a in args if a != str(draws)]
name, i, v = args[0].split(":")
a, b = args[1].split(">")
kw = _harder()[name][int(i)]
mk = _harder_suite()
ex = mk.make_exemplar(name, rng=int(v), **kw)
bp = big_params(name, kw, 3.5)
orig = mk._stone
kn = np.asarray(ex.kind_names)
print("exemplar", {k: int((kn == k).sum()) for k in sorted(set(kn))})
fails = 0
vals = []
for d in range(draws):
    sg = np.random.default_rng(int(v))  # the exemplar's shape stream: its outlines, exactly
    mk._stone = lambda g, *x, **y: orig(sg, *x, **y)
    try:
        big = mk.make_exemplar(name, rng=int(v) + 1000 * (d + 1), **bp)
    finally:
        mk._stone = orig
    rep = fidelity(ex, big, eq5=False, local=False)
    key = f"nn[{a}>{b}]"
    m = rep.metrics[key]
    vals.append(m.value)
    fails += not rep.faithful
    bk = np.asarray(big.kind_names)
    print(f"draw {d}", {k: int((bk == k).sum()) for k in sorted(set(bk))}, "pass" if rep.faithful else "FAIL",
          [f"{k}={rep.metrics[k].value:.3f}/{rep.metrics[k].tolerance:.3f}" for k in rep.failures],
          f"{key}={m.value:.4f}/{m.tolerance:.4f} dec(draw-ex)/s {np.round((nnq(big, a, b) - nnq(ex, a, b)) / rep.s, 2)}", flush=True)
print(f"{args[0]} {key}: {draws - fails}/{draws} draws faithful; nn value mean {np.mean(vals):.4f} (tolerance {m.tolerance:.4f})")

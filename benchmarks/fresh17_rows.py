"""Helper fresh17: chosen ``--varied`` rows (any variant seed) at more seeds, grow or synth (``SHOW=metric,...`` also prints those metrics where they pass; helper g45f).

    PYTHONPATH=src python benchmarks/fresh17_rows.py METHOD CLASS:LABEL[,CLASS:LABEL...] 1-6

METHOD is grow, grow-rotate or synth; LABEL is ``v9`` (default parameters, variant seed
9) or ``p2s10`` (set 2 of ``VARIED`` + ``EDGE`` in ``_variants.py``, variant seed 10), as
``--varied --varied-variants`` labels them. Judged as the audit (eq5 and local off).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite

import strew
from strew.metrics import fidelity


def exemplar(mk, cls, label):
    if label.startswith("v"):
        return mk.make_exemplar(cls, rng=int(label[1:]))
    if not label.startswith("p"):
        # an ``h`` label (``--harder``) used to be read as the --varied set of that index
        # (helper s62d): refuse it, --harder rows have their own scripts (syn13z_rows.py,
        # grw14y_rows.py, s62d_rows.py)
        sys.exit(f"fresh17_rows.py reads only v and p labels, not {label!r}: use syn13z_rows.py / grw14y_rows.py for --harder rows")
    i, _, v = label[1:].partition("s")
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    return mk.make_exemplar(cls, rng=int(v), **sets[int(i)])


def main():
    method, specs, seeds = sys.argv[1], sys.argv[2], _variants.ints(sys.argv[3])
    mk = fidelity_suite()
    if method == "synth":
        from synth_variants import run
        args = None
    else:
        from types import SimpleNamespace

        from grow_variants import run
        args = SimpleNamespace(mode="rotate" if method == "grow-rotate" else "fixed", times=10.0)
    tot = n = 0
    for spec in specs.split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        res = []
        for seed in seeds:
            out, _ = run(ex, 3.5, seed, args)
            rep = fidelity(ex, out, eq5=False, local=False)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and (not m.passed or k in os.environ.get("SHOW", "").split(","))]
            res.append(int(rep.faithful))
            print(f"  {method} {spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {' '.join(fails)}", flush=True)
        print(f"{method} {spec} {sum(res)}/{len(res)}", flush=True)
        tot += sum(res)
        n += len(res)
    print(f"total {tot}/{n}  ({strew.__file__})", flush=True)


if __name__ == "__main__":
    main()

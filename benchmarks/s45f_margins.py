"""Helper s45f: the metrics nearest their tolerance (value/tolerance) for synth rows.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s45f_margins.py three_sizes:h1s25,three_sizes:p4s31 1
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import _harder, run

import strew
from strew.metrics import fidelity


def main():
    mk = fidelity_suite()
    for spec in sys.argv[1].split(","):
        cls, lab = spec.split(":")
        if lab.startswith("h"):
            i, _, v = lab[1:].partition("s")
            ex = mk.make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
        else:
            ex = exemplar(mk, cls, lab)
        for seed in _variants.ints(sys.argv[2]):
            out, _ = run(ex, 3.5, seed, None)
            rep = fidelity(ex, out, eq5=False, local=False)
            ms = sorted(((m.value / m.tolerance, k, m.value, m.tolerance) for k, m in rep.metrics.items() if m.applicable and m.tolerance), reverse=True)[:4]
            print(f"{spec} seed {seed} {'pass' if rep.faithful else 'FAIL'} n={len(out)} " + " ".join(f"{k}={v:.3g}/{t:.3g}" for _, k, v, t in ms), strew.__file__.split('/')[2], flush=True)


if __name__ == "__main__":
    main()

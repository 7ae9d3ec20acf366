"""Issue 13 point 1, helper peb13m: rerun single rows of ``synth_variants.py --harder``
(class, HARDER index, variant seed, synth seed) and print their verdicts as the audit does.

    python benchmarks/peb13m_rows.py three_sizes:6:7:1 stones:2:7:1 ...
"""

from __future__ import annotations

import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite  # noqa: E402
from synth_variants import _harder, run  # noqa: E402

from strew.metrics import fidelity  # noqa: E402

if __name__ == "__main__":
    mk = _harder_suite()
    for arg in sys.argv[1:]:
        name, i, v, seed = arg.split(":")
        ex = mk.make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
        out, _ = run(ex, 3.5, int(seed), None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        print(f"{name} h{i}s{v} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {' '.join(fails)}", flush=True)

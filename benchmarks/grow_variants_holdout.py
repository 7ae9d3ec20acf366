"""Held-out exemplars for ``grow_variants.py``: one class's parameter set at variant seeds the audit never draws.

``grow_variants.py --varied`` draws each VARIED / EDGE set at variant seeds 7 and 8 only.
This draws set ``SET`` (an index into ``VARIED[name] + EDGE[name]`` of ``_variants.py``,
or ``default``) of class ``NAME`` at the variant seeds given, grows each as
``grow_variants.py`` does (fixed mode, region 3.5x the frame's side, enlarged once to
reach 10x the count) at the grow seeds given, and prints one line per run and the pass
count. Compare two checkouts with ``PYTHONPATH=<checkout>/src``.

    python benchmarks/grow_variants_holdout.py NAME SET VARIANTS SEEDS [--mode fixed|rotate]
    e.g. python benchmarks/grow_variants_holdout.py clusters 4 20,25,28 1
"""

from __future__ import annotations

import argparse
import sys
import time

import grow_variants as gv
from _runner import SKIPPED, fidelity_suite
from _variants import EDGE, VARIED, ints

from strew.metrics import fidelity


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("grow_variants_holdout: skipped: it needs its positional NAME SET VARIANTS SEEDS (a held-out case picked by hand), which have no default")
        sys.exit(SKIPPED)
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("name")
    ap.add_argument("set", help="index into VARIED[name] + EDGE[name], or 'default'")
    ap.add_argument("variants", help="variant seeds, e.g. 11-16")
    ap.add_argument("seeds", help="grow seeds, e.g. 1-2")
    ap.add_argument("--mode", default="fixed", choices=["fixed", "rotate"])
    ap.add_argument("--times", type=float, default=10.0)
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--quick", action="store_true", help="run_all.py's check: skips (the positional arguments have no default)")
    a = ap.parse_args()
    mk = fidelity_suite()
    sets = list(VARIED.get(a.name, [])) + list(EDGE.get(a.name, []))
    kw = {} if a.set == "default" else sets[int(a.set)]
    tot = [0, 0]
    for v in ints(a.variants):
        ex = mk.make_exemplar(a.name, rng=v, **kw)
        for s in ints(a.seeds):
            t0 = time.process_time()
            out, _ = gv.run(ex, a.scale, s, a)
            dt = time.process_time() - t0
            rep = fidelity(ex, out, eq5=False, local=False)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            tot[0] += int(rep.faithful)
            tot[1] += 1
            print(f"  {a.name} set {a.set} variant {v} seed {s}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {dt:.1f}s cpu {' '.join(fails)}", flush=True)
    print(f"{a.name} set {a.set} ({kw}): {tot[0]}/{tot[1]} faithful")


if __name__ == "__main__":
    main()

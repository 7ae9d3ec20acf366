"""Issue 13 point 1, held out: synth on the audit's parameter sets (default, ``VARIED``
and ``EDGE`` of ``_variants.py``) at exemplar generator seeds that the audit
(``synth_variants.py``: seeds 1-3, 7, 8) does not use, to check a change on exemplars
nobody looked at while making it. Each fills 3.5x the frame's side with synth seed 1
and is judged by ``strew.metrics.fidelity``. Printed: per set the pass count and one
mark per exemplar seed (+ pass, - fail), then the total. There is no baseline method:
run it with ``PYTHONPATH`` at the old and the new tree and compare.

    PYTHONPATH=src python benchmarks/synth_holdout.py --only stones [--exemplar-seeds 9-14]
"""

from __future__ import annotations

import argparse

from _runner import fidelity_suite
from _variants import EDGE, VARIED, ints

import strew
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", default="stones", help="class names, comma-separated")
    ap.add_argument("--exemplar-seeds", default="9-14")
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--quick", action="store_true", help="the default set only (a check of the script)")
    args = ap.parse_args()
    mk = fidelity_suite()
    seeds = ints(args.exemplar_seeds)
    tot = [0, 0]
    print(f"strew from {strew.__file__}")
    for name in args.only.split(","):
        sets = [("default", {})] + [("varied", kw) for kw in VARIED.get(name, [])] + [("edge", kw) for kw in EDGE.get(name, [])]
        sets = sets[:1] if args.quick else sets
        for i, (tag, kw) in enumerate(sets):
            marks = []
            for v in seeds:
                ex = mk.make_exemplar(name, rng=v, **kw)
                x0, y0, x1, y1 = ex.region.bounds
                out = synthesize(ex, Region.rectangle(args.scale * (x1 - x0), args.scale * (y1 - y0)), rng=1, measure=False)
                ok = fidelity(ex, out, eq5=False, local=False).faithful
                marks.append("+" if ok else "-")
                tot[0] += ok
                tot[1] += 1
            print(f"{name:12s} set {i} {tag:7s} {kw}: {marks.count('+')}/{len(marks)} {''.join(marks)}", flush=True)
    print(f"total {tot[0]}/{tot[1]} faithful")

"""Helper sp: audit rows that ``_optimize.sized_scatter`` changes, before and after, in one run.

Only exemplars where ``sized_scatter`` is True (and that are near-regular) can change: elsewhere
``spread_bound`` is computed as before, so those outputs are byte-identical and are not rerun.
Each changed row is synthesised with ``_optimize.SCATTER_BOUND = False`` (the code before
helper sp) and ``True``, at 3.5x the frame's side, and judged as ``benchmarks/synth_variants.py``
judges (``fidelity(ex, out, eq5=False, local=False)``; printed: verdict, count, each kind's density
over the exemplar's in ``ex.kinds`` order, CPU seconds, failing metrics), or with ``--full`` as
``benchmarks/fidelity.py`` does (``fidelity(ex, out)``: local windows too).

    PYTHONPATH=src:benchmarks python benchmarks/sp_rows.py --harder 7,8 --only two_sizes,three_sizes,clusters
    PYTHONPATH=src:benchmarks python benchmarks/sp_rows.py --varied 7,8 --only two_sizes,three_sizes,clusters,rings
    PYTHONPATH=src:benchmarks python benchmarks/sp_rows.py --suite 1,2,3,4,5 --only clusters --full [--variants none,1,2]
"""
import argparse
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _variants import EDGE, VARIED, ints
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.metrics import fidelity
from strew.synth import _optimize as O
from strew.synth import new_state, synthesize

ap = argparse.ArgumentParser()
ap.add_argument("--harder", default=None, help="variant seeds of the HARDER sets")
ap.add_argument("--varied", default=None, help="variant seeds of the VARIED and EDGE sets")
ap.add_argument("--suite", default=None, help="synth seeds on the suite's exemplars (--variants)")
ap.add_argument("--variants", default="none", help="suite exemplar variants ('none': the default exemplar)")
ap.add_argument("--only", required=True)
ap.add_argument("--seeds", default="1")
ap.add_argument("--full", action="store_true")
a = ap.parse_args()
mk = _harder_suite()
names = a.only.split(",")
cases = []
if a.harder:
    H = _harder()
    cases += [(n, f"h{i}s{v}", v, kw) for n in names for i, kw in enumerate(H.get(n, [])) for v in ints(a.harder)]
if a.varied:
    for n in names:
        sets = list(VARIED.get(n, [])) + list(EDGE.get(n, []))
        cases += [(n, f"p{i}s{v}", v, kw) for i, kw in enumerate(sets) for v in ints(a.varied)]
if a.suite:
    cases += [(n, f"v{v}", None if v == "none" else int(v), {}) for n in names for v in a.variants.split(",")]
seeds = ints(a.suite or a.seeds)
tot = {False: [0, 0], True: [0, 0]}
changed = 0
for name, lab, v, kw in cases:
    ex = mk.make_exemplar(name, rng=v, **kw)
    p = new_state(ex, Region.rectangle(100, 100), rng=1).prep
    if not (O.near_regular(p)[0] and O.sized_scatter(p)[0]):
        continue
    changed += 1
    x0, y0, x1, y1 = ex.region.bounds
    for seed in seeds:
        cells = []
        for on in (False, True):
            O.SCATTER_BOUND = on
            t = time.process_time()
            out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
            rep = fidelity(ex, out) if a.full else fidelity(ex, out, eq5=False, local=False)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            tot[on][0] += int(rep.faithful)
            tot[on][1] += 1
            dens = "/".join(f"{rep.metrics[f'density[{k}]'].result / rep.metrics[f'density[{k}]'].exemplar:.3f}" for k in ex.kinds if f"density[{k}]" in rep.metrics)
            cells.append(f"{'pass' if rep.faithful else 'FAIL'} n={len(out)} dens {dens} {time.process_time() - t:.1f}s {' '.join(fails)}")
        mark = "" if cells[0].split()[0] == cells[1].split()[0] else ("  GAIN" if cells[1].startswith("pass") else "  LOSS")
        print(f"  {name:12s} {lab:7s} seed {seed}: before {cells[0]} | after {cells[1]}{mark}", flush=True)
print(f"changed exemplars {changed}; faithful before {tot[False][0]}/{tot[False][1]}, after {tot[True][0]}/{tot[True][1]}")

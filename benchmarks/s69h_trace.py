"""Helper s69h: trace the prototype ``_grow._TWO_CLASS_AREA`` (count of the larger class per grown
area) through growth, and compare its target with the judge's exemplar density.

    PYTHONPATH=src:benchmarks python benchmarks/s69h_trace.py two_sizes:p3s31,two_sizes:h5s38 1 [SE=k] [off]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew._fidelity as F
import strew.synth._grow as G
from strew.metrics import fidelity
from strew.synth._palette import Palette
from strew.synth._prepare import prepare

G._TWO_CLASS_AREA = "off" not in sys.argv
for a in sys.argv[3:]:
    if a.startswith("SE="):
        G._TWO_CLASS_AREA_SE = float(a[3:])
CAP = []
_disc = F._discrepancies
F._discrepancies = lambda a, b, *x, **k: (CAP.append((a, b)), _disc(a, b, *x, **k))[1]


def exemplar(cls, label):
    i, _, v = label[1:].partition("s")
    if label.startswith("h"):
        return _harder_suite().make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    return fidelity_suite().make_exemplar(cls, rng=int(v), **sets[int(i)])


for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(cls, label)
    prep = prepare(Palette({"ex": ex}).select("ex"))
    dens, n_big, er, cell, wm = G._two_class_target(prep)
    print(f"== {spec} target {dens * 1e4:.3f}/1e4 (n {n_big}) empty reach {er:.2f} cell {cell:.2f} result margin {wm:.2f}", flush=True)
    for seed in _variants.ints(sys.argv[2]):
        G._AREA_LOG = []
        CAP.clear()
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        a, b = CAP[0]
        k = ex.kinds.index("stone")
        log = G._AREA_LOG
        G._AREA_LOG = None
        print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} judge ex dens[stone] {b.density[k] * 1e4:.3f} out {a.density[k] * 1e4:.3f}"
              f" ({a.density[k] / b.density[k] - 1:+.3f}); calls {len(log)}", flush=True)
        last = None
        for row in log:
            key = (row[0], row[8])
            if key != last:
                it, n, nin, nall, area, cov, d, bd, owed = row
                print(f"   it {it:3d} n {n:5d} larger in core {nin:4d} / all {nall:4d} core {area:9.0f} covered {cov:9.0f}"
                      f" dens {nin / max(area, 1) * 1e4:.3f} whole {nall / max(cov, 1) * 1e4:.3f} owed {owed}")
                last = key

"""Helper s26o (issue 13 point 1): which one-kind exemplars synth splits into size classes
(``_prepare.size_classes``): per exemplar, the elements in each class, the radius ratio
max/min, and the largest step between consecutive sorted bounding radii (a continuum of
sizes has small steps; two sizes of one kind a large one). Over the suite, the audit's
VARIED/EDGE sets and the HARDER sets at the given variant seeds.

    PYTHONPATH=src python benchmarks/s26o_size_class_survey.py [--variants 7,8,15,16,17,18] [--all]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import numpy as np
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.synth._api import as_selection
from strew.synth._prepare import prepare


def row(label, ex, every):
    prep = prepare(as_selection(ex))
    sel = prep.selected_elements
    if len(np.unique(prep.kind[sel])) != 1:
        return
    cls = prep.size_class[sel]
    if cls.max() == 0 and not every:
        return
    r = np.sort(prep.r[sel])
    step = r[1:] / r[:-1]
    print(f"{label:28s} n {len(r)} classes {np.bincount(cls).tolist()} r {r[0]:.2f}-{r[-1]:.2f} ratio {r[-1] / r[0]:.3f} "
          f"max step {step.max():.3f}", flush=True)


def main():
    vs = _variants.ints(sys.argv[sys.argv.index("--variants") + 1]) if "--variants" in sys.argv else [7, 8, 15, 16, 17, 18]
    every = "--all" in sys.argv
    mk = fidelity_suite()
    for name in mk.NAMES:
        row(f"{name} suite", mk.make_exemplar(name), every)
        sets = _variants.VARIED.get(name, []) + _variants.EDGE.get(name, [])
        for i, kw in enumerate(sets):
            for v in vs:
                row(f"{name} p{i}s{v}", mk.make_exemplar(name, rng=v, **kw), every)
    hk = _harder_suite()
    for name, sets in _harder().items():
        for i, kw in enumerate(sets):
            for v in vs:
                row(f"{name} h{i}s{v}", hk.make_exemplar(name, rng=v, **kw), every)


if __name__ == "__main__":
    main()

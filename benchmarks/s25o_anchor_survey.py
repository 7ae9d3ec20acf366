"""Helper s25o (issue 13 point 2): which exemplar classes synth keeps at their full closest
approach (``_prepare.anchor_spacing``): the classes that nearly all of their leaning elements
follow (a disc ringed by its dots, a hub by its tiles), with the spread of their own
nearest-neighbour distances (90th over 10th percentile: a lattice's stays under 1.07, a
dart-thrown hard-core pattern's runs past 1.1). Over the suite, the audit's VARIED/EDGE
sets and the HARDER sets at the given variant seeds.

    PYTHONPATH=src python benchmarks/s25o_anchor_survey.py [--variants 7,8,15,16]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import numpy as np
from _runner import fidelity_suite
from grow_variants import _harder_suite
from scipy.spatial import cKDTree
from synth_variants import _harder

from strew.synth._api import as_selection
from strew.synth._prepare import prepare


def row(label, ex):
    prep = prepare(as_selection(ex))
    sk, par = prep.skind, prep.parent
    out = []
    for a in np.unique(sk):
        kids = np.flatnonzero(par >= 0)
        kids = kids[sk[par[kids]] == a]
        if not len(kids):
            continue
        share = float(prep.follow[kids].mean())
        p = prep.pos[sk == a]
        d3, _ = cKDTree(p).query(p, k=min(4, len(p)))
        d = d3[:, 1]
        third = float(np.median(d3[:, -1] / d3[:, 1]))
        tail = float(np.quantile(d, 0.9) / np.quantile(d, 0.1))
        floor = float(np.quantile(d, 0.1) / d.min())
        kept = bool(np.isclose(prep.min_dist[a, a], d.min()))
        out.append(f"class {a} n {len(p)} follow {share:.2f} tail {tail:.3f} floor {floor:.3f} d3/d1 {third:.3f} full {kept}")
    print(f"{label:28s} " + " ; ".join(out), flush=True)


def main():
    vs = _variants.ints(sys.argv[sys.argv.index("--variants") + 1]) if "--variants" in sys.argv else [7, 8, 15, 16]
    mk = fidelity_suite()
    for name in mk.NAMES:
        if name == "sticks":
            continue
        row(f"{name} suite", mk.make_exemplar(name))
        sets = _variants.VARIED.get(name, []) + _variants.EDGE.get(name, [])
        for i, kw in enumerate(sets):
            for v in vs:
                row(f"{name} p{i}s{v}", mk.make_exemplar(name, rng=v, **kw))
    hk = _harder_suite()
    for name, sets in _harder().items():
        for i, kw in enumerate(sets):
            for v in vs:
                row(f"{name} h{i}s{v}", hk.make_exemplar(name, rng=v, **kw))


if __name__ == "__main__":
    main()

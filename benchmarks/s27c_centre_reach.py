"""Helper s27c (issue 13 point 2): which exemplars ``_prepare.centre_spacing`` reaches and
the spacing it keeps for cluster centres, relative to the exemplar's closest approach
(main: 0.95 for every class). Needs the change applied:
``git apply benchmarks/results/s27c_hard_core_centre_spacing.patch`` (on main it prints ``-``
for every row).

    PYTHONPATH=src python benchmarks/s27c_centre_reach.py [--names clusters,two_sizes,...] [--variants 7,19]

Rows: the suite exemplar, the VARIED/EDGE sets (``p{i}s{v}``) and synth's HARDER sets
(``h{i}s{v}``) at the given variant seeds; one line per class whose spacing changed.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.synth._api import as_selection
from strew.synth._prepare import closest_approach, prepare


def reach(ex) -> list[str]:
    prep = prepare(as_selection(ex))
    approach = closest_approach(prep.pos, prep.skind, prep.source)
    names = np.asarray(ex.kind_names)
    out = []
    for a in np.unique(prep.skind):
        f = prep.min_dist[a, a] / approach[a, a] if np.isfinite(approach[a, a]) else 0.0
        if f > 0.9501:
            kind = names[prep.skind == a][0]
            out.append(f"{kind} n={int((prep.skind == a).sum())} approach={approach[a, a]:.2f} spacing={prep.min_dist[a, a]:.2f} ({f:.4f}x)")
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--names", default="clusters,two_sizes,three_sizes,stones,rings,sparse_voids,stripes")
    ap.add_argument("--variants", default="7,19")
    a = ap.parse_args()
    mk = _harder_suite()  # stones with aspect (HARDER sets)
    vs = [int(v) for v in a.variants.split(",") if v]
    for name in a.names.split(","):
        rows = [("suite", mk.make_exemplar(name))]
        sets = _variants.VARIED.get(name, []) + _variants.EDGE.get(name, [])
        rows += [(f"p{i}s{v}", mk.make_exemplar(name, rng=v, **kw)) for i, kw in enumerate(sets) for v in vs]
        rows += [(f"h{i}s{v}", mk.make_exemplar(name, rng=v, **kw)) for i, kw in enumerate(_harder().get(name, [])) for v in vs]
        for label, ex in rows:
            r = reach(ex)
            print(f"{name:12s} {label:6s} " + ("; ".join(r) if r else "-"), flush=True)


if __name__ == "__main__":
    main()

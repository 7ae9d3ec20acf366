"""Helper syn17: per three sizes exemplar (suite, --harder sets at variant seeds 7-12, --varied/edge), each size class's
cover of the inner frame (inner-frame density x mean bounding-disc area, as ``_grow._top_cover`` computes it for the
largest class), its element count and kinds: which exemplars have a sparse class below the largest.

    PYTHONPATH=TREE/src python benchmarks/syn17_cover.py [CLASSES] [VARIANTS]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.synth._api import new_state
from strew.synth._displace import _inner_density


def covers(prep):
    dens = _inner_density(prep, 2.0 * float(prep.rc.max()))
    sel = prep.selected_elements & ~prep.void
    out = []
    for c in np.unique(prep.size_class[sel]):
        ids = np.flatnonzero(sel & (prep.size_class == c))
        kinds = np.unique(prep.skind[ids])
        out.append((int(c), float(np.sum(dens[kinds]) * np.mean(np.pi * prep.r[ids] ** 2)), len(ids), [prep.kind_names[k] if hasattr(prep, "kind_names") else int(k) for k in kinds]))
    return out


if __name__ == "__main__":
    classes = sys.argv[1].split(",") if len(sys.argv) > 1 else ["three_sizes"]
    vs = [int(v) for v in sys.argv[2].split(",")] if len(sys.argv) > 2 else [7, 8, 9, 10, 11, 12]
    mk = _harder_suite()
    H = _harder()
    for cls in classes:
        rows = [(f"{cls}:suite", mk.make_exemplar(cls))]
        rows += [(f"{cls}:h{i}s{s}", mk.make_exemplar(cls, rng=s, **kw)) for i, kw in enumerate(H.get(cls, [])) for s in vs]
        rows += [(f"{cls}:{lab}", mk.make_exemplar(cls, rng=s, **kw)) for lab, tag, s, kw in _variants.cases(cls, [1, 2, 3], True)]
        for name, ex in rows:
            prep = new_state(ex).prep
            print(f"{name:26s} " + "  ".join(f"c{c} cover {cv:.3f} n {n:3d} {k}" for c, cv, n, k in covers(prep)), flush=True)

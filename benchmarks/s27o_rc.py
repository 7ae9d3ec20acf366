"""Helper s27o (issue 13 point 1): per kind of a --harder three_sizes exemplar, the bounding radius r,
the area radius and the collision radius rc synth keeps (``_prepare.collision_radii``), medians, and rc / area radius.

    PYTHONPATH=TREE/src python benchmarks/s27o_rc.py H V[,V...]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from synth_variants import _harder

from strew.synth._api import as_selection
from strew.synth._prepare import area_radii, prepare

mk = _harder_suite()
i = int(sys.argv[1])
for v in [int(x) for x in sys.argv[2].split(",")]:
    ex = mk.make_exemplar("three_sizes", rng=v, **_harder()["three_sizes"][i])
    prep = prepare(as_selection(ex))
    ar = area_radii(ex.with_columns(radius=prep.r))
    k = np.asarray(ex.kind)
    row = []
    for j, nm in enumerate(ex.kinds):
        m = k == j
        row.append(f"{nm}: r {np.median(prep.r[m]):.2f} a {np.median(ar[m]):.2f} rc {np.median(prep.rc[m]):.2f} rc/a {np.median(prep.rc[m] / ar[m]):.2f} cls {int(prep.size_class[m][0])}")
    print(f"h{i}s{v}", " | ".join(row), f"min_dist diag {np.round(np.diag(prep.min_dist), 2)}")

"""Helper s63t: the exemplar's own spread of its largest class's count in windows of its
inner frame (issue 13 point 1), for the rows of the ownership gate.

    PYTHONPATH=src:benchmarks python benchmarks/s63t_fano.py v25,p4s27,p4s29,p0s32,h6s29
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely

from s60t_ahead_probe import exemplar

import strew.synth._grow as G
from strew.synth._api import new_state

for label in sys.argv[1].split(","):
    ex = exemplar(label)
    prep = new_state(ex).prep
    top, _a, cover, rate = G._own_setup(prep)
    margin = 2.0 * float(prep.rc.max())
    for s_ in np.flatnonzero(cover > 0):
        inner = prep.domains[s_].buffer(-margin)
        x0, y0, x1, y1 = inner.bounds
        pts = prep.pos[top & (prep.source == s_)]
        ntot = int(np.count_nonzero(shapely.contains_xy(inner, pts[:, 0], pts[:, 1])))
        row = [f"{label}: kept cover={cover[s_]:.3f} inner large={ntot} rate*A={rate[s_]*inner.area:.1f}"]
        for f in (1 / 2, 1 / 3, 1 / 4):
            w, h = f * (x1 - x0), f * (y1 - y0)
            k = 41
            cs = []
            for cx in np.linspace(x0, x1 - w, k):
                for cy in np.linspace(y0, y1 - h, k):
                    cs.append(np.count_nonzero((pts[:, 0] >= cx) & (pts[:, 0] < cx + w) & (pts[:, 1] >= cy) & (pts[:, 1] < cy + h)))
            cs = np.asarray(cs, float)
            row.append(f"side {f:.2f}: mean {cs.mean():.2f} sd {cs.std():.2f} fano {cs.var() / cs.mean():.3f}")
        print("  ".join(row), flush=True)
    if not (cover > 0).any():
        print(f"{label}: not kept")

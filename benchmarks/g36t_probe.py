"""Helper g36t: the hole pass's kind-reach gate at the fitted position, probed on one row.

    ROW=three_sizes:9:25 SEED=1 PYTHONPATH=src python benchmarks/g36t_probe.py

Grows the row as ``grw14y_rows.py`` and prints, for each hole the pass (``fill_void_holes``
with ``small_fill``) tries: the hole's radius, the fit's move from the circle's centre, and
per kind the nearest placed element from the fitted position over that kind's reach (all in
s = the exemplar's median nn); then the row's verdict.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite  # noqa: E402

import strew.grow._void_holes as vh  # noqa: E402
from strew import Region  # noqa: E402
from strew.grow import grow  # noqa: E402
from strew.grow._objects import ELEMENT  # noqa: E402
from strew.metrics import fidelity  # noqa: E402

rows = []
o_fit = vh._fitted_xy


def fitted(g, s, pick):
    x, y = o_fit(g, s, pick)
    cx, cy = g.xy[s]
    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT])
    d = np.hypot(g.pos[els, 0] - x, g.pos[els, 1] - y)
    k = g.kind[els]
    reach = vh.small_fill(g)[1]
    rows.append((len(g._last_nb), np.hypot(x - cx, y - cy) / g.l, [float(d[k == b].min() / reach[b]) for b in range(g.n_kinds)]))
    return x, y


vh._fitted_xy = fitted
cls, i, v = os.environ.get("ROW", "three_sizes:9:25").split(":")
seed = int(os.environ.get("SEED", 1))
ex = _harder_suite().make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
x0, y0, x1, y1 = ex.region.bounds
out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
rep = fidelity(ex, out, eq5=False, local=False)
for nb, mv, q in rows:
    print(f"nb {nb:2d} move {mv:.2f} l  nearest/reach " + " ".join(f"{x:.2f}" for x in q))
print("tried", len(rows), "pass all", sum(max(q) <= 1 for _, _, q in rows), "empty_circle", rep.metrics["empty_circle"].value, rep.faithful)

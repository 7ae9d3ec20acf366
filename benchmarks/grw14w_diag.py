"""Helper grw14w: signed error per decile of nn[a>b] (grow, fixed mode), output against exemplar.

``SPEC`` is ``suite`` (the fidelity suite's three_sizes, variant 0) or ``I:V`` (``--harder``
three_sizes variant I drawn with seed V). Grows the output as the audits do (3.5x the
frame's side) and prints: per-kind counts per 1e4 area (elements at least 2 s from the
region's edge), the deciles of kind a's distance to its nearest b in the exemplar and the
output (Hanisch: an element counts only when that distance is below its distance to the
edge), their signed difference in units of s, the quantiles of the gap between a's
scaled bounding disc and its nearest b's, the grower's pair_disc[a, b] / [b, a], and the
failing metrics.

Measured at d6d394e: the suite's three sizes, seeds 1-2, nn[small>large] signed error per
decile (deciles 1-9) -0.02/+0.01/+0.02/+0.04/+0.07/+0.10/+0.13/+0.33/+0.33 s (0.116; 0.110
seed 2; tolerance 0.127): small stones already too far from the large ones at the upper
deciles; with grw14v's disc gap for every snug smallest kind (0.9 of the least gap, 1.10)
+0.02/+0.05/+0.07/+0.08/+0.12/+0.13/+0.18/+0.35/+0.30 (0.150; 0.139 seed 2): the small
stones pushed off the large ones at every decile, disc gaps q10/q30/q50 1.19/2.17/3.41 ->
1.54/2.52/3.75 (exemplar 1.44/2.17/2.89). h12s7 seed 1 nn[large>small] -0.20..-0.02 s at
every decile (0.103), disc gaps q0/q10/q30/q50 0.00/0.10/0.41/0.88 (exemplar
1.20/1.22/1.25/1.45); with DISC_RINGED 1.08/1.16/1.27/1.41 (0.024). h1s7 (40:100:20) seeds
1-2 nn[large>medium] -0.18..-0.02 / -0.20..-0.04 s (0.088, 0.136): medium stones inside the
large stones' discs (disc gaps q0/q10 -2.6/-1.1, -3.4/-1.4; exemplar 1.21/1.39).

    PYTHONPATH=src python benchmarks/grw14w_diag.py suite 1,2 small large
    PYTHONPATH=src python benchmarks/grw14w_diag.py 12:7 1 large small
"""

import os
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import _growth as G
from strew.grow import grow
from strew.metrics import fidelity

mk = _harder_suite()
spec, seeds, ka, kb = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
if spec == "suite":
    ex = mk.make_exemplar("three_sizes", rng=0)
else:
    i, v = map(int, spec.split(":"))
    ex = mk.make_exemplar("three_sizes", rng=v, **HARDER["three_sizes"][i])
cap = {}
r0 = G._Grower.result


def res(self, meta):
    cap["g"] = self
    return r0(self, meta)


G._Grower.result = res
x0, y0, x1, y1 = ex.region.bounds
Q = np.linspace(0.1, 0.9, 9)


def stats(arr, g, region):
    ks = list(arr.kinds)
    a, b = ks.index(ka), ks.index(kb)
    Ra = np.array([g.kind_radius[ex.kinds.index(k)] for k in ks])[arr.kind] * np.abs(
        arr.scale
    )
    edge = shapely.distance(region.boundary, shapely.points(arr.xy))
    ia, ib = np.flatnonzero(arr.kind == a), np.flatnonzero(arr.kind == b)
    d, j = cKDTree(arr.xy[ib]).query(arr.xy[ia], k=2 if a == b else 1)
    if a == b:
        d, j = d[:, 1], j[:, 1]
    keep = d <= edge[ia]
    gap = d - Ra[ia] - Ra[ib][j]
    return (
        np.quantile(d[keep], Q),
        np.quantile(gap[keep], [0, 0.1, 0.3, 0.5, 0.7, 0.9]),
        edge,
    )


for seed in map(int, seeds.split(",")):
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = grow(ex, region=region, mode="fixed", rng=seed)
    g = cap["g"]
    rep = fidelity(ex, out, eq5=False, local=False)
    s = rep.s
    a, b = ex.kinds.index(ka), ex.kinds.index(kb)
    print(
        f"{spec} seed {seed} s={s:.2f} pair_disc[a,b]={g.pair_disc[a, b]:.2f} [b,a]={g.pair_disc[b, a]:.2f}"
    )
    qe, ge, ee = stats(ex, g, ex.region.geometry)
    qo, go, eo = stats(out, g, out.region.geometry)
    for name, arr, e in (("exemplar", ex, ee), ("output", out, eo)):
        bx = arr.region.bounds
        inner = shapely.box(
            bx[0] + 2 * s, bx[1] + 2 * s, bx[2] - 2 * s, bx[3] - 2 * s
        ).area
        cnt = [
            int(np.sum((arr.kind == k) & (e >= 2 * s))) for k in range(len(arr.kinds))
        ]
        print(
            f" {name:8s} per 1e4: "
            + " ".join(
                f"{arr.kinds[k]} {1e4 * c / inner:.1f}" for k, c in enumerate(cnt)
            )
        )
    print(f" nn[{ka}>{kb}] ex  {np.round(qe, 2)}")
    print(f" nn[{ka}>{kb}] out {np.round(qo, 2)}")
    print(
        f" signed/s        {np.round((qo - qe) / s, 3)}  mean|.| {np.mean(np.abs(qo - qe)) / s:.4f}"
    )
    print(f" disc gap q0/10/30/50/70/90 ex {np.round(ge, 2)} out {np.round(go, 2)}")
    print(
        " fails",
        [
            f"{k}={m.value:.3g}/{m.tolerance:.3g}"
            for k, m in rep.metrics.items()
            if m.applicable and not m.passed
        ],
        flush=True,
    )

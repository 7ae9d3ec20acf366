"""Holes of voids among visible elements (issue 14 point 1, untuned exemplars).

Sparse apples drawn saturated among voids (the audit's sparse_voids p0s7: spacing 24,
apple 4): grow left apple-sized holes that voids filled, and the visible elements'
empty circles (q95; the judge leaves voids out) came out 17-23 % wider than the
exemplar's. After the growth, ``strew.grow._void_holes.fill_void_holes`` puts a visible
element in place of the voids of each empty circle wider than the exemplar's widest
(and its least visible spacing).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay
from strew_testing import fidelity_suite

from strew import Region
from strew._kernels.geometry import circumcircles
from strew.grow import analyze, grow
from strew.grow._growth import GrowParams, grow_reference
from strew.metrics import fidelity, overlaps


def _exemplar():
    return fidelity_suite().make_exemplar("sparse_voids", rng=7, spacing=24.0, apple=4.0)


def _region(ex, side):
    x0, y0, x1, y1 = ex.region.bounds
    return Region.rectangle(side * (x1 - x0), side * (y1 - y0))


def _visible_circles(arr, region):
    """Circumradii of the visible elements' Delaunay triangles whose circle lies inside ``region``."""
    vis = ~np.asarray(arr.columns["void"], dtype=bool)
    p = arr.xy[vis]
    tri = Delaunay(p)
    cen, r, _ = circumcircles(*(p[tri.simplices[:, q]] for q in range(3)))
    inner = region.contains(cen) & (region.distance_to_boundary(cen) >= r)
    return r[inner]


def test_no_void_hole_wider_than_the_exemplar_has():
    ex = _exemplar()
    widest = float(_visible_circles(ex, ex.region).max())
    region = _region(ex, 2.5)
    out = grow(ex, region=region, rng=1)
    assert len(out) >= 5 * len(ex)
    r = _visible_circles(out, region)
    # 7c83aee (and void_holes=False): 15 % of the circles wider than 1.05 x the
    # exemplar's widest, up to 1.36 x, q95 1.25 x the exemplar's; now 0.4 %, 1.07 x, 1.05 x
    assert float(np.mean(r > 1.05 * widest)) <= 0.02
    assert float(np.quantile(r, 0.95)) <= 1.1 * float(np.quantile(_visible_circles(ex, ex.region), 0.95))
    assert len(overlaps(out)[0]) == 0
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    # the pass is the difference: without it the holes are there
    off = grow_reference(analyze(ex), GrowParams(region=region, void_holes=False), rng=1)
    assert float(np.mean(_visible_circles(off, region) > 1.05 * widest)) > 0.04
    # deterministic
    again = grow(ex, region=region, rng=1)
    assert np.array_equal(again.xy, out.xy) and np.array_equal(again.kind, out.kind)


def test_sparse_apples_among_voids_are_faithful():
    # the audit's case at 3.5 x: empty_circle 0.171 against 0.1 at 7c83aee
    ex = _exemplar()
    out = grow(ex, region=_region(ex, 3.5), rng=1)
    assert len(out) >= 10 * len(ex)
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    assert rep.metrics["empty_circle"].passed

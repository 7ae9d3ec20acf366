"""Flow mode: the last holes of a bent lattice are closed (issue 14 point 2: "the
defects are sparse, isolated dislocations, not holes").

The hexagonal lattice grown along the quarter-circle field from a start near the corner
at its centre of curvature (``benchmarks/grow.py --structure``) kept one hole (an empty
circle wider than 1.5 spacings) at 7c83aee, a ring of five elements that neither
``fill_holes`` nor ``close_gaps`` could change, and 0.796 of its interior elements had
six neighbours at the spacing. :func:`strew.grow._flow_holes.close_holes` relaxes the
ring's window (§5.5) and places an element there: no hole is left, the share is 0.806,
nothing leaves the region and nothing overlaps.
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from strew import Region
from strew.fields import flow_field
from strew.grow import analyze
from strew.grow._growth import GrowParams, grow_reference
from strew.grow._relax import relax_positions

from strew_testing import fidelity_suite

SP = 12.0  # the hexagonal exemplar's spacing


def _holes14c(xy: np.ndarray, region: Region) -> int:
    """Groups of grid points (3 units apart, 2 spacings inside the edge) farther than
    0.75 spacing from every centre (benchmarks/grow.py, lattice_defects)."""
    x0, y0, x1, y1 = region.bounds
    g = np.mgrid[x0 + 2 * SP : x1 - 2 * SP : 3.0, y0 + 2 * SP : y1 - 2 * SP : 3.0].reshape(2, -1).T
    far = g[cKDTree(xy).query(g)[0] > 0.75 * SP]
    if len(far) == 0:
        return 0
    m = cKDTree(far).sparse_distance_matrix(cKDTree(far), 4.5)
    return len(np.unique(connected_components(m, directed=False)[1]))


def _six14c(xy: np.ndarray, region: Region) -> float:
    tree = cKDTree(xy)
    inner = np.flatnonzero(region.distance_to_boundary(xy) > 2 * SP)
    hi = np.array([len(tree.query_ball_point(xy[i], 1.15 * SP)) - 1 for i in inner])
    lo = np.array([len(tree.query_ball_point(xy[i], 0.85 * SP)) - 1 for i in inner])
    return float(((hi == 6) & (lo == 0)).mean())


@pytest.mark.slow
def test_flow_quarter_circles_from_the_corner_leave_no_hole():
    ex = fidelity_suite().make_exemplar("hex_lattice", nx=8, ny=8)
    a = 30 * SP
    th = np.linspace(0, np.pi / 2, 30)
    field = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (a / 3, a * 5 / 6)])
    region = Region.rectangle(a, a)
    kw = dict(region=region, mode="flow", flow=field, start=(2 * SP, 2 * SP))
    ref = analyze(ex)
    out = grow_reference(ref, GrowParams(**kw), rng=1)
    # inside the region, no overlap
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    geoms = np.asarray(out.geometry)
    i, j = shapely.STRtree(geoms).query(geoms, predicate="intersects")
    keep = i < j
    inter = shapely.area(shapely.intersection(geoms[i[keep]], geoms[j[keep]]))
    assert inter.max(initial=0.0) < 1e-6 * float(shapely.area(geoms[0]))
    assert _holes14c(out.xy, region) == 0  # 1 at 7c83aee
    share = _six14c(out.xy, region)
    assert share >= 0.79  # 0.806 here; 0.796 at 7c83aee
    # the pass is what closes it
    off = grow_reference(ref, GrowParams(**kw, flow_hole_min=None), rng=1)
    assert _holes14c(off.xy, region) >= 1
    # the same output again (determinism)
    again = grow_reference(ref, GrowParams(**kw), rng=1)
    assert np.array_equal(again.xy, out.xy) and np.array_equal(again.rotation, out.rotation)


def test_relax_positions_weights_one_is_unweighted_and_weights_pull_harder():
    rng = np.random.default_rng(0)
    pos = rng.uniform(0, 10, (8, 2))
    src = np.array([0, 1, 2, 3, 4, 5, 6, 0])
    dst = np.array([1, 2, 3, 4, 5, 6, 7, 7])
    off = rng.uniform(-2, 2, (8, 2))
    free = np.array([False, True, True, True, True, True, True, True])
    plain = relax_positions(pos, src, dst, off, free)
    ones = relax_positions(pos, src, dst, off, free, weights=np.ones(8))
    assert np.allclose(plain, ones, atol=1e-9)
    # a heavy term is met more nearly than with weight one
    w = np.ones(8)
    w[3] = 100.0
    heavy = relax_positions(pos, src, dst, off, free, weights=w)

    def miss(p):
        return float(np.hypot(*(p[dst[3]] - p[src[3]] - off[3])))

    assert miss(heavy) < 0.1 * miss(plain)

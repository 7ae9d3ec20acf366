"""Flow mode: the gaps a bent lattice leaves are filled or closed (issue 14 point 2).

The hexagonal lattice grown from the corner at the centre of curvature of a
quarter-circle field (the hardest case of ``benchmarks/grow.py --structure``) left ten
holes (empty circles wider than 1.5 spacings) at d66b77e; the passes of
:mod:`strew.grow._flow_gaps` leave two. Whatever they move stays inside the region and
off every other element, and the lattice keeps its six-neighbour share.

The same case's rows fan out. At 82a4322 the front only stretched: 0.536 of the interior
elements kept six neighbours at the spacing (+-15%), 0.46 had fewer than six within 1.15
spacings and none nearer (a stretched site), and two holes were left.
``_Grower.flow_respace`` spaces a stretched run of front seeds anew with one seed more:
0.796 keep six neighbours, 0.20 are stretched, one hole.
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

from strew_testing import fidelity_suite

SP = 12.0  # the hexagonal exemplar's spacing


def _holes(xy: np.ndarray, region: Region) -> int:
    """Groups of grid points (3 units apart, 2 spacings inside the edge) farther than
    0.75 spacing from every centre (benchmarks/grow.py, lattice_defects)."""
    x0, y0, x1, y1 = region.bounds
    g = np.mgrid[x0 + 2 * SP : x1 - 2 * SP : 3.0, y0 + 2 * SP : y1 - 2 * SP : 3.0].reshape(2, -1).T
    far = g[cKDTree(xy).query(g)[0] > 0.75 * SP]
    if len(far) == 0:
        return 0
    m = cKDTree(far).sparse_distance_matrix(cKDTree(far), 4.5)
    return len(np.unique(connected_components(m, directed=False)[1]))


def _shares(xy: np.ndarray, region: Region) -> tuple[float, float]:
    """Of the interior elements (over 2 spacings inside): the share with six neighbours
    at 0.85-1.15 spacings and none nearer, and the share with fewer than six within 1.15
    spacings and none nearer (stretched)."""
    tree = cKDTree(xy)
    inner = np.flatnonzero(region.distance_to_boundary(xy) > 2 * SP)
    hi = np.array([len(tree.query_ball_point(xy[i], 1.15 * SP)) - 1 for i in inner])
    lo = np.array([len(tree.query_ball_point(xy[i], 0.85 * SP)) - 1 for i in inner])
    return float(((hi == 6) & (lo == 0)).mean()), float(((hi < 6) & (lo == 0)).mean())


def _six_share(xy: np.ndarray, region: Region) -> float:
    return _shares(xy, region)[0]


def _quarter_circles(a: float):
    th = np.linspace(0, np.pi / 2, 30)
    return flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (a / 3, a * 5 / 6)])


@pytest.fixture(scope="module")
def corner():
    """The hexagonal lattice grown from the corner at the centre of curvature of a
    quarter-circle field: the reference, the growth's keywords and the output."""
    ex = fidelity_suite().make_exemplar("hex_lattice", nx=8, ny=8)
    a = 30 * SP
    kw = dict(region=Region.rectangle(a, a), mode="flow", flow=_quarter_circles(a), start=(2 * SP, 2 * SP))
    ref = analyze(ex)
    return ref, kw, grow_reference(ref, GrowParams(**kw), rng=1)


def _inside_without_overlap(out, region: Region) -> None:
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    geoms = np.asarray(out.geometry)
    i, j = shapely.STRtree(geoms).query(geoms, predicate="intersects")
    keep = i < j
    inter = shapely.area(shapely.intersection(geoms[i[keep]], geoms[j[keep]]))
    assert inter.max(initial=0.0) < 1e-6 * float(shapely.area(geoms[0]))


def grown_with_and_without(ref, region: Region, flow, **off) -> tuple:
    """Grow ``ref`` in flow mode along ``flow`` (seed 1) with the defaults and with the
    parameters ``off``; assert the default output is inside ``region``, free of
    overlaps and holes, and return it with its (six, stretched) shares and the
    shares of the other output."""
    kw = dict(region=region, mode="flow", flow=flow)
    out = grow_reference(ref, GrowParams(**kw), rng=1)
    _inside_without_overlap(out, region)
    assert _holes(out.xy, region) == 0
    other = grow_reference(ref, GrowParams(**kw, **off), rng=1)
    return out, _shares(out.xy, region), _shares(other.xy, region)


@pytest.mark.slow
def test_flow_from_the_centre_of_curvature_leaves_few_holes_and_no_overlap(corner):
    ref, kw, out = corner
    region = kw["region"]
    _inside_without_overlap(out, region)
    holes = _holes(out.xy, region)
    assert holes <= 3
    # without the passes (the growth of d66b77e): ten
    off = grow_reference(ref, GrowParams(**kw, flow_fill_min=None, flow_close_min=None, flow_hole_min=None), rng=1)
    assert _holes(off.xy, region) > holes
    # they move a few elements: the lattice keeps its six-neighbour share (0.541 without)
    assert _six_share(out.xy, region) >= _six_share(off.xy, region) - 0.02


def test_flow_gap_passes_leave_an_irregular_exemplars_gaps_alone():
    # stones: the widest empty circle of the exemplar's interior is 0.8 mean edges;
    # only wider ones (by a tenth) are filled, so the density stays the exemplar's
    ex = fidelity_suite().make_exemplar("stones")
    x0, y0, x1, y1 = ex.region.bounds
    w, h = 2 * (x1 - x0), 2 * (y1 - y0)
    t = np.linspace(0, w, 20)
    kw = dict(region=Region.rectangle(w, h), mode="flow", flow=flow_field([np.c_[t, h * (0.4 + 0.1 * np.sin(2 * np.pi * t / w))]]))
    ref = analyze(ex)
    on = grow_reference(ref, GrowParams(**kw), rng=1)
    off = grow_reference(ref, GrowParams(**kw, flow_fill_min=None, flow_close_min=None), rng=1)
    assert abs(len(on) - len(off)) <= 0.01 * len(off)


@pytest.mark.slow
def test_flow_away_from_the_centre_of_curvature_keeps_the_lattice(corner, monkeypatch):
    ref, kw, out = corner
    region = kw["region"]
    _inside_without_overlap(out, region)
    six, stretched = _shares(out.xy, region)
    assert six >= 0.72  # 0.796 here; 0.536 at 82a4322
    assert stretched <= 0.28  # 0.20; 0.46 at 82a4322
    assert _holes(out.xy, region) <= 1  # 1; 2 at 82a4322
    # the respacing is what keeps it: without it the front stretches as before (and
    # without the band's insertions of strew.grow._flow_densify, which put nothing in
    # here but mend part of a front left stretched: 0.823 without the respacing)
    # (weighed without the band's last network pass, as the respacing was: since the
    # band pass also sends back the elements near the grid's new far points it mends
    # more of the front the missing respacing leaves, 0.838 without the respacing,
    # 0.796 at 8224b5f, 0.770 without the band pass)
    from test_grow_flow14m_band import without_band_pass

    without_band_pass(monkeypatch)
    off = grow_reference(ref, GrowParams(**kw, flow_respace=None, flow_densify_rounds=None), rng=1)
    six_off, stretched_off = _shares(off.xy, region)
    assert six_off < six - 0.1 and stretched_off > stretched + 0.1


@pytest.mark.parametrize("mode", ["fixed", "rotate"])
def test_flow_respace_leaves_the_other_modes_alone(mode):
    ex = fidelity_suite().make_exemplar("hex_lattice", nx=8, ny=8)
    ref = analyze(ex)
    kw = dict(region=Region.rectangle(16 * SP, 12 * SP), mode=mode)
    on = grow_reference(ref, GrowParams(**kw), rng=3)
    off = grow_reference(ref, GrowParams(**kw, flow_respace=None), rng=3)
    assert len(on) > 100
    assert np.array_equal(on.xy, off.xy) and np.array_equal(on.rotation, off.rotation)


@pytest.mark.slow
def test_flow_close_holes_leaves_no_hole_from_the_corner(corner):
    # close_holes (strew.grow._flow_holes): at 7c83aee this case kept one hole, a ring of
    # five elements that neither fill_holes nor close_gaps could change, and 0.796 of the
    # interior kept six neighbours; relaxing the ring's window (§5.5) and placing an
    # element there leaves none, 0.806
    ref, kw, out = corner
    region = kw["region"]
    _inside_without_overlap(out, region)
    assert _holes(out.xy, region) == 0
    assert _six_share(out.xy, region) >= 0.79
    # the pass is what closes it
    off = grow_reference(ref, GrowParams(**kw, flow_hole_min=None), rng=1)
    assert _holes(off.xy, region) >= 1
    # the same output again (determinism)
    again = grow_reference(ref, GrowParams(**kw), rng=1)
    assert np.array_equal(again.xy, out.xy) and np.array_equal(again.rotation, out.rotation)

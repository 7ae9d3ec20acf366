"""Pack's field marks a placed region's pixels by row crossings (issue 15 point 5).

``_occupy`` (``DistanceField.occupy``) and ``_occupy_posed`` (the draw loop's update)
find each row's crossings once with the shared scanline (``strew._kernels.raster``)
and walk them along the row. The pixels they set to 0 must be exactly those whose
centres a brute-force even-odd test, per pixel and edge, finds inside, and those on
the boundary (distance 0): with holes, concave parts and vertices on pixel centres
(where the half-open rule decides).
"""

from __future__ import annotations

import numpy as np
import shapely
import shapely.affinity
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import Region
from strew.pack._field import DistanceField, _occupy_posed, _segments

CELL = 1.0


def _brute_inside(px: np.ndarray, py: np.ndarray, segs: np.ndarray) -> np.ndarray:
    """Even-odd, half-open in y, one test per centre and edge (numpy, no scanline)."""
    inside = np.zeros(px.shape, bool)
    for ax, ay, bx, by in segs:
        crosses = (ay > py) != (by > py)
        if not crosses.any():
            continue
        with np.errstate(divide="ignore", invalid="ignore"):
            xc = ax + (py - ay) * (bx - ax) / (by - ay)
        inside ^= crosses & (px < xc)
    return inside


@st.composite
def holed_polygons(draw):
    """A star-shaped (so often concave) polygon with up to two star holes; with
    ``snap`` its vertices lie on pixel centres and pixel corners."""
    n = draw(st.integers(5, 14))
    radii = draw(st.lists(st.floats(6.0, 18.0), min_size=n, max_size=n))
    snap = draw(st.booleans())
    cx, cy = draw(st.floats(20.0, 40.0)), draw(st.floats(20.0, 40.0))
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    outer = np.c_[cx + np.array(radii) * np.cos(t), cy + np.array(radii) * np.sin(t)]
    holes = []
    for _ in range(draw(st.integers(0, 2))):
        hx = draw(st.floats(-3.0, 3.0))
        hy = draw(st.floats(-3.0, 3.0))
        hr = draw(st.floats(1.5, 4.5))
        k = draw(st.integers(3, 7))
        u = np.linspace(0, 2 * np.pi, k, endpoint=False) + draw(st.floats(0, 1))
        holes.append(np.c_[cx + hx + hr * np.cos(u), cy + hy + hr * np.sin(u)])
    if snap:
        outer = np.round(outer * 2) / 2
        holes = [np.round(h * 2) / 2 for h in holes]
    geom = shapely.Polygon(outer)
    for h in holes:
        geom = geom.difference(shapely.Polygon(h))
    geom = shapely.make_valid(geom)
    geom = shapely.union_all([g for g in shapely.get_parts(geom) if g.geom_type == "Polygon"])
    return geom


@settings(max_examples=40, deadline=None)
@given(holed_polygons())
def test_field_occupancy_equals_a_brute_force_inside_test(geom):
    if geom.is_empty:
        return
    field = DistanceField(Region.rectangle(60, 60), CELL)
    free0 = field.d > 0
    field.dmax = 1e6  # a window over the whole raster
    field.occupy([geom])
    segs, _ = _segments([geom])
    r, c = np.mgrid[0:field.rows, 0:field.cols]
    px = field.x0 + (c + 0.5) * CELL
    py = field.y0 + (r + 0.5) * CELL
    inside = _brute_inside(px, py, segs)
    zero = field.d == 0
    assert np.all(zero[inside])
    # elsewhere a 0 only on the boundary (distance 0), and never more than the exact
    # distance to the polygon
    out = ~inside & free0
    exact = shapely.distance(geom, shapely.points(px[out], py[out]))
    assert np.all(exact[zero[out]] <= 1e-9)
    assert np.all(field.d[out] <= exact + 1e-9)


@settings(max_examples=40, deadline=None)
@given(holed_polygons(), st.floats(0.0, 2 * np.pi), st.floats(0.5, 1.5), st.booleans())
def test_posed_occupancy_equals_a_brute_force_inside_test(geom, angle, scale, torus_pixels):
    if geom.is_empty:
        return
    # the kind's rings in local coordinates about the polygon's centre, posed at (tx, ty)
    cx, cy = geom.centroid.x, geom.centroid.y
    local = shapely.affinity.translate(geom, -cx, -cy)
    lsegs, _ = _segments([local])
    lbb = np.array(local.bounds)
    c, sn = scale * np.cos(angle), scale * np.sin(angle)
    tx, ty = 30.0 + 0.25, 30.0 - 0.25
    segs = np.c_[tx + c * lsegs[:, 0] - sn * lsegs[:, 1], ty + sn * lsegs[:, 0] + c * lsegs[:, 1],
                 tx + c * lsegs[:, 2] - sn * lsegs[:, 3], ty + sn * lsegs[:, 2] + c * lsegs[:, 3]]
    segs = np.ascontiguousarray(segs)
    bounds = np.array([min(segs[:, 0].min(), segs[:, 2].min()), min(segs[:, 1].min(), segs[:, 3].min()),
                       max(segs[:, 0].max(), segs[:, 2].max()), max(segs[:, 1].max(), segs[:, 3].max())])
    cell_y = 0.9 * CELL if torus_pixels else CELL  # a repeat tile's pixels need not be square
    rows, cols = int(60 / cell_y), 60
    d = np.full((rows, cols), 1e6)
    _occupy_posed(d, 0.0, 0.0, CELL, cell_y, segs, bounds, 1e6, tx, ty, c, sn, lbb)
    r, cc = np.mgrid[0:rows, 0:cols]
    px = (cc + 0.5) * CELL
    py = (r + 0.5) * cell_y
    inside = _brute_inside(px, py, segs)
    assert np.all(d[inside] == 0)
    world = shapely.MultiLineString([[(a, b), (e, f)] for a, b, e, f in segs])
    exact = shapely.distance(world, shapely.points(px[~inside], py[~inside]))
    np.testing.assert_allclose(d[~inside], exact, rtol=0, atol=1e-9)

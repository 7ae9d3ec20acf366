"""The fill-gap distance field's compiled set-up (strew.pack._field) and the engine's
per-kind set-up (strew.pack._fit): they agree with scipy and shapely."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from scipy import ndimage

from strew import Region
from strew.pack._field import DistanceField, _edt, _scan_fill, _segments
from strew.pack._fit import _interior_grid

REGIONS = {
    "rectangle": Region.rectangle(60, 52),
    "disk with a hole": Region(shapely.Point(0, 0).buffer(40, 16).difference(shapely.Point(8, 4).buffer(15, 7))),
    "two parts": Region(shapely.MultiPolygon([shapely.box(0, 0, 10, 10), shapely.box(20.3, 0, 50, 33.3)])),
    "concave": Region(shapely.Polygon([(0, 0), (50, 0), (50, 40), (30, 40), (30, 12), (18, 12), (18, 40), (0, 40)])),
}


@pytest.mark.parametrize("seed", range(20))
def test_edt_equals_scipy_with_an_obstacle_frame(seed):
    rng = np.random.default_rng(seed)
    rows, cols = rng.integers(1, 50, 2)
    free = rng.random((rows, cols)) < rng.uniform(0.3, 1.0)
    ref = ndimage.distance_transform_edt(np.pad(free, 1))[1:-1, 1:-1]
    ref[~free] = 0.0
    assert np.array_equal(_edt(free), ref)


@pytest.mark.parametrize("name", list(REGIONS))
@pytest.mark.parametrize("cell", [0.77, 1.3, 3.11])
def test_field_free_pixels_are_the_region_raster(name, cell):
    region = REGIONS[name]
    mask, (x0, y0, c) = region.rasterize(cell)
    field = DistanceField(region, cell)
    assert (field.x0, field.y0, field.cell) == (x0, y0, c)
    assert np.array_equal(field.d > 0, mask)
    # and the initial field is scipy's transform of that raster
    ref = ndimage.distance_transform_edt(np.pad(mask, 1))[1:-1, 1:-1] * cell
    ref[~mask] = 0.0
    assert np.allclose(field.d, ref, rtol=0, atol=1e-12)


def test_scanline_fill_clears_pixels_inside_placed_regions():
    rng = np.random.default_rng(3)
    geoms = [shapely.Point(x, y).buffer(r, 5).difference(shapely.Point(x, y).buffer(r / 2, 4))
             for x, y, r in rng.uniform([5, 5, 2], [55, 45, 7], size=(15, 3))]
    cell = 0.9
    region = REGIONS["rectangle"]
    field = DistanceField(region, cell, geoms)
    rows, cols = field.d.shape
    gy, gx = np.mgrid[0:rows, 0:cols]
    px, py = field.x0 + (gx + 0.5) * cell, field.y0 + (gy + 0.5) * cell
    covered = np.zeros((rows, cols), dtype=bool)
    for g in geoms:  # holes of the rings stay free
        covered |= shapely.contains_xy(g, px, py)
    assert not np.any((field.d > 0) & covered)
    # pixels that no region covers (and not on an outline) stay free
    near = np.zeros_like(covered)
    for g in geoms:
        near |= shapely.dwithin(shapely.boundary(g), shapely.points(px, py), 1e-9)
    assert np.all((field.d > 0) | covered | near)
    # a direct fill agrees too
    free = np.ones((rows, cols), dtype=bool)
    segs, off = _segments(geoms)
    _scan_fill(free, field.x0, field.y0, cell, segs, off, False)
    assert np.array_equal(free, field.d > 0)


def test_field_never_exceeds_the_distance_to_obstacles():
    region = REGIONS["disk with a hole"]
    field = DistanceField(region, 1.1)
    free = np.argwhere(field.d > 0)
    pts = shapely.points(field.x0 + (free[:, 1] + 0.5) * 1.1, field.y0 + (free[:, 0] + 0.5) * 1.1)
    exact = shapely.distance(shapely.boundary(region.geometry), pts)
    assert np.all(field.d[free[:, 0], free[:, 1]] >= exact - 1e-9)


@pytest.mark.parametrize("geom", [
    shapely.Polygon([(-15, -15), (15, -15), (15, -7), (-5, -7), (-5, 7), (15, 7), (15, 15), (-15, 15)]),
    shapely.Point(0, 0).buffer(9, 8).difference(shapely.Point(1, 0).buffer(5, 8)),
    shapely.MultiPolygon([shapely.box(0, 0, 3, 3), shapely.box(5, 0, 9, 2)]),
])
def test_interior_grid_agrees_with_shapely(geom):
    pts, clear = _interior_grid(geom)
    assert len(pts) > 10
    assert np.all(shapely.contains_xy(geom, pts[:, 0], pts[:, 1]))
    assert np.allclose(clear, shapely.distance(shapely.boundary(geom), shapely.points(pts)), rtol=0, atol=1e-9)


def test_candidate_draw_is_bernoulli_alpha_per_pixel():
    """Block-bounded geometric skips give the same law: pixel i joins Q with (e/emax)**n."""
    from strew.pack._draw import BLOCK, _block_max, _draw_q

    power = 16.0
    # levels from the maximum down to just above the cut, spread over blocks of every kind
    # (a block holding the maximum, blocks far below it, partial blocks at the edges)
    levels = np.r_[1.0, 0.97, 0.9, 0.8, 0.77, 0.7, 0.6, 0.5]
    rows, cols = 3 * BLOCK + 3, 4 * BLOCK + 5
    rng = np.random.default_rng(0)
    d = levels[rng.integers(0, len(levels), (rows, cols))]
    # blocks at several heights below the maximum: read in full, thinned by skips
    scale = rng.choice([1.0, 0.95, 0.85, 0.75], size=((rows + BLOCK - 1) // BLOCK, (cols + BLOCK - 1) // BLOCK))
    d = d * np.kron(scale, np.ones((BLOCK, BLOCK)))[:rows, :cols]
    d[:BLOCK, :BLOCK] = 1.0  # the maximum
    d[rng.random((rows, cols)) < 0.1] = 0.0  # obstacles
    w = np.where(rng.random((rows, cols)) < 0.2, 0.95, 1.0)  # some suppression
    e = d * w
    emax = e.max()
    alpha = np.where(e > 0.3, (e / emax) ** power, 0.0)
    nb = ((rows + BLOCK - 1) // BLOCK) * ((cols + BLOCK - 1) // BLOCK)
    bme, bmd = np.zeros(nb), np.zeros(nb)
    _block_max(d, w, bme, bmd, 0, (rows + BLOCK - 1) // BLOCK, 0, (cols + BLOCK - 1) // BLOCK)
    assert bme.max() == emax and bmd.max() == d.max()
    from strew.pack._fit import rand_state

    gen = rand_state(np.random.default_rng(5))
    qbuf = np.zeros(d.size, dtype=np.int64)
    hits = np.zeros(d.size)
    trials = 3000
    for _ in range(trials):
        n = _draw_q(gen, d, w, bme, 0.3, emax, power, qbuf)
        assert len(np.unique(qbuf[:n])) == n
        hits[qbuf[:n]] += 1
    flat = alpha.ravel()
    assert np.all(hits[flat == 0] == 0)  # obstacles and pixels at or below the cut
    # per level, the number of picks matches alpha within 5 sigma (and a few picks of
    # slack where the expected count is tiny)
    for a in np.unique(flat[flat > 0]):
        sel = flat == a
        count, expect = hits[sel].sum(), a * sel.sum() * trials
        assert abs(count - expect) <= 5 * np.sqrt(expect * (1 - a)) + 3, (a, count, expect)


def test_posed_update_equals_the_plain_update():
    """The oriented-box skip of _occupy_posed changes no value that _occupy would set."""
    from strew.pack._field import _occupy, _occupy_posed

    leaf = shapely.Polygon(np.c_[12 * np.cos(np.linspace(0, 2 * np.pi, 24, endpoint=False)),
                                 2.5 * np.sin(np.linspace(0, 2 * np.pi, 24, endpoint=False))])
    hook = shapely.Polygon([(-15, -15), (15, -15), (15, -7), (-5, -7), (-5, 7), (15, 7), (15, 15), (-15, 15)])
    rng = np.random.default_rng(1)
    region = REGIONS["rectangle"]
    for body in (leaf, hook):
        a = DistanceField(region, 0.7)
        b = DistanceField(region, 0.7)
        lbb = np.array(body.bounds)
        local = shapely.get_coordinates(body.exterior)
        for _ in range(8):
            t, s = rng.uniform(0, 2 * np.pi), rng.uniform(0.2, 0.6)
            tx, ty = rng.uniform(5, 55), rng.uniform(5, 47)
            c, sn = s * np.cos(t), s * np.sin(t)
            ring = local @ np.array([[c, sn], [-sn, c]]) + (tx, ty)
            segs = np.ascontiguousarray(np.c_[ring[:-1], ring[1:]])
            bb = np.r_[ring.min(axis=0), ring.max(axis=0)]
            grow = max(a.d.max(), b.d.max()) + 0.7
            _occupy(a.d, a.x0, a.y0, 0.7, segs, np.array([0, len(segs)]), bb[None], grow)
            _occupy_posed(b.d, b.x0, b.y0, 0.7, 0.7, segs, bb, grow, tx, ty, c, sn, lbb)
            assert np.allclose(a.d, b.d, rtol=0, atol=1e-12)
        assert (a.d == 0).sum() > (DistanceField(region, 0.7).d == 0).sum()  # regions were marked

"""The shared kernel floor (strew._kernels, issue 15 point 5) against references:
segment distance and intersection against shapely, the scanline rasteriser against
shapely's point tests and areas, the EDT against scipy, the grids against brute force,
and the compiled stream's determinism and range."""

from __future__ import annotations

import numba
import numpy as np
import shapely
from hypothesis import given
from hypothesis import strategies as st
from scipy import ndimage

from strew._kernels import geometry, grid, prng, raster

# coordinates with at most 6 decimals: shapely squares distances, and a gap of 1e-172
# underflows to a contact there
coord = st.floats(-50, 50, allow_nan=False, allow_infinity=False).map(lambda v: round(v, 6))
point = st.tuples(coord, coord)


# the predicates carry no Python wrapper (issue 16): tests call them through these
@numba.njit
def _seg_dist2(p, a, b):  # pragma: no cover - numba
    return geometry.seg_dist2(p[0], p[1], a[0], a[1], b[0], b[1])


@numba.njit
def _seg_dist2_min(p, segs):  # pragma: no cover - numba
    n = len(segs)
    ax, ay, ex, ey, il2 = np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    for k in range(n):
        ax[k], ay[k] = segs[k, 0], segs[k, 1]
        ex[k], ey[k] = segs[k, 2] - segs[k, 0], segs[k, 3] - segs[k, 1]
        l2 = ex[k] * ex[k] + ey[k] * ey[k]
        il2[k] = 1.0 / l2 if l2 > 0.0 else 0.0
    return geometry.seg_dist2_min(p[0], p[1], ax, ay, ex, ey, il2, np.inf)


@numba.njit
def _seg_hit(s, t):  # pragma: no cover - numba
    return geometry.seg_hit(s[0], s[1], s[2], s[3], t[0], t[1], t[2], t[3])


@numba.njit
def _seg_cross(s, t):  # pragma: no cover - numba
    return geometry.seg_cross(s[0], s[1], s[2], s[3], t[0], t[1], t[2], t[3])


@numba.njit
def _where(p, v, rings):  # pragma: no cover - numba
    return geometry.where(p[0], p[1], v, rings, 0, len(rings) - 1), geometry.inside(p[0], p[1], v, rings, 0, len(rings) - 1)


@numba.njit
def _stream(state, n):  # pragma: no cover - numba
    out = np.empty(n)
    for i in range(n):
        out[i] = prng.uniform(state)
    return out


@given(point, point, point)
def test_segment_distance_matches_shapely(p, a, b):
    line = shapely.LineString([a, b]) if a != b else shapely.Point(a)
    ref = shapely.distance(shapely.Point(p), line)
    d = np.sqrt(_seg_dist2(np.array(p), np.array(a), np.array(b)))
    assert abs(d - ref) <= 1e-9 * (1 + ref)
    segs = np.array([[*a, *b], [*b, *p]])
    both = np.sqrt(_seg_dist2_min(np.array(p), segs[:1]))
    assert abs(both - ref) <= 1e-9 * (1 + ref)


@given(point, point, point, point)
def test_segment_intersection_never_misses_a_contact(a, b, c, d):
    s, t = np.array([*a, *b]), np.array([*c, *d])
    hit = _seg_hit(s, t)
    ab, cd = shapely.LineString([a, b]), shapely.LineString([c, d])
    if a == b or c == d:
        return  # degenerate segments: shapely's LineString needs two distinct points
    gap = shapely.distance(ab, cd)
    if gap == 0.0:
        assert hit  # touching and crossing count: a contact is never missed
    elif gap > 1e-6 * (1 + max(map(abs, (*a, *b, *c, *d)))):
        assert not hit  # clearly apart: no false alarm beyond the tolerance


small = st.tuples(st.integers(-4, 4), st.integers(-4, 4)).map(lambda p: (float(p[0]), float(p[1])))


@given(small, small, small, small)
def test_strict_crossing_is_shapely_crosses_on_exact_coordinates(a, b, c, d):
    """On small integers every orientation is exact: the strict rule (Ijiri et al.
    Fig. 6 (d)) says yes exactly when the segments cross at one point interior to both;
    touching, an end on the other segment and collinear overlap are no."""
    if a == b or c == d:
        return
    ab, cd = shapely.LineString([a, b]), shapely.LineString([c, d])
    one_point = ab.intersection(cd).geom_type == "Point"
    interior = one_point and all(shapely.Point(p) != ab.intersection(cd) for p in (a, b, c, d))
    assert _seg_cross(np.array([*a, *b]), np.array([*c, *d])) == interior
    assert _seg_cross(np.array([*c, *d]), np.array([*a, *b])) == interior


@given(point, point, point, point)
def test_strict_crossing_matches_the_growth_rule_and_never_touches(a, b, c, d):
    from strew.grow._growth import _segments_cross

    s, t = np.array([*a, *b]), np.array([*c, *d])
    cross = _seg_cross(s, t)
    assert cross == _segments_cross(a, b, c, d)  # the same arithmetic as the grower's oracle
    if cross:
        assert _seg_hit(s, t)  # a crossing is a contact for the lenient rule too
    if a != b and c != d:
        ab, cd = shapely.LineString([a, b]), shapely.LineString([c, d])
        scale = 1 + max(map(abs, (*a, *b, *c, *d)))
        if cross:  # never a false alarm beyond rounding
            assert shapely.distance(ab, cd) <= 1e-9 * scale
        # clearly crossing, away from every end: found
        if ab.crosses(cd) and ab.intersection(cd).geom_type == "Point":
            x = ab.intersection(cd)
            if min(x.distance(shapely.Point(p)) for p in (a, b, c, d)) > 1e-6 * scale:
                assert cross


polygons = st.lists(point, min_size=3, max_size=9).map(lambda pts: shapely.Polygon(pts).buffer(0)).filter(
    lambda g: not g.is_empty and g.area > 1.0
)


def _layout(geom):
    v, rings = [], [0]
    for ring in shapely.get_rings(shapely.get_parts(geom)):
        xy = shapely.get_coordinates(ring)
        v.append(xy)
        rings.append(rings[-1] + len(xy))
    return np.ascontiguousarray(np.concatenate(v)), np.asarray(rings, dtype=np.int64)


@given(polygons, st.lists(point, min_size=1, max_size=20))
def test_point_in_rings_matches_shapely(poly, pts):
    v, rings = _layout(poly)
    for p in pts:
        w, ins = _where(np.array(p), v, rings)
        if shapely.distance(poly.boundary, shapely.Point(p)) > 1e-6:
            assert ins == bool(shapely.contains_xy(poly, *p))
            assert w == int(ins)


def _segments(geom):
    segs = []
    for ring in shapely.get_rings(shapely.get_parts(geom)):
        xy = shapely.get_coordinates(ring)
        segs.append(np.c_[xy[:-1], xy[1:]])
    s = np.ascontiguousarray(np.concatenate(segs))
    return s, np.array([0, len(s)], dtype=np.int64)


@given(polygons, st.floats(0.3, 4.0))
def test_scanline_fill_matches_shapely(poly, cell):
    x0, y0, x1, y1 = poly.bounds
    x0, y0 = x0 - 2 * cell, y0 - 2 * cell
    cols, rows = int((x1 - x0) / cell) + 3, int((y1 - y0) / cell) + 3
    mask = np.zeros((rows, cols), dtype=np.bool_)
    segs, off = _segments(poly)
    raster.scan_fill(mask, x0, y0, cell, segs, off, True)
    gx, gy = np.meshgrid(x0 + (np.arange(cols) + 0.5) * cell, y0 + (np.arange(rows) + 0.5) * cell)
    ref = shapely.contains_xy(poly, gx, gy)
    near = shapely.distance(poly.boundary, shapely.points(gx, gy)) <= 1e-9 * (1 + abs(gx) + abs(gy))
    assert np.array_equal(mask[~near], ref[~near])  # centres on the boundary: either side
    # the area of the filled pixels approaches the polygon's (each boundary pixel errs
    # by at most its own area)
    edge_pixels = poly.boundary.length / cell * 2 + 4
    assert abs(mask.sum() * cell * cell - poly.area) <= edge_pixels * cell * cell
    # the cell list of one outline is the same set, in raster order
    if len(shapely.get_rings(poly)) == 1:
        outline = np.ascontiguousarray(shapely.get_coordinates(poly.exterior)[:-1])
        cells = raster.scan_cells(rows, cols, x0, y0, cell, outline)
        assert np.array_equal(cells, np.flatnonzero(mask))


@given(st.integers(1, 40), st.integers(1, 40), st.floats(0.0, 0.9), st.integers(0, 2**31))
def test_edt_matches_scipy(rows, cols, density, seed):
    free = np.random.default_rng(seed).random((rows, cols)) >= density
    ref = ndimage.distance_transform_edt(np.pad(free, 1))[1:-1, 1:-1]
    assert np.array_equal(raster.edt(free), ref)
    aniso = raster.edt_aniso(free, 1.0, 1.0)
    assert np.allclose(aniso, ref)


@given(st.lists(point, min_size=1, max_size=60), point, st.floats(0.0, 30.0), st.floats(0.5, 20.0), st.booleans())
def test_bucket_grid_query_matches_brute_force(pts, q, reach, cell, reverse):
    p = np.array(pts, dtype=float)
    x0, y0, c, nx, ny, head, nxt = grid.bucket_grid(p, cell, np.int64(1), np.bool_(reverse))
    assert c >= cell and nx * ny >= 1
    found = []
    for i in range(max(int((q[0] - reach - x0) / c), 0), min(int((q[0] + reach - x0) / c), nx - 1) + 1):
        for j in range(max(int((q[1] - reach - y0) / c), 0), min(int((q[1] + reach - y0) / c), ny - 1) + 1):
            k = head[i * ny + j]
            bucket = []
            while k >= 0:
                bucket.append(k)
                k = nxt[k]
            assert bucket == sorted(bucket, reverse=not reverse)
            found += [k for k in bucket if np.hypot(*(p[k] - q)) <= reach]
    ref = np.flatnonzero(np.hypot(p[:, 0] - q[0], p[:, 1] - q[1]) <= reach)
    assert sorted(found) == ref.tolist()


@given(st.integers(0, 2**63 - 1))
def test_stream_is_determined_by_the_generator_and_in_range(seed):
    s1 = prng.seed_state(np.random.default_rng(seed))
    s2 = prng.seed_state(np.random.default_rng(seed))
    assert s1.dtype == np.uint64 and s1.shape == (4,) and np.all(s1 > 0)
    a, b = _stream(s1, 2000), prng.uniforms(s2, 2000)
    assert np.array_equal(a, b)  # the same generator state gives the same stream
    assert np.array_equal(s1, s2)  # and leaves the same state
    assert a.min() >= 0.0 and a.max() < 1.0
    other = _stream(prng.seed_state(np.random.default_rng(seed + 1)), 2000)
    assert not np.array_equal(a, other)


def test_stream_is_uniform():
    u = prng.uniforms(prng.seed_state(np.random.default_rng(0)), 200_000)
    counts = np.bincount((u * 20).astype(int), minlength=20)
    chi2 = float(((counts - 10_000) ** 2 / 10_000).sum())
    assert chi2 < 45.3  # 19 degrees of freedom, p = 0.001
    assert abs(np.corrcoef(u[:-1], u[1:])[0, 1]) < 0.01

"""Mappers' built-ins (Table 3), utilities (Table 5) and stationarity (§6.1)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

import strew
from strew.program import *
from strew.program import Curve, Curves, induce

pi = math.pi
coord = st.floats(-100, 100, allow_nan=False)
point = st.tuples(coord, coord)


@settings(max_examples=50, deadline=None)
@given(point, point, point, point)
def test_match_points_maps_s1_to_t1_and_s2_to_t2(s1, s2, t1, t2):
    s1, s2, t1, t2 = map(np.array, (s1, s2, t1, t2))
    if np.linalg.norm(s2 - s1) < 1e-3:
        return
    c = Curves.polyline([s1, (s1 + s2) / 2 + (1, 2), s2], named={"a": s1, "b": s2})
    m = match_points(c, s1, s2, t1, t2)
    tol = 1e-6 * (1 + np.abs(np.r_[t1, t2]).max()) * (1 + np.linalg.norm(t2 - t1) / np.linalg.norm(s2 - s1))
    assert np.allclose(point_labeled(m, "a"), t1, atol=tol)
    assert np.allclose(point_labeled(m, "b"), t2, atol=tol)
    assert np.allclose(m.curves[0].points[0], t1, atol=tol) and np.allclose(m.curves[0].points[-1], t2, atol=tol)
    # a similarity: shape preserved up to the scale |t2 - t1| / |s2 - s1|
    k = np.linalg.norm(t2 - t1) / np.linalg.norm(s2 - s1)
    p, q = c.curves[0].points, m.curves[0].points
    assert np.isclose(np.linalg.norm(q[1] - q[0]), k * np.linalg.norm(p[1] - p[0]), rtol=1e-6, atol=tol)


def test_match_point_match_face_and_transforms():
    c = Curves.polygon([(0, 0), (4, 0), (4, 2), (0, 2)])
    m = match_point(c, (0, 0), (10, 10))
    assert m.bbox == (10, 10, 14, 12)
    assert np.allclose(bbox_center(scale(c, 2)), bbox_center(c)) and bbox_width(scale(c, 2)) == 8
    r = rotate(c, pi / 2)
    assert np.isclose(bbox_width(r), 2) and np.isclose(bbox_height(r), 4) and np.allclose(bbox_center(r), (2, 1))
    assert translate(c, (1, -1)).bbox == (1, -1, 5, 1)
    (f,) = induce(Curves.polygon([(0, 0), (100, 0), (100, 50), (0, 50)])).bounded_faces
    fit = match_face(c, f)
    assert np.allclose(fit.bbox, (0, 0, 100, 50))
    assert len(nothing()) == 0 and len(append(c, m)) == 2


def test_geometry_builtins():
    pm = induce(Curves((Curve([(0, 0), (10, 0), (10, 10)], labels="L"), Curve([(0, 0), (10, 10)]))))
    (f,) = pm.bounded_faces
    assert np.allclose(centroid(f), (20 / 3, 10 / 3))
    (e,) = [e for e in pm.edges if has_label(e, "L")]
    assert np.allclose(location_at(e, 0.0), (0, 0)) and np.allclose(location_at(e, 0.25), (5, 0))
    assert np.allclose(location_at(e, 0.75), (10, 5)) and np.allclose(location_at(e, 1), (10, 10))
    assert np.isclose(shapely.Polygon(np.concatenate([c.points for c in contour(f)])).area, 50)
    curve = to_curve(e)
    assert curve.curves[0].labels == {"L"} and np.allclose(curve.curves[0].points, e.points)
    assert has_label([e, f], "L") and not has_label(f, "L")
    with pytest.raises(strew.InputError, match="location_at: s must be in"):
        location_at(e, 2)
    with pytest.raises(strew.InputError, match="centroid: the unbounded face"):
        centroid(pm.unbounded_face)
    with pytest.raises(strew.InputError, match="source_vertex: expected an edge"):
        source_vertex(f)


def test_labelled_points_and_curves():
    c = Curves((Curve([(0, 0), (1, 0)], labels="stem"), Curve([(0, 0), (0, 1)], labels="leaf")), {"start": (0, 0)})
    assert np.allclose(point_labeled(c, "start"), (0, 0))
    assert len(curve_labeled(c, "leaf")) == 1 and curve_labeled(c, "leaf").curves[0].labels == {"leaf"}
    with pytest.raises(strew.InputError, match="no point labelled 'end' \\(have: start\\)"):
        point_labeled(c, "end")
    with pytest.raises(strew.InputError, match="no curve labelled 'root'"):
        curve_labeled(c, "root")


def _grid(w=50, theta=0.0):
    return grid_partition(stripes_properties(theta, w), stripes_properties(theta + pi / 2, w), KEEP_INSIDE)


def test_cell_random_is_deterministic_and_order_independent():
    pm = _grid()(400, seed=1)
    faces = pm.bounded_faces

    def values(cells, seed):
        # the per-cell random values as seen from a mapper, run in some order
        out = {}

        def m(face):
            out[tuple(np.round(centroid(face), 6))] = (random(face, 0, 1, 0), random(face, 0, 1, 1))
            return nothing()

        map_to_faces(m, cells)(400, seed=seed)
        return out

    a = values(_grid(), 1)
    b = values(_grid(), 1)
    assert a == b and len(a) == len(faces) == 64
    # the order of cells does not matter: reversed map, same values per cell
    rev = values(Curves(tuple(reversed(pm.curves.curves))), 1)
    assert rev == a
    # n changes the value, a different seed changes all of them
    assert all(v[0] != v[1] for v in a.values())
    c = values(_grid(), 2)
    assert all(c[k] != a[k] for k in a)
    # uniform in [0, 1)
    vals = np.array([v[0] for v in a.values()])
    assert 0 <= vals.min() and vals.max() < 1 and 0.3 < vals.mean() < 0.7


def test_a_cell_gets_the_same_result_wherever_it_lies():
    # §6.1: the mapper sees its cell only; an interior cell of a small and of a large
    # domain is the same cell, and gets the same output (random values included)
    def m(face):
        c = rotate(scale(contour(face), random(face, 0.3, 0.9, 0)), random(face, 0, pi, 1))
        return append(c, translate(c, (random(0, 1), 0)))

    small = map_to_faces(m, _grid())(200, seed=5)
    large = map_to_faces(m, _grid())(600, seed=5)
    key = lambda c: np.round(c.points, 6).tobytes()  # noqa: E731
    small_set = {key(c) for c in small.curves}
    large_set = {key(c) for c in large.curves}
    assert len(small_set) == 16 * 4 * 2  # 16 cells, 4 sides, 2 copies: every curve of the small run...
    assert small_set <= large_set  # ...appears, identical, in the large run
    # a mapper without randomness is translation covariant
    plain = map_to_faces(lambda f: scale(contour(f), 0.5), _grid())
    a = plain(shapely.box(0, 0, 200, 200))
    b = plain(shapely.box(100, 0, 300, 200))
    sa = {np.round(c.points + (100, 0), 6).tobytes() for c in a.curves}
    sb = {np.round(c.points, 6).tobytes() for c in b.curves}
    assert sa == sb and len(sa) == 16 * 4  # the same 16 cells, moved by the shift


def test_plain_random_is_repeatable_per_seed():
    def m(face):
        return translate(contour(face), (random(0, 10), random(0, 10)))

    a = map_to_faces(m, _grid())(200, seed=4).curves
    b = map_to_faces(m, _grid())(200, seed=4).curves
    c = map_to_faces(m, _grid())(200, seed=5).curves
    pts = lambda cs: np.concatenate([x.points for x in cs])  # noqa: E731
    assert np.array_equal(pts(a), pts(b)) and not np.array_equal(pts(a), pts(c))
    with pytest.raises(strew.InputError, match="random: expected random"):
        random(1, 2, 3)


def test_mapper_errors_name_mapper_file_and_line():
    def bad(face):
        return 1 / 0

    with pytest.raises(strew.InputError, match=r"test_program_builtins.py line \d+, in mapper bad: ZeroDivisionError"):
        map_to_faces(bad, _grid())(100)
    with pytest.raises(strew.InputError, match="mapper wrong: returned int"):

        def wrong(face):
            return 3

        map_to_faces(wrong, _grid())(100)
    with pytest.raises(strew.InputError, match="returned None"):
        map_to_edges(lambda e: None, _grid())(100)

"""The transform convention of DESIGN.md: p_world = (x, y) + s R(t) p_local, y-down."""

from __future__ import annotations

import numpy as np
import shapely
from strew_testing import angles, finite, scales
from hypothesis import given
from hypothesis import strategies as st

from strew import Arrangement, Shape
from strew.arrangement import transform_points


def svg_matrix(x: float, y: float, t: float, s: float) -> np.ndarray:
    """translate(x y) rotate(deg t) scale(s) composed as SVG does (left to right)."""
    T = np.array([[1, 0, x], [0, 1, y], [0, 0, 1.0]])
    c, sn = np.cos(t), np.sin(t)
    R = np.array([[c, -sn, 0], [sn, c, 0], [0, 0, 1.0]])
    S = np.diag([s, s, 1.0])
    return T @ R @ S


@given(finite, finite, angles, scales, st.lists(st.tuples(finite, finite), min_size=3, max_size=8))
def test_transform_points_matches_svg_matrix(x, y, t, s, pts):
    p = np.array(pts, dtype=float)
    m = svg_matrix(x, y, t, s)
    expected = (m @ np.c_[p, np.ones(len(p))].T).T[:, :2]
    np.testing.assert_allclose(transform_points(p, x, y, t, s), expected, rtol=1e-9, atol=1e-6)


@given(st.lists(st.tuples(finite, finite, angles, scales), min_size=1, max_size=10))
def test_world_geometry_follows_convention(rows):
    local = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.5, 1.5]])
    shape = Shape.polygon(local)
    xs, ys, ts, ss = (np.array(c, dtype=float) for c in zip(*rows))
    arr = Arrangement({"q": shape}, [0] * len(rows), xs, ys, ts, ss)
    for i, g in enumerate(arr.geometry):
        ring = np.asarray(g.exterior.coords)[:-1]
        expected = transform_points(local, xs[i], ys[i], ts[i], ss[i])
        # shapely may reorder a ring's start but not for a valid, simple input like this
        np.testing.assert_allclose(ring, expected, rtol=1e-9, atol=1e-6)


def test_positive_rotation_is_clockwise_on_screen():
    # y points down: rotating +90 degrees takes the local +x axis to world +y (downwards).
    out = transform_points(np.array([[1.0, 0.0]]), 0, 0, np.pi / 2, 1)
    np.testing.assert_allclose(out, [[0.0, 1.0]], atol=1e-12)


def test_geometry_of_mixed_kinds_keeps_element_order():
    arr = Arrangement(
        {"a": Shape.rectangle(1, 1), "b": Shape.circle(1)},
        ["b", "a", "b", "a"],
        [0, 10, 20, 30],
        [0, 0, 0, 0],
    )
    cx = shapely.get_x(shapely.centroid(arr.geometry))
    np.testing.assert_allclose(cx, [0, 10, 20, 30], atol=1e-9)
    assert shapely.area(arr.geometry[1]) == 1.0

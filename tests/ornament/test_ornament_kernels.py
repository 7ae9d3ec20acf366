"""The framework's numba kernels (issue 16 rewrites): the scalar 3 x 3 solve and the
one-pass cover of polylines."""

import numpy as np
from hypothesis import example, given
from hypothesis import strategies as st

from strew.ornament._raster import _solve3, climb, cover_polygon, cover_polyline

finite = st.floats(-10, 10, allow_nan=False)


@given(st.lists(finite, min_size=12, max_size=12))
@example([0.0, 0.0, 0.0, 1.1125369292536007e-308, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0])
def test_solve3_solves_or_reports_a_singular_system(v):
    a = np.array(v[:9]).reshape(3, 3)
    b = np.array(v[9:])
    ok, *x = _solve3(*a.ravel().tolist(), *b.tolist())
    # the reference determinant of a subnormal entry underflows in LAPACK (a RuntimeWarning,
    # an error under the suite's filterwarnings): the reference, not _solve3, warned
    with np.errstate(all="ignore"):
        det = np.linalg.det(a)
    if ok:
        assert np.allclose(a @ np.array(x), b, atol=1e-6 * max(1.0, np.abs(b).max()) / max(1e-3, min(1.0, abs(det))))
    else:
        assert abs(det) < 1e-9 or not np.isfinite(det)


@given(st.lists(st.tuples(st.floats(0, 40), st.floats(0, 40)), min_size=1, max_size=6), st.floats(0.2, 3))
def test_cover_polyline_holds_exactly_the_cells_within_pad(pts, pad):
    pts = np.array(pts, dtype=float)
    rows = cols = 48
    got = np.unique(cover_polyline(rows, cols, 0.0, 0.0, 1.0, pts, pad))
    ii, jj = np.divmod(np.arange(rows * cols), cols)
    c = np.c_[jj + 0.5, ii + 0.5]
    segs = np.c_[pts[:-1], pts[1:]] if len(pts) > 1 else np.c_[pts, pts]
    d = np.full(len(c), np.inf)
    for ax, ay, bx, by in segs:
        ab = np.array([bx - ax, by - ay])
        ll = ab @ ab
        t = np.clip(((c - [ax, ay]) @ ab) / ll, 0, 1) if ll > 0 else np.zeros(len(c))
        d = np.minimum(d, np.hypot(*(c - ([ax, ay] + t[:, None] * ab)).T))
    want = np.flatnonzero(d <= pad - 1e-9)
    edge = np.flatnonzero(np.abs(d - pad) <= 1e-9)
    assert set(want) <= set(got) <= set(want) | set(edge)
    if len(pts) >= 3:
        cover_polygon(rows, cols, 0.0, 0.0, 1.0, pts)  # runs on any outline, even a self-crossing one


def test_climb_reaches_the_point_equidistant_from_three_discs():
    circ = np.array([[0.0, 0.0, 1.0], [10.0, 0.0, 1.0], [5.0, 8.0, 1.0]])
    x, y, v = climb(4.0, 3.0, circ, np.zeros((0, 4)), 0.5, 1e-4, 100.0)
    d = np.hypot(circ[:, 0] - x, circ[:, 1] - y) - circ[:, 2]
    assert np.ptp(d) < 1e-6 and abs(v - d.min()) < 1e-9

"""grow's compiled certificate of a large overlap (``_overlap_kernels.overlap_certain``)
and the overlap test built on it (``_collide._big_overlaps``): never True where the
GEOS overlay's area is at most ``1e-9`` of the first polygon's, and the test's answers
the overlay's, pair for pair (issue 14 point 5, speed; byte-identical output)."""

from __future__ import annotations

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st


def _star(rng, n, cx, cy, r):
    """A simple polygon: n vertices at sorted angles and random radii (often not convex)."""
    t = np.sort(rng.uniform(0, 2 * np.pi, n))
    rr = r * rng.uniform(0.3, 1.0, n)
    return shapely.Polygon(np.c_[cx + rr * np.cos(t), cy + rr * np.sin(t)])


def _overlay(A, B):
    return shapely.area(shapely.intersection(A, B)) > 1e-9 * np.maximum(shapely.area(A), 1e-300)


def _pairs(seed, m):
    rng = np.random.default_rng(seed)
    A, B = [], []
    for _ in range(m):
        a = _star(rng, int(rng.integers(3, 16)), 0.0, 0.0, 1.0)
        if rng.random() < 0.3:
            a = a.reverse()  # clockwise rings too
        k = rng.random()
        if k < 0.15:
            b = shapely.affinity.translate(a, float(rng.uniform(-2, 2)), 0.0)  # a copy beside or over it
        elif k < 0.3:
            # touching: a copy of its bounding box's neighbour (area 0, contact only)
            _, y0, x1, y1 = a.bounds
            b = shapely.box(x1, y0, x1 + 1.0, y1)
        else:
            b = _star(rng, int(rng.integers(3, 16)), *rng.uniform(-1.8, 1.8, 2), float(rng.uniform(0.05, 1.3)))
        A.append(a)
        B.append(b)
    A = np.array(A, dtype=object)
    B = np.array(B, dtype=object)
    ok = shapely.is_valid(A) & shapely.is_valid(B)
    return A[ok], B[ok]


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_certificate_never_wrong_and_test_equals_overlay(seed):
    from strew.grow._collide import _big_overlaps
    from strew.grow._overlap_kernels import overlap_certain

    A, B = _pairs(seed, 60)
    ref = _overlay(A, B)
    oa = np.r_[0, np.cumsum(shapely.get_num_coordinates(A))].astype(np.int64)
    ob = np.r_[0, np.cumsum(shapely.get_num_coordinates(B))].astype(np.int64)
    cert = np.zeros(len(A), dtype=bool)
    overlap_certain(shapely.get_coordinates(A), oa, shapely.get_coordinates(B), ob, cert)
    assert not (cert & ~ref).any()
    assert (_big_overlaps(A, B) == ref).all()
    # one geometry against many (as _hits_any and overlapping ask)
    assert (_big_overlaps(A[0], B) == _overlay(np.full(len(B), A[0], dtype=object), B)).all()


def test_certificate_proves_most_plain_overlaps_and_falls_back_on_holes():
    """The kernel takes the common case (it proves at least 90 % of the overlapping
    random pairs), and polygons with holes or several parts go to the overlay."""
    from strew.grow._collide import _big_overlaps
    from strew.grow._overlap_kernels import overlap_certain

    A, B = _pairs(7, 400)
    ref = _overlay(A, B)
    oa = np.r_[0, np.cumsum(shapely.get_num_coordinates(A))].astype(np.int64)
    ob = np.r_[0, np.cumsum(shapely.get_num_coordinates(B))].astype(np.int64)
    cert = np.zeros(len(A), dtype=bool)
    overlap_certain(shapely.get_coordinates(A), oa, shapely.get_coordinates(B), ob, cert)
    assert ref.sum() > 100 and cert.sum() >= 0.9 * ref.sum()
    # a ring around a disc: the disc lies in the hole, no overlap (a test of the
    # exterior ring alone would prove one); a multipolygon with a part over the disc
    ring = shapely.Point(0, 0).buffer(3.0).difference(shapely.Point(0, 0).buffer(2.0))
    disc = shapely.Point(0, 0).buffer(1.0)
    two = shapely.MultiPolygon([shapely.box(5, 5, 6, 6), shapely.box(-0.5, -0.5, 0.5, 0.5)])
    A2 = np.array([ring, disc, two, disc], dtype=object)
    B2 = np.array([disc, ring, disc, two], dtype=object)
    assert _big_overlaps(A2, B2).tolist() == [False, False, True, True] == _overlay(A2, B2).tolist()

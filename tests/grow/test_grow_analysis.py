"""Connectivity of the reference arrangement (Ijiri et al. §4)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from strew import Arrangement, InputError, Shape
from strew.grow import analyze, delaunay_edges, flip_edge
from strew.grow._analysis import SKEW_ANGLE, _triangle_angles
from strew.grow._exemplars import hex_exemplar, hex_lattice, tile_exemplar


def _arr(xy):
    xy = np.asarray(xy, dtype=float)
    return Arrangement({"dot": Shape.circle(0.5)}, np.zeros(len(xy), dtype=int), xy[:, 0], xy[:, 1])


def _triangles_of(edges, n):
    adj = [set() for _ in range(n)]
    for i, j in edges:
        adj[i].add(j)
        adj[j].add(i)
    return {tuple(sorted((i, j, k))) for i, j in edges for k in adj[i] & adj[j]}


def _delaunay_classes(xy):
    from scipy.spatial import Delaunay

    tri = Delaunay(xy).simplices
    ang = _triangle_angles(xy, tri)
    good, bad = set(), set()
    for t, a in zip(tri.tolist(), ang):
        es = {tuple(sorted(p)) for p in ((t[0], t[1]), (t[1], t[2]), (t[0], t[2]))}
        (bad if a.max() > SKEW_ANGLE else good).update(es)
    return good, bad - good


def test_skewed_triangle_removed():
    # Element 5 far to the right makes two flat triangles (angles of 147° and 152°).
    xy = np.array([(0, 0), (10, 0), (20, 0), (10, 12), (10, -2), (30, -3)], float)
    good, only_skewed = _delaunay_classes(xy)
    e = {tuple(x) for x in delaunay_edges(xy).tolist()}
    assert only_skewed  # the configuration does have edges of skewed triangles only
    assert e == good
    assert not (e & only_skewed)
    assert all(5 not in edge for edge in e)  # element 5 joined nothing but flat triangles


@given(st.lists(st.tuples(st.floats(0, 100), st.floats(0, 100)), min_size=6, max_size=30, unique=True))
def test_kept_edges_belong_to_unskewed_triangles(pts):
    xy = np.array(pts)
    try:
        e = delaunay_edges(xy)
    except InputError:
        return  # collinear / duplicate / all skewed: rejected with a message
    tris = np.array(sorted(_triangles_of(e.tolist(), len(xy))))
    ang = _triangle_angles(xy, tris)
    ok = tris[ang.max(axis=1) < SKEW_ANGLE]
    covered = {tuple(sorted(p)) for t in ok.tolist() for p in ((t[0], t[1]), (t[1], t[2]), (t[0], t[2]))}
    assert {tuple(x) for x in e.tolist()} <= covered


def test_boundary_elements_excluded_and_rings_recorded():
    ex = hex_exemplar(5, 5)
    ref = analyze(ex)
    xy = ex.xy
    # interior = not on the outer rows / columns of the lattice
    r, c = np.divmod(np.arange(25), 5)
    expected = (r > 0) & (r < 4) & (c > 0) & (c < 4)
    assert ref.interior.tolist() == expected.tolist()
    rings = ref.ring_arrays()
    assert (rings["n"] == 6).all()
    # relative positions are the six lattice directions at distance 10, ccw ordered
    for a, i in enumerate(rings["ids"]):
        rel = rings["rel"][a]
        assert np.allclose(np.linalg.norm(rel, axis=1), 10.0)
        ang = np.arctan2(rel[:, 1], rel[:, 0])
        assert np.all(np.diff(ang) > 0)
        assert rings["sub"][a].tolist() == ref.rings[i].tolist()
        assert np.allclose(xy[rings["sub"][a]] - xy[i], rel)


def test_flip_edge_and_explicit_edges():
    ex = tile_exemplar()
    ref = analyze(ex)
    i, j = ref.edges[len(ref.edges) // 2].tolist()
    # find a flippable interior edge
    for i, j in ref.edges.tolist():
        try:
            flipped = flip_edge(ref, i, j)
        except InputError:
            continue
        break
    before = {tuple(e) for e in ref.edges.tolist()}
    after = {tuple(e) for e in flipped.edges.tolist()}
    assert (i, j) not in after and len(after) == len(before)
    (new,) = after - before
    assert before - after == {(i, j)}
    # the new edge joins the two common neighbours of i and j
    adj = {v: {b for a, b in before if a == v} | {a for a, b in before if b == v} for v in (i, j)}
    assert set(new) <= adj[i] & adj[j]
    # flipping it back restores the original connectivity
    assert {tuple(e) for e in flip_edge(flipped, *new).edges.tolist()} == before
    # an explicit edge list (as a document would carry) is used as given
    ex2 = ex.replace(extra={"connectivity": {"edges": flipped.edges.tolist()}})
    assert np.array_equal(analyze(ex2).edges, flipped.edges)
    assert np.array_equal(analyze(ex, flips=[(i, j)]).edges, flipped.edges)


def test_flip_errors_name_the_problem():
    ref = analyze(hex_exemplar(5, 5))
    with pytest.raises(InputError, match="not joined by an edge"):
        flip_edge(ref, 0, 24)
    with pytest.raises(InputError, match="out of range"):
        flip_edge(ref, 0, 99)
    with pytest.raises(InputError, match="boundary"):
        flip_edge(ref, 0, 1)


@pytest.mark.parametrize(
    "xy, message",
    [
        ([(0, 0), (1, 0), (0, 1)], "at least four elements"),
        ([(0, 0), (1, 1), (2, 2), (3, 3), (4, 4)], "collinear"),
        ([(0, 0), (10, 0), (0, 10), (10, 10), (10, 0)], "duplicate positions: elements 1 and 4"),
    ],
)
def test_bad_exemplars(xy, message):
    with pytest.raises(InputError, match=message):
        analyze(_arr(xy))


def test_no_interior_element_is_rejected():
    with pytest.raises(InputError, match="no interior element"):
        analyze(_arr([(0, 0), (10, 0), (0, 10), (10, 10)]))


def test_bad_explicit_edges():
    ex = _arr(hex_lattice(4, 4))
    with pytest.raises(InputError, match="out of range"):
        analyze(ex, edges=[[0, 99]])
    bad = ex.replace(extra={"connectivity": {"edges": "nope"}})
    with pytest.raises(InputError, match="connectivity.edges"):
        analyze(bad)

"""The local map m_p on a surface (Davison et al. §5.1, §5.7)."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings, strategies as st

from strew import InputError
from strew import surface

SPHERE = trimesh.creation.icosphere(subdivisions=4)


def _plane(k=8):
    # the square [-2, 2]^2 in z = 0 as a k x k grid of squares, split into triangles
    xs = np.linspace(-2, 2, k + 1)
    X, Y = np.meshgrid(xs, xs)
    v = np.column_stack([X.ravel(), Y.ravel(), np.zeros(X.size)])
    f = []
    for i in range(k):
        for j in range(k):
            a = i * (k + 1) + j
            f += [[a, a + 1, a + k + 2], [a, a + k + 2, a + k + 1]]
    return trimesh.Trimesh(v, np.array(f), process=False)


def test_flat_plane_is_a_translation_in_the_frame():
    mesh = _plane()
    field = surface.orientation_field(mesh, strokes=[[[-1.5, 0, 0], [1.5, 0, 0]]])
    face = 70
    bary = np.array([0.2, 0.3, 0.5])
    p = bary @ mesh.vertices[mesh.faces[face]]
    offsets = np.array([[0.3, 0.0], [0.0, 0.4], [-0.25, 0.5], [0.0, 0.0]])
    pts, faces, bc = surface.local_map(mesh, field, face, bary, offsets)
    t = field.at(np.array([face]), bary[None], np.array([[0, 0, 1.0]]))[0]
    b = np.cross([0, 0, 1.0], t)
    expected = p + offsets[:, :1] * t - offsets[:, 1:] * b  # exemplar +y (down) along -b
    assert np.allclose(pts, expected, atol=1e-9)
    assert np.allclose(np.einsum("ij,ijk->ik", bc, mesh.vertices[mesh.faces[faces]]), pts, atol=1e-9)


@settings(max_examples=20, deadline=None)
@given(
    face=st.integers(0, len(SPHERE.faces) - 1),
    u=st.floats(-0.8, 0.8),
    w=st.floats(-0.8, 0.8),
)
def test_sphere_walks_keep_their_length(face, u, w):
    field = _sphere_field()
    bary = np.array([0.3, 0.3, 0.4])
    p = bary @ SPHERE.vertices[SPHERE.faces[face]]
    pts, faces, bc = surface.local_map(SPHERE, field, face, bary, [[u, w]])
    # on the unit sphere the geodesic distance is the angle (polyhedral error ~ 1e-3)
    cosang = np.dot(pts[0] / np.linalg.norm(pts[0]), p / np.linalg.norm(p))
    assert abs(np.arccos(np.clip(cosang, -1, 1)) - np.hypot(u, w)) < 5e-3
    # on the surface: the located face holds the point
    back = bc[0] @ SPHERE.vertices[SPHERE.faces[faces[0]]]
    assert np.linalg.norm(back - pts[0]) < 1e-9


_FIELD = []


def _sphere_field():
    if not _FIELD:
        _FIELD.append(surface.orientation_field(SPHERE))
    return _FIELD[0]


def test_bad_arguments():
    with pytest.raises(InputError, match="face: index"):
        surface.local_map(SPHERE, _sphere_field(), 10**6, [1, 0, 0], [[0.1, 0]])
    with pytest.raises(InputError, match="offsets: NaN"):
        surface.local_map(SPHERE, _sphere_field(), 0, [1, 0, 0], [[np.nan, 0]])


def test_chart_of_a_plane_is_an_isometry():
    from strew import Shape
    from strew.arrangement import transform_points

    mesh = _plane(32)
    arr = surface.pack({"tri": Shape.polygon([(0, 0), (0.2, 0), (0, 0.08)])}, mesh, rng=3, rotation="random", field=None)
    ch = surface.chart(arr, mesh, [0, 0, 0], 1.5)
    p = np.column_stack([arr.x, arr.y, arr["z"]])
    keep = np.hypot(p[:, 0], p[:, 1]) < 1.5 - 1e-9
    assert len(ch) == keep.sum() > 20
    # distances are kept, and each element's 2D outline is its 3D outline moved rigidly
    pts = arr.shapes["tri"].points
    q, n, t, b, s = surface.element_frames(arr)
    world = q[keep][:, None, :] + s[keep, None, None] * (pts[None, :, :1] * t[keep, None] - pts[None, :, 1:] * b[keep, None])
    flat = np.stack([transform_points(pts, x, y, r, sc) for x, y, r, sc in zip(ch.x, ch.y, ch.rotation, ch.scale)])
    d3 = np.linalg.norm(world.reshape(-1, 3)[:, None] - world.reshape(-1, 3)[None], axis=2)
    d2 = np.linalg.norm(flat.reshape(-1, 2)[:, None] - flat.reshape(-1, 2)[None], axis=2)
    assert np.all(np.abs(d3 - d2) <= 1e-6 * d3 + 1e-9)
    within = np.abs(d3 - d2).reshape(len(world), 3, len(world), 3)[np.arange(len(world)), :, np.arange(len(world))]
    assert within.max() < 1e-9
    def signed(a):
        e1, e2 = a[:, 1, :2] - a[:, 0, :2], a[:, 2, :2] - a[:, 0, :2]
        return e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
    # same picture: the surface seen from outside (+z, y up on the screen) against the
    # chart drawn as SVG (y down): raw signed areas have opposite signs
    assert np.all(np.sign(signed(world)) == -np.sign(signed(flat)))
    with pytest.raises(InputError, match="radius: must be positive"):
        surface.chart(arr, mesh, [0, 0, 0], -1)


def test_sphere_charts_are_faithful_to_a_flat_packing():
    from strew.metrics import fidelity

    r = 0.05
    flat = surface.pack(r, _plane(), rng=1, field=None)
    exemplar = flat.select(np.ones(len(flat), bool)).without_columns(*flat.columns)
    exemplar = exemplar.replace(region=strew_region_box(-2, -2, 2, 2))
    arr = surface.pack(r, SPHERE, rng=2, field=None)
    verdicts = [fidelity(exemplar, surface.chart(arr, SPHERE, c, 0.8), local=False, eq5=False).faithful
                for c in ([0, 0, 1], [1, 0, 0], [0, -1, 0])]
    assert all(verdicts)


def strew_region_box(x0, y0, x1, y1):
    import shapely

    from strew import Region

    return Region(shapely.box(x0, y0, x1, y1))

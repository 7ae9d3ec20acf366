"""The local map m_p on a surface (Davison et al. §5.1, §5.7)."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings, strategies as st

from strew import InputError
from strew import surface

SPHERE = trimesh.creation.icosphere(subdivisions=4)


def _plane():
    # a flat 4 x 4 grid of squares in z = 0, split into triangles
    xs = np.linspace(-2, 2, 9)
    X, Y = np.meshgrid(xs, xs)
    v = np.column_stack([X.ravel(), Y.ravel(), np.zeros(X.size)])
    f = []
    for i in range(8):
        for j in range(8):
            a = i * 9 + j
            f += [[a, a + 1, a + 10], [a, a + 10, a + 9]]
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

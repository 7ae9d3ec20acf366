"""Packing on surfaces (issue 20 point 3): on the surface, no sphere overlaps, uniform density."""

from __future__ import annotations

import json

import numpy as np
import pytest
import trimesh
from hypothesis import HealthCheck, given, settings, strategies as st
from scipy.spatial import cKDTree

import strew
from strew import InputError, Shape
from strew import surface

from _surface_helpers import positions


def assert_on_surface(arr, mesh, tol=1e-6):
    """Each element lies on its recorded face: within tol * mesh size of the face's plane,
    with barycentric coordinates in [0, 1]."""
    size = float(np.linalg.norm(mesh.extents))
    p = positions(arr)
    f = np.asarray(arr["face"])
    tri = np.asarray(mesh.vertices)[np.asarray(mesh.faces)[f]]
    n = np.asarray(mesh.face_normals)[f]
    plane = np.abs(np.einsum("ij,ij->i", p - tri[:, 0], n))
    assert plane.max() < tol * size
    bary = trimesh.triangles.points_to_barycentric(tri, p)
    assert bary.min() > -1e-9 and bary.max() < 1 + 1e-9


def assert_no_overlaps(arr):
    p = positions(arr)
    r = np.asarray(arr["radius"])
    pairs = cKDTree(p).query_pairs(2 * r.max(), output_type="ndarray")
    if len(pairs):
        d = np.linalg.norm(p[pairs[:, 0]] - p[pairs[:, 1]], axis=1)
        assert np.all(d >= r[pairs[:, 0]] + r[pairs[:, 1]] - 1e-12), "bounding spheres overlap"


def test_on_surface_and_no_overlaps(sphere, sphere_dots, torus, torus_mixed):
    assert len(sphere_dots) > 500
    for arr, mesh in ((sphere_dots, sphere), (torus_mixed, torus)):
        assert_on_surface(arr, mesh)
        assert_no_overlaps(arr)
    assert set(torus_mixed.kinds) == {"leaf", "dot"} and min(torus_mixed.counts().values()) > 20


def test_frames_are_orthonormal_and_follow_the_surface(sphere, sphere_dots, torus, torus_mixed):
    for arr, mesh in ((sphere_dots, sphere), (torus_mixed, torus)):
        p, n, t, b, s = surface.element_frames(arr)
        assert np.allclose(np.linalg.norm(n, axis=1), 1) and np.allclose(np.linalg.norm(t, axis=1), 1)
        assert np.abs(np.einsum("ij,ij->i", n, t)).max() < 1e-9
        fn = np.asarray(mesh.face_normals)[np.asarray(arr["face"])]
        assert np.einsum("ij,ij->i", n, fn).min() > 0.95  # outward, like the faces
    # on the unit sphere the normal is the position
    p, n, *_ = surface.element_frames(sphere_dots)
    assert np.einsum("ij,ij->i", n, p / np.linalg.norm(p, axis=1, keepdims=True)).min() > 0.999


def test_density_uniform_on_sphere(sphere_dots):
    # Archimedes: bands of equal height are of equal area; 4 bands x 6 sectors
    p = positions(sphere_dots)
    z = p[:, 2] / np.linalg.norm(p, axis=1)
    band = np.clip(((z + 1) / 2 * 4).astype(int), 0, 3)
    sector = ((np.arctan2(p[:, 1], p[:, 0]) + np.pi) / (2 * np.pi) * 6).astype(int) % 6
    counts = np.bincount(band * 6 + sector, minlength=24)
    assert counts.std() / counts.mean() < 0.1


def test_packing_is_dense(sphere, sphere_dots):
    # fill-gap leaves almost no room for one more dot: points of the surface where a new
    # sphere of the same radius would fit are rare
    r = 0.05
    q = trimesh.sample.sample_surface(sphere, 20000, seed=3)[0]
    d, _ = cKDTree(positions(sphere_dots)).query(q)
    assert np.mean(d >= 2 * r) < 0.01
    # random sequential adsorption fills at least half the hexagonal packing's count
    assert len(sphere_dots) > 0.5 * sphere.area / (2 * np.sqrt(3) * r * r)


def test_deterministic(sphere):
    a = surface.pack(0.08, sphere, rng=5, field=None)
    b = surface.pack(0.08, sphere, rng=5, field=None)
    c = surface.pack(0.08, sphere, rng=6, field=None)
    assert a.equals(b)
    assert not np.array_equal(a.x, c.x)


def test_field_orients_tangents(sphere):
    field = surface.orientation_field(sphere, sources=[[0, 0, 1]])
    a = surface.pack(0.08, sphere, rng=2, field=field)
    p, n, t, _, _ = surface.element_frames(a)
    # away from the poles the tangent points away from the source (south along meridians)
    south = np.array([0, 0, -1.0])[None] - np.einsum("ij,j->i", n, [0, 0, -1.0])[:, None] * n
    keep = np.abs(p[:, 2]) < 0.8
    south = south[keep] / np.linalg.norm(south[keep], axis=1, keepdims=True)
    assert np.einsum("ij,ij->i", t[keep], south).min() > 0.9
    assert a.meta["params"]["field"]["method"] == "singularities"


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(
    radius=st.floats(0.05, 0.25),
    sub=st.integers(1, 3),
    lo=st.floats(0.5, 1.0),
    spread=st.floats(1.0, 2.0),
    margin=st.floats(0.0, 0.02),
    seed=st.integers(0, 2**31),
)
def test_any_sphere_and_scales(radius, sub, lo, spread, margin, seed):
    mesh = trimesh.creation.icosphere(subdivisions=sub, radius=2.0)
    lib = {"a": Shape.circle(radius), "b": Shape.rectangle(radius, 2 * radius)}
    arr = surface.pack(lib, mesh, scale=(lo, lo * spread), margin=margin, rng=seed, field=None)
    assert len(arr) > 0
    assert_on_surface(arr, mesh)
    assert_no_overlaps(arr)
    assert np.all(arr["radius"] >= np.array([lib[k].radius for k in arr.kind_names]) * arr.scale + margin - 1e-12)


def test_document_version_2_round_trip(tmp_path, torus_mixed):
    path = tmp_path / "scene.json"
    strew.save(torus_mixed, path)
    doc = json.loads(path.read_text())
    assert doc["version"] == 2
    assert {"z", "nx", "ny", "nz", "tx", "ty", "tz", "scale", "kind"} <= set(doc["elements"])
    back = strew.load(path)
    assert back.equals(torus_mixed)
    # a 2D arrangement is still written as version 1
    flat = strew.Arrangement({"dot": Shape.circle(1)}, ["dot"], [0], [0])
    strew.save(flat, tmp_path / "flat.json")
    assert json.loads((tmp_path / "flat.json").read_text())["version"] == 1


def test_document_version_2_validation(tmp_path, sphere_dots):
    doc = json.loads(strew.io.encode(sphere_dots.select(slice(0, 3)), "x.json"))
    bad = json.loads(json.dumps(doc))
    bad["elements"]["nx"][1] = 5.0
    with pytest.raises(InputError, match=r"elements\.nx\[1\]: the normal"):
        strew.io.document.from_document(bad)
    bad = json.loads(json.dumps(doc))
    del bad["elements"]["tz"]
    with pytest.raises(InputError, match=r"elements\.tz: missing column"):
        strew.io.document.from_document(bad)
    bad = json.loads(json.dumps(doc))
    bad["elements"]["tx"], bad["elements"]["ty"], bad["elements"]["tz"] = bad["elements"]["nx"], bad["elements"]["ny"], bad["elements"]["nz"]
    with pytest.raises(InputError, match="orthogonal"):
        strew.io.document.from_document(bad)


@pytest.mark.parametrize(
    "args, kwargs, message",
    [
        ((-1.0,), {}, "radius: must be a positive number"),
        ((0.1,), {"scale": (0, 1)}, "scale: expected 0 < lo <= hi"),
        ((0.1,), {"scale": "big"}, "scale: expected a number or (lo, hi)"),
        ((0.1,), {"rotation": "spin"}, "rotation: expected 'field' or 'random'"),
        ((0.1,), {"weights": [1, 2]}, "weights: expected 1 non-negative numbers"),
        ((0.1,), {"weights": {"x": 1}}, "weights: unknown kind 'x'"),
        ((0.1,), {"max_failures": 0}, "max_failures: must be a positive integer"),
        ((0.1,), {"field": "curly"}, "field: expected an OrientationField"),
        (({"a": "not a shape"},), {}, "shapes.a: must be a Shape"),
        (({},), {}, "shapes: no shape given"),
        ((0.1,), {"margin": float("nan")}, "margin: must be finite"),
    ],
)
def test_bad_options(sphere, args, kwargs, message):
    with pytest.raises(InputError) as info:
        surface.pack(*args, sphere, rng=1, **kwargs)
    assert message in str(info.value)


def test_field_of_another_mesh_is_refused(sphere, torus):
    with pytest.raises(InputError, match="field: has"):
        surface.pack(0.1, sphere, field=surface.orientation_field(torus))


def test_density_does_not_follow_curvature(torus):
    # the torus's inner half has negative Gaussian curvature, its outer half positive:
    # elements per unit area agree within 10%
    arr = surface.pack(0.04, torus, rng=3, field=None)
    f = np.asarray(arr["face"])
    c = torus.triangles_center
    inner = np.hypot(c[:, 0], c[:, 1]) < 1.0
    d_in = np.count_nonzero(inner[f]) / torus.area_faces[inner].sum()
    d_out = np.count_nonzero(~inner[f]) / torus.area_faces[~inner].sum()
    assert 0.9 < d_in / d_out < 1.1

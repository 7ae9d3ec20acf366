"""The studio's 3D view (issue 20.7), its messages without a browser: a mesh loads and
travels as arrays; brush points on it paint elements that lie on the surface with no
bounding spheres overlapping; bad messages are refused with a message."""

from __future__ import annotations

import numpy as np
import pytest

from strew import InputError
from strew.studio._common import PRELOAD_EXAMPLE
from strew.studio._session import Session

pytest.importorskip("trimesh")
pytest.importorskip("potpourri3d")

SPHERE = "examples/meshes/sphere.ply"


@pytest.fixture(scope="module")
def painted(tmp_path_factory):
    s = Session(tmp_path_factory.mktemp("view3d"), seed=3, preload=PRELOAD_EXAMPLE)
    s.handle({"type": "hello"})
    mesh_reply = s.handle({"type": "load_mesh", "path": SPHERE})
    stroke = np.array([[60.0, 0, 0], [54, 18, 6], [42, 42, 0]])
    replies = s.handle({"type": "brush3d", "points": stroke.tolist(), "radius": 15})
    return s, mesh_reply, replies


def test_load_mesh_sends_vertices_and_faces(painted):
    s, replies, _ = painted
    mesh = replies[0]
    assert mesh["type"] == "mesh"
    V = np.asarray(mesh["vertices"]).reshape(-1, 3)
    F = np.asarray(mesh["faces"]).reshape(-1, 3)
    assert len(V) == len(s.mesh3d.vertices) and len(F) == len(s.mesh3d.faces)
    assert F.min() == 0 and F.max() == len(V) - 1
    assert mesh["radius"] == pytest.approx(np.linalg.norm(V - V.mean(axis=0), axis=1).max(), rel=1e-6)
    assert replies[1] == {"type": "elements3d", "count": 0, "positions": [], "normals": [], "tangents": [], "scales": [], "radii": [], "kinds": [], "names": []}


def test_brush_paints_on_the_surface_without_overlaps(painted):
    s, _, replies = painted
    el = replies[0]
    assert el["type"] == "elements3d" and el["count"] >= 10
    P = np.asarray(el["positions"]).reshape(-1, 3)
    N = np.asarray(el["normals"]).reshape(-1, 3)
    T = np.asarray(el["tangents"]).reshape(-1, 3)
    assert len(P) == len(N) == len(T) == len(el["scales"]) == len(el["kinds"]) == el["count"]
    # on the surface: the sphere.ply is a radius-60 icosphere; the closest points agree
    _, _, on = s.surf3d.surf.locate(P)  # closest points on the mesh
    assert np.linalg.norm(P - on, axis=1).max() < 1e-4 * 60
    assert np.abs(np.linalg.norm(P, axis=1) - 60).max() < 1.0  # and on this sphere, not elsewhere
    assert np.abs(np.einsum("ij,ij->i", N, T)).max() < 1e-3  # tangents lie in the tangent planes
    # painted near the stroke only
    stroke = np.array([[60.0, 0, 0], [54, 18, 6], [42, 42, 0]])
    near = np.min(np.linalg.norm(P[:, None] - stroke[None], axis=2), axis=1)
    assert near.max() < 15 + 2 * float(s.surf3d.rc.max())
    # no bounding spheres overlap (the state's own sphere radii)
    st = s.surf3d
    from scipy.spatial.distance import pdist, squareform

    arr = st.to_arrangement()
    R = np.asarray(arr["radius"])
    assert len(R) == el["count"] and (R > 0).all() and np.allclose(el["radii"], R, atol=1e-5)
    D = squareform(pdist(P))
    np.fill_diagonal(D, np.inf)
    assert (D - (R[:, None] + R[None, :]) > -1e-9).all()
    assert max(el["kinds"]) < len(el["names"])


def test_clear_and_bad_messages(tmp_path):
    s = Session(tmp_path, seed=1, preload=PRELOAD_EXAMPLE)
    s.handle({"type": "hello"})
    with pytest.raises(InputError, match="load a mesh first"):
        s.handle({"type": "brush3d", "points": [[0, 0, 0]], "radius": 1})
    with pytest.raises(InputError, match="example mesh"):
        s.handle({"type": "load_mesh", "path": "examples/meshes/../exemplars/stones.svg"})
    with pytest.raises(InputError):
        s.handle({"type": "load_mesh", "path": "missing.ply"})
    s.handle({"type": "load_mesh", "path": SPHERE})
    with pytest.raises(InputError, match="brush3d.points"):
        s.handle({"type": "brush3d", "points": [[0, 0]], "radius": 1})
    with pytest.raises(InputError, match="brush3d.radius"):
        s.handle({"type": "brush3d", "points": [[60, 0, 0]], "radius": -1})
    assert s.handle({"type": "brush3d", "points": [[60, 0, 0]], "radius": 10})[0]["count"] > 0
    assert s.handle({"type": "clear3d"})[0]["count"] == 0


def test_cli_surface_opens_the_3d_view(tmp_path, monkeypatch, capsys):
    """``strew studio --surface MESH`` opens the 3D view on a mesh of the project (or an
    example mesh); a mesh that is missing or outside the project is an exit 2."""
    import shutil

    import strew.studio
    from strew._resources import examples_dir
    from strew.cli import main

    pytest.importorskip("fastapi")
    seen = {}
    monkeypatch.setattr(strew.studio, "serve", lambda root, **kw: seen.update(kw))
    shutil.copy(examples_dir() / "meshes" / "sphere.ply", tmp_path / "ball.ply")
    def run(mesh):
        return main(["studio", str(tmp_path), "--no-browser", "--port", "0", "--surface", mesh])

    assert run("ball.ply") == 0
    assert seen["page"] == "static/view3d.html?mesh=ball.ply"
    assert run("examples/meshes/sphere.ply") == 0
    assert seen["page"] == "static/view3d.html?mesh=examples/meshes/sphere.ply"
    capsys.readouterr()
    for bad in ("missing.ply", "../outside.ply", str(examples_dir() / "meshes" / "sphere.ply")):
        seen.clear()
        assert run(bad) == 2, bad
        assert "--surface" in capsys.readouterr().err and not seen

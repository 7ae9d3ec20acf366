"""GLB round trip through trimesh, the PNG preview (issue 20 point 5)."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from PIL import Image

from strew import InputError, Shape
from strew import surface


def test_glb_round_trip(tmp_path, torus, torus_mixed):
    path = surface.save_glb(torus_mixed, tmp_path / "scene.glb", mesh=torus)
    scene = trimesh.load(path)
    assert set(scene.geometry) == {"surface", "leaf", "dot"}
    nodes = [n for n in scene.graph.nodes_geometry if n != "surface"]
    assert len(nodes) == len(torus_mixed)
    p, n, t, b, s = surface.element_frames(torus_mixed)
    kinds = torus_mixed.kind_names
    for node in nodes:
        matrix, geom = scene.graph[node]
        i = int(node.split("#")[1])
        assert geom == kinds[i]
        assert np.allclose(matrix[:3, 3], p[i], atol=1e-6)
        assert np.allclose(matrix[:3, 0], s[i] * t[i], atol=1e-6)
        assert np.allclose(matrix[:3, 2], s[i] * n[i], atol=1e-6)
    # one mesh per kind, shared by its nodes: the file stays small
    assert path.stat().st_size < 2000 + 600 * len(torus_mixed) + 60 * len(torus.faces)
    # the surface itself comes back
    assert np.isclose(scene.geometry["surface"].area, torus.area, rtol=1e-6)


def test_element_meshes_and_decals(tmp_path, sphere, sphere_dots):
    rock = trimesh.creation.icosphere(subdivisions=1, radius=0.05)
    scene = trimesh.load(surface.save_glb(sphere_dots, tmp_path / "rocks.glb", element_meshes={"dot": rock}))
    assert len(scene.geometry["dot"].faces) == len(rock.faces)
    decal = surface.shape_mesh(Shape.circle(1.0), style="decal")
    assert np.ptp(decal.vertices[:, 2]) == 0 and np.isclose(decal.area, np.pi, rtol=0.02)
    slab = surface.shape_mesh(Shape.polygon([(0, 0), (2, 0), (2, 1), (1, 0.4), (0, 1)]))
    # a concave polygon of area 1.4, extruded by a fifth of its radius sqrt(5)
    assert slab.is_watertight and np.isclose(slab.volume, 1.4 * 0.2 * np.sqrt(5), rtol=1e-9)
    # mirrored: SVG's y-down point (0, 1) lands at local y = -1
    asym = surface.shape_mesh(Shape.polygon([(0, 0), (1, 0), (0, 1)]), style="decal")
    assert asym.vertices[:, 1].min() < -0.99 and asym.vertices[:, 1].max() < 1e-9


def test_glb_errors(tmp_path, sphere_dots):
    with pytest.raises(InputError, match="written as .glb"):
        surface.save_glb(sphere_dots, tmp_path / "scene.gltf")
    with pytest.raises(InputError, match="element_meshes: unknown kind 'rock'"):
        surface.save_glb(sphere_dots, tmp_path / "scene.glb", element_meshes={"rock": "rock.glb"})
    with pytest.raises(InputError, match="elements.z: missing column"):
        from strew import Arrangement

        surface.save_glb(Arrangement({"d": Shape.circle(1)}, ["d"], [0], [0]), tmp_path / "flat.glb")
    assert not (tmp_path / "scene.glb").exists()


def test_preview(tmp_path, sphere, sphere_dots):
    path = surface.save_preview(sphere_dots, tmp_path / "preview.png", sphere, size=300)
    with Image.open(path) as im:
        img = np.asarray(im.convert("RGB")).astype(int)
    assert img.shape == (300, 300, 3)
    # element colour (first kind: rust) is visible, and so is the grey surface
    rust = (img[..., 0] > img[..., 2] + 60)
    grey = (np.abs(img[..., 0] - img[..., 2]) < 30) & (img[..., 0] < 235) & (img[..., 0] > 60)
    assert rust.mean() > 0.05 and grey.mean() > 0.05
    # elements on the back are culled: none is drawn outside the sphere's disc
    yy, xx = np.mgrid[:300, :300]
    outside = np.hypot(xx - 150, yy - 150) > 150
    assert rust[outside].mean() < 0.001
    with pytest.raises(InputError, match="size: expected an integer"):
        surface.render_preview(sphere_dots, sphere, size=3)


def test_flat_arrangement_lifted_to_3d(tmp_path):
    from strew import Arrangement
    from strew.arrangement import transform_points

    rng = np.random.default_rng(4)
    lib = {"tri": Shape.polygon([(0, 0), (3, 0), (0, 1)]), "dot": Shape.circle(0.5)}
    a = Arrangement(lib, rng.integers(0, 2, 20), rng.uniform(0, 50, 20), rng.uniform(0, 50, 20),
                    rng.uniform(-np.pi, np.pi, 20), rng.uniform(0.5, 2, 20))
    lifted = surface.lift(a, z=2.0)
    p, n, t, b, s = surface.element_frames(lifted)
    pts = lib["tri"].points
    for i in np.flatnonzero(a.kind == 0):
        world = p[i] + s[i] * (pts[:, :1] * t[i] - pts[:, 1:] * b[i])  # the frames' convention
        flat = transform_points(pts, a.x[i], a.y[i], a.rotation[i], a.scale[i])
        assert np.allclose(world[:, :2], flat) and np.allclose(world[:, 2], 2.0)
    rock = trimesh.creation.icosphere(subdivisions=1, radius=0.5)
    scene = trimesh.load(surface.save_glb(lifted, tmp_path / "flat.glb", element_meshes={"dot": rock}))
    assert len(scene.graph.nodes_geometry) == len(a)
    with pytest.raises(InputError, match="z: must be finite"):
        surface.lift(a, z=float("inf"))


def test_glb_gpu_instancing_holds_every_element_frame():
    import json
    import struct

    from scipy.spatial.transform import Rotation

    m = trimesh.creation.icosphere(subdivisions=2)
    arr = surface.pack({"a": Shape.circle(0.15), "b": Shape.rectangle(0.3, 0.1)}, m, rng=2, rotation="random")
    g = surface.to_glb(arr, mesh=m, instancing=True)
    assert g[:4] == b"glTF" and struct.unpack_from("<I", g, 8)[0] == len(g)
    jl = struct.unpack_from("<I", g, 12)[0]
    doc = json.loads(g[20:20 + jl])
    binary = g[20 + jl + 8:]
    assert "EXT_mesh_gpu_instancing" in doc["extensionsUsed"] and "EXT_mesh_gpu_instancing" not in doc.get("extensionsRequired", [])

    def read(i):
        acc = doc["accessors"][i]
        view = doc["bufferViews"][acc["bufferView"]]
        width = {"VEC3": 3, "VEC4": 4}[acc["type"]]
        return np.frombuffer(binary, np.float32, acc["count"] * width, view.get("byteOffset", 0)).reshape(-1, width)

    p, n, t, b, s = surface.element_frames(arr)
    seen = 0
    for node in doc["nodes"]:
        ext = node.get("extensions", {}).get("EXT_mesh_gpu_instancing")
        if ext is None:
            continue
        k = arr.kinds.index(node["name"].split(":", 1)[1])
        rows = np.flatnonzero(np.asarray(arr.kind) == k)
        at = ext["attributes"]
        assert np.allclose(read(at["TRANSLATION"]), p[rows], atol=1e-6)
        rot = Rotation.from_quat(read(at["ROTATION"]).astype(float))
        assert np.allclose(rot.apply([1.0, 0, 0]), t[rows], atol=1e-5) and np.allclose(rot.apply([0, 0, 1.0]), n[rows], atol=1e-5)
        assert np.allclose(read(at["SCALE"]), s[rows, None], atol=1e-6)
        seen += len(rows)
    assert seen == len(arr)
    # readers without the extension still open the file (surface + one copy per kind)
    scene = trimesh.load(trimesh.util.wrap_as_stream(g), file_type="glb")
    assert len(scene.geometry) == 3
    assert len(g) < len(surface.to_glb(arr, mesh=m))

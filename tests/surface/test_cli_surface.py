"""``strew surface`` (the CLI over strew.surface.pack): outputs, and exit 2 for bad meshes."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

import strew
from strew.cli import main

CONCAVE = Path(__file__).resolve().parents[2] / "examples" / "shapes" / "concave.svg"


@pytest.fixture(scope="module")
def mesh_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("mesh") / "torus.obj"
    trimesh.creation.torus(1.0, 0.4, major_sections=48, minor_sections=24).export(path)
    return path


def test_surface_command_writes_every_output(mesh_file, tmp_path, capsys):
    outs = [tmp_path / "scene.glb", tmp_path / "scene.json", tmp_path / "preview.png", tmp_path / "top.svg"]
    args = ["surface", "--surface", str(mesh_file), "--radius", "0.08", "--seed", "3"]
    for o in outs:
        args += ["--out", str(o)]
    assert main(args) == 0
    assert "packed" in capsys.readouterr().out
    arr = strew.load(outs[1])
    assert json.loads(outs[1].read_text())["version"] == 2
    assert arr.meta["command"].startswith("strew surface") and arr.meta["seed"] == 3
    scene = trimesh.load(outs[0])
    assert len([n for n in scene.graph.nodes_geometry if n != "surface"]) == len(arr)
    assert outs[2].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and outs[3].read_text().startswith("<?xml")
    # same seed, same document
    again = tmp_path / "again.json"
    assert main(["surface", "--surface", str(mesh_file), "--radius", "0.08", "--seed", "3", "--out", str(again)]) == 0
    assert np.array_equal(strew.load(again).x, arr.x)


def test_surface_command_with_shapes_and_field(mesh_file, tmp_path):
    (tmp_path / "design.json").write_text(json.dumps({"sources": [[1.4, 0, 0]]}))
    out = tmp_path / "stars.json"
    code = main(["surface", str(CONCAVE), "--surface", str(mesh_file), "--scale", "0.003:0.005",
                 "--field", str(tmp_path / "design.json"), "--quiet", "--out", str(out)])
    assert code == 0
    arr = strew.load(out)
    assert arr.meta["params"]["field"]["method"] == "singularities" and len(arr) > 10


def _bad_meshes(tmp_path):
    (tmp_path / "empty.obj").write_text("# nothing\n")
    (tmp_path / "fan.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0.5\nf 1 2 3\nf 1 2 4\nf 1 2 5\n")
    (tmp_path / "flat.obj").write_text("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")
    return {"empty.obj": "empty", "fan.obj": "non-manifold", "flat.obj": "degenerate", "missing.obj": "no such file",
            "mesh.txt": "unsupported extension"}


def test_bad_meshes_exit_2(tmp_path, capsys):
    for name, message in _bad_meshes(tmp_path).items():
        out = tmp_path / "out.glb"
        assert main(["surface", "--surface", str(tmp_path / name), "--radius", "0.1", "--out", str(out)]) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and err.startswith("strew: error: --surface") and message in err, err
        assert not out.exists()


@pytest.mark.parametrize(
    "args, message",
    [
        (["--radius", "0.1", "--out", "x.gltf"], "a surface scene is written as .glb, .json, .png, .svg"),
        (["--out", "x.glb"], "give SHAPE files or --radius R"),
        (["--radius", "-1", "--out", "x.glb"], "radius: must be a positive number"),
        (["--radius", "0.1", "--element", "rock", "--out", "x.glb"], "--element: expected KIND=MESH"),
        (["--radius", "0.1", "--field", "f.txt", "--out", "x.glb"], "no such file"),
        (["--radius", "0.1", "--out", "nofolder/x.glb"], "does not exist"),
    ],
)
def test_usage_errors_exit_2(args, message, mesh_file, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["surface", "--surface", str(mesh_file), *args]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1
    assert [p.name for p in tmp_path.iterdir()] == []


def test_missing_extra_names_the_install(mesh_file, tmp_path, capsys, monkeypatch):
    import sys

    from strew.surface import load_mesh

    monkeypatch.setitem(sys.modules, "potpourri3d", None)  # import fails as if not installed
    assert main(["surface", "--surface", str(mesh_file), "--radius", "0.1", "--out", str(tmp_path / "x.glb")]) == 2
    assert "strew.surface needs potpourri3d: pip install 'strew[surface]'" in capsys.readouterr().err
    monkeypatch.setitem(sys.modules, "trimesh", None)
    with pytest.raises(ImportError, match=r"pip install 'strew\[surface\]'"):
        load_mesh(mesh_file)


# -- strew pack|synth|grow --surface MESH ---------------------------------------------------
@pytest.fixture(scope="module")
def grid_file(tmp_path_factory):
    from strew.synth._exemplars import grid

    path = tmp_path_factory.mktemp("ex") / "grid.json"
    strew.save(grid(n=8), path)
    return path


def test_synth_on_surface_writes_scene(mesh_file, grid_file, tmp_path, capsys):
    outs = [tmp_path / "scene.glb", tmp_path / "scene.json"]
    args = ["synth", str(grid_file), "--surface", str(mesh_file), "--mesh-scale", "0.03", "--seed", "2"]
    for o in outs:
        args += ["--out", str(o)]
    assert main(args) == 0
    assert "elements" in capsys.readouterr().out
    arr = strew.load(outs[1])
    assert arr.meta["method"] == "surface.synth" and arr.meta["params"]["scale"] == 0.03
    assert arr.meta["command"].startswith("strew synth")
    mesh = trimesh.load(mesh_file, force="mesh")
    p = np.column_stack([arr.x, arr.y, arr["z"]])
    f = np.asarray(arr["face"])
    dist = np.abs(np.einsum("ij,ij->i", p - mesh.triangles[f][:, 0], mesh.face_normals[f]))
    assert len(arr) > 100 and dist.max() < 1e-6 * float(np.linalg.norm(mesh.extents))
    scene = trimesh.load(outs[0])
    assert len([n for n in scene.graph.nodes_geometry if n != "surface"]) == len(arr)
    inst = tmp_path / "inst.glb"
    assert main(args[:-4] + ["--instancing", "--out", str(inst)]) == 0
    assert b"EXT_mesh_gpu_instancing" in inst.read_bytes()[:4000] and inst.stat().st_size < outs[0].stat().st_size


def test_pack_on_surface_follows_the_field_unless_rotated(mesh_file, tmp_path):
    out = tmp_path / "pack.json"
    assert main(["pack", str(CONCAVE), "--surface", str(mesh_file), "--mesh-scale", "0.004", "--seed", "1", "--out", str(out)]) == 0
    arr = strew.load(out)
    assert arr.meta["method"] == "surface.pack" and arr.meta["params"]["rotation"] == "field" and len(arr) > 50
    out2 = tmp_path / "pack2.json"
    assert main(["pack", str(CONCAVE), "--surface", str(mesh_file), "--mesh-scale", "0.004", "--rotate", "0:360", "--out", str(out2)]) == 0
    assert strew.load(out2).meta["params"]["rotation"] == "random"


@pytest.mark.parametrize(
    "args, message",
    [
        (["synth", "{ex}", "--surface", "{mesh}", "--size", "10x10"], "leave out --region"),
        (["synth", "{ex}", "--surface", "{mesh}", "--optimize", "global"], "--optimize"),
        (["synth", "{ex}", "--surface", "{mesh}", "--fill", "1,2"], "--fill"),
        (["grow", "{ex}", "--surface", "{mesh}", "--mode", "rotate"], "--mode"),
        (["pack", "{shape}", "--surface", "{mesh}", "--method", "naive"], "--method"),
        (["pack", "{shape}", "--surface", "{mesh}", "--rotate", "0:90"], "--rotate"),
        (["synth", "{ex}", "--surface", "{bad}"], "--surface"),
    ],
)
def test_surface_option_refuses_what_has_no_meaning(mesh_file, grid_file, tmp_path, capsys, args, message):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")
    fill = {"ex": str(grid_file), "mesh": str(mesh_file), "shape": str(CONCAVE), "bad": str(bad)}
    argv = [a.format(**fill) for a in args] + ["--out", str(tmp_path / "x.glb")]
    assert main(argv) == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / "x.glb").exists()


def test_height_profile_is_refused_for_surface_scenes(tmp_path, capsys):
    mesh = tmp_path / "ball.ply"
    trimesh.creation.icosphere(subdivisions=2).export(mesh)
    assert main(["surface", "--surface", str(mesh), "--radius", "0.2", "--out", str(tmp_path / "s.glb"),
                 "--height-profile", "*=dome"]) == 2
    assert "--height-profile" in capsys.readouterr().err

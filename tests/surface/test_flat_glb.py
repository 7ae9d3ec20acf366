"""A flat result written as .glb (issue 20 point 4, Sakurai & Miyata Fig. 15): the
elements on the plane z = 0, kinds as extruded shapes or as a mesh given by --element."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import trimesh

import strew
from strew.cli import main

ROOT = Path(__file__).resolve().parents[2]
CONCAVE = ROOT / "examples" / "shapes" / "concave.svg"
SPHERE = ROOT / "examples" / "meshes" / "sphere.ply"


def _node_translations(scene: trimesh.Scene) -> np.ndarray:
    return np.array([scene.graph.get(n)[0][:3, 3] for n in scene.graph.nodes_geometry if n != "surface"])


def test_flat_pack_glb_places_each_element_at_its_xy(tmp_path):
    glb, doc = tmp_path / "rocks.glb", tmp_path / "rocks.json"
    args = ["pack", str(CONCAVE), "--size", "300x200", "--scale", "0.3", "--seed", "2",
            "--element", f"concave={SPHERE}", "--out", str(glb), "--out", str(doc)]
    assert main(args) == 0
    arr = strew.load(doc)
    scene = trimesh.load(glb)
    t = _node_translations(scene)
    assert len(arr) > 20 and len(t) == len(arr)
    assert np.allclose(t[:, 2], 0.0)
    got = t[np.lexsort((t[:, 1], t[:, 0]))][:, :2]
    want = np.column_stack([arr.x, arr.y])
    want = want[np.lexsort((want[:, 1], want[:, 0]))]
    assert np.allclose(got, want, atol=1e-6)
    # the kind carries the sphere's mesh, not an extruded outline
    sphere = trimesh.load(SPHERE)
    (geom,) = scene.geometry.values()
    assert len(geom.vertices) == len(sphere.vertices)
    assert "command" in json.loads(doc.read_text())["meta"]


def test_flat_glb_without_element_extrudes_and_render_writes_glb(tmp_path):
    doc, glb = tmp_path / "a.json", tmp_path / "a.glb"
    assert main(["pack", str(CONCAVE), "--size", "200x150", "--scale", "0.3", "--seed", "1", "--out", str(doc)]) == 0
    assert main(["render", str(doc), "--out", str(glb)]) == 0
    scene = trimesh.load(glb)
    arr = strew.load(doc)
    assert len(_node_translations(scene)) == len(arr)
    (geom,) = scene.geometry.values()
    z = geom.vertices[:, 2]
    assert z.max() - z.min() > 0  # a slab, not a flat decal


def test_element_without_glb_output_is_refused_and_writes_nothing(tmp_path, capsys):
    out = tmp_path / "a.svg"
    code = main(["pack", str(CONCAVE), "--size", "200x150", "--element", f"concave={SPHERE}", "--out", str(out)])
    assert code == 2
    assert "--element" in capsys.readouterr().err
    assert not out.exists()


def test_glb_output_into_a_missing_folder_is_refused_before_work(tmp_path, capsys):
    code = main(["pack", str(CONCAVE), "--size", "200x150", "--out", str(tmp_path / "nope" / "a.glb")])
    assert code == 2
    assert "does not exist" in capsys.readouterr().err

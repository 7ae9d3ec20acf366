"""``strew run``, scripts, import_svg / export_svg, and the example scripts."""

from __future__ import annotations

import json
import runpy
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

import strew
from strew._resources import example_path, examples_dir
from strew.cli import main
from strew.program import *
from strew.program import run_script

GRID_SCRIPT = """
from strew.program import *
from math import pi
g = grid_partition(stripes_properties(0, 100), stripes_properties(pi / 2, 100), KEEP_INSIDE)
def shrink(face):
    return rotate(scale(contour(face), random(face, 0.5, 0.65, 0)), random(0, 1))
arrangement = map_to_faces(shrink, g)
if __name__ == "__main__":
    export_svg(arrangement, 400)
"""


def _script(tmp_path: Path, text: str, name: str = "script.py") -> Path:
    p = tmp_path / name
    p.write_text(textwrap.dedent(text))
    return p


def test_run_writes_faces_closed_and_edges_open(tmp_path, capsys):
    script = _script(tmp_path, GRID_SCRIPT)
    out = tmp_path / "out.json"
    assert main(["run", str(script), "--size", "400", "--seed", "3", "--out", str(out), "--out", str(tmp_path / "o.svg")]) == 0
    assert "16 bounded faces" in capsys.readouterr().out
    arr = strew.load(out)
    cells = arr["cell"]
    faces, edges = np.flatnonzero(cells == "face"), np.flatnonzero(cells == "edge")
    assert len(faces) == 16 and len(edges) == 64
    shapes = arr.shapes
    assert all(p.closed for i in faces for p in shapes[arr.kinds[arr.kind[i]]].paths)
    assert all(not p.closed for i in edges for p in shapes[arr.kinds[arr.kind[i]]].paths)
    assert arr.meta["seed"] == 3 and arr.meta["params"]["size"] == 400
    assert arr.region is not None and arr.region.bounds == (0, 0, 400, 400)
    assert (tmp_path / "o.svg").read_text().startswith("<?xml")


def test_run_is_deterministic(tmp_path, monkeypatch):
    script = _script(tmp_path, GRID_SCRIPT)
    texts = []
    for sub, seed in (("a", "1"), ("b", "1"), ("c", "2")):
        d = tmp_path / sub
        d.mkdir()
        monkeypatch.chdir(d)
        assert main(["run", str(script), "--size", "400", "--seed", seed, "-q", "--out", "o.json"]) == 0
        texts.append((d / "o.json").read_bytes())
    assert texts[0] == texts[1]
    a, c = json.loads(texts[0]), json.loads(texts[2])
    assert a["elements"]["x"] != c["elements"]["x"] or a["shapes"] != c["shapes"]


def test_script_runs_as_python_would(tmp_path):
    # __file__ is set and the script's folder is on sys.path
    (tmp_path / "helper_mod_for_program.py").write_text("WIDTH = 100\n")
    script = _script(
        tmp_path,
        """
        from pathlib import Path
        from math import pi
        from helper_mod_for_program import WIDTH
        from strew.program import *
        assert Path(__file__).name == "s.py"
        arrangement = grid_partition(stripes_properties(0, WIDTH), stripes_properties(pi / 2, WIDTH), KEEP_INSIDE)
        """,
        "s.py",
    )
    pm, arr = run_script(script, size=300, seed=0)
    assert len(pm.bounded_faces) == 9 and len(arr) == 9 + pm.n_edges


@pytest.mark.parametrize(
    "body, message",
    [
        (
            """
            from strew.program import *
            g = grid_partition(stripes_properties(0, 100), stripes_properties(1.5, 100), KEEP_INSIDE)
            def m(face):
                x = 1
                return contour(face) if x > 2 else undefined_name
            arrangement = map_to_faces(m, g)
            """,
            "bad.py line 6, in mapper m: NameError: name 'undefined_name' is not defined",
        ),
        ("x = 1\n", "bad.py: no module-level 'arrangement'"),
        (
            """
            from strew.program import *
            g = grid_partition(stripes_properties(0, 100), stripes_properties(1.5, 100), KEEP_INSIDE)
            def m(face):
                return centroid(face)
            arrangement = map_to_faces(m, g)
            """,
            "bad.py line 4, mapper m: returned ndarray; a mapper must return curves",
        ),
        ("arrangement = 3\n", "bad.py: 'arrangement' is int, expected an arrangement"),
        ("import math\nmath.sqrt(-1)\n", "bad.py line 2: ValueError: math domain error"),
        ("def f(:\n", "bad.py line 1: SyntaxError"),
        (
            "from strew.program import *\narrangement = grid_partition(stripes_properties(0, -5), stripes_properties(1, 5), CROP)\n",
            "bad.py line 2: InputError: stripes_properties: widths must be positive",
        ),
    ],
)
def test_bad_scripts_exit_2_with_one_line(tmp_path, capsys, body, message):
    script = _script(tmp_path, body, "bad.py")
    out = tmp_path / "out.svg"
    assert main(["run", str(script), "--size", "300", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and message in err, err
    assert not out.exists()


def test_missing_script_and_bad_out(tmp_path, capsys):
    assert main(["run", str(tmp_path / "nope.py"), "--out", str(tmp_path / "o.svg")]) == 2
    assert "no such script" in capsys.readouterr().err
    script = _script(tmp_path, GRID_SCRIPT)
    assert main(["run", str(script), "--out", str(tmp_path / "o.txt")]) == 2
    assert "unsupported extension" in capsys.readouterr().err


def test_export_svg_with_plain_python(tmp_path):
    script = _script(tmp_path, GRID_SCRIPT, "plain.py")
    res = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr
    svg = (tmp_path / "plain.svg").read_text()
    assert svg.startswith("<?xml") and svg.count("<use") == 16 + 64
    # under strew run, export_svg writes nothing: the outputs are the --out files
    (tmp_path / "plain.svg").unlink()
    assert main(["run", str(script), "--size", "400", "-q", "--out", str(tmp_path / "x.json")]) == 0
    assert not (tmp_path / "plain.svg").exists()


def test_import_svg_reads_labelled_points_and_curves():
    zig = import_svg(example_path("program", "zig.svg"))
    assert set(zig.points) == {"start", "end"}
    assert np.allclose(point_labeled(zig, "end") - point_labeled(zig, "start"), (200, 0))
    assert len(curve_labeled(zig, "zig")) == 1
    wig = import_svg(example_path("program", "wiggles.svg"))
    assert {lab for c in wig for lab in c.labels} == {"w1", "w2", "w3"}
    for c in wig:  # every stroke runs from start to end
        assert np.allclose(c.points[0], point_labeled(wig, "start")) and np.allclose(c.points[-1], point_labeled(wig, "end"))
    blob = import_svg(example_path("program", "blob.svg"))
    assert len(blob) == 1 and blob.curves[0].closed
    with pytest.raises(strew.InputError, match="no such file"):
        import_svg("missing.svg")


#: Stated sliver tolerance: every bounded face of every example has an area above this
#: (document units squared; the snapping grid is 1e-6, so this is 10^6 grid cells).
SLIVER_AREA = 1e-6


def _panels():
    out = []
    for script in sorted((examples_dir() / "program").glob("fig*.py")):
        g = runpy.run_path(str(script))
        for name in g.get("demo_panels", ["arrangement"]):
            out.append((script.name, name))
    return out


@pytest.mark.parametrize("script, name", _panels())
def test_examples_run_without_slivers(script, name):
    pm, arr = run_script(examples_dir() / "program" / script, size=1000, seed=0, name=name)
    assert pm.n_edges > 10
    if pm.n_faces > 1:
        assert pm.face_areas().min() > SLIVER_AREA
    assert len(arr) == pm.n_edges + pm.n_faces - 1


def test_import_svg_inkscape_labels_and_transforms(tmp_path):
    svg = tmp_path / "el.svg"
    svg.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" viewBox="0 0 100 100">'
        '<g transform="translate(10 20)">'
        '<path id="path12" inkscape:label="stem" d="M 0 0 L 30 0" fill="none"/>'
        '<path id="path13" d="M 0 10 L 30 10 L 30 40 Z"/>'
        '<circle id="circle5" inkscape:label="start" cx="0" cy="0" r="1"/>'
        '<circle id="circle6" cx="50" cy="50" r="5"/>'
        "</g></svg>"
    )
    c = import_svg(svg)
    assert c.points == {"start": (10.0, 20.0)}  # the group's transform is applied
    stem = curve_labeled(c, "stem")
    assert np.allclose(stem.curves[0].points, [(10, 20), (40, 20)]) and not stem.curves[0].closed
    unlabelled = [k for k in c.curves if not k.labels]
    assert len(unlabelled) == 2 and all(k.closed for k in unlabelled)  # the triangle and the plain circle

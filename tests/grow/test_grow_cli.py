"""``strew grow`` end to end: options, outputs, determinism and bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest
import shapely

from strew import Arrangement, Shape, load, metrics, save
from strew._resources import example_path
from strew.cli import main
from strew.grow import analyze

HEX = str(example_path("grow", "scales_hex.json"))
TILES = str(example_path("grow", "tiles_near_regular.json"))
STONES = str(example_path("grow", "stones_irregular.json"))


def test_grow_fills_size_and_writes_every_format(tmp_path, capsys):
    outs = [tmp_path / "g.json", tmp_path / "g.svg", tmp_path / "g.png"]
    args = ["grow", HEX, "--size", "150x120", "--seed", "3", "--connectivity"]
    for o in outs:
        args += ["--out", str(o)]
    assert main(args) == 0
    line = capsys.readouterr().out.strip()
    assert line.startswith("grew ") and "elements/s" in line
    arr = load(outs[0])
    assert len(arr) > 150
    assert np.all((arr.x > 0) & (arr.x < 150) & (arr.y > 0) & (arr.y < 120))
    assert len(metrics.overlaps(arr)[0]) == 0
    assert arr.meta["method"] == "grow" and arr.meta["seed"] == 3
    conn = json.loads(outs[0].read_text())["connectivity"]
    assert conn["count"] == len(arr) and len(conn["edges"]) > len(arr)
    assert outs[1].read_text().startswith("<?xml") or "<svg" in outs[1].read_text()[:400]
    assert outs[2].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_count_start_mode_and_no_relax(tmp_path):
    out = tmp_path / "g.json"
    assert main(["grow", STONES, "--count", "80", "--start", "5,7", "--mode", "rotate", "--no-relax", "-q", "--out", str(out)]) == 0
    arr = load(out)
    assert len(arr) == 80
    assert arr.xy[0].tolist() == [5.0, 7.0]
    assert arr.meta["params"]["relax"] is False and arr.meta["params"]["mode"] == "rotate"


def test_same_command_same_bytes(tmp_path, monkeypatch):
    outs = []
    for d in ("a", "b"):
        (tmp_path / d).mkdir()
        monkeypatch.chdir(tmp_path / d)
        assert main(["grow", STONES, "--count", "120", "--seed", "9", "--jitter-rotation", "8", "-q", "--out", "g.json"]) == 0
        outs.append((tmp_path / d / "g.json").read_bytes())
    assert outs[0] == outs[1]


def test_flow_boundary_spray_tools(tmp_path):
    flow = tmp_path / "flow.json"
    flow.write_text(json.dumps({"paths": [{"points": [[0, 0], [100, 100]]}]}))
    out = tmp_path / "f.json"
    assert main(["grow", HEX, "--count", "60", "--flow", str(flow), "-q", "--out", str(out)]) == 0
    assert np.allclose(load(out).rotation, np.pi / 4, atol=1e-6)  # --flow implies --mode flow

    wall = tmp_path / "wall.json"
    wall.write_text(json.dumps({"paths": [{"points": [[60, -10], [60, 110]]}]}))
    out = tmp_path / "b.json"
    assert main(["grow", HEX, "--size", "100x100", "--start", "30,50", "--boundary", str(wall), "-q", "--out", str(out)]) == 0
    assert np.all(load(out).x < 60)

    spray = tmp_path / "spray.json"
    spray.write_text(json.dumps({"paths": [{"points": [[0, 0], [80, 0]]}]}))
    out = tmp_path / "s.json"
    assert main(["grow", TILES, "--spray", str(spray), "--spray-radius", "12", "-q", "--out", str(out)]) == 0
    arr = load(out)
    assert len(arr) > 10
    assert np.all(shapely.distance(shapely.LineString([[0, 0], [80, 0]]), shapely.points(arr.xy)) <= 12 + 1e-9)


def test_flip_option_changes_the_connectivity(tmp_path):
    ref = analyze(load(TILES))
    for i, j in ref.edges.tolist():
        try:
            ref.flip(i, j)
        except Exception:
            continue
        break
    a, b = tmp_path / "a.json", tmp_path / "b.json"
    assert main(["grow", TILES, "--count", "100", "-q", "--out", str(a)]) == 0
    assert main(["grow", TILES, "--count", "100", "--flip", f"{i},{j}", "-q", "--out", str(b)]) == 0
    assert load(b).meta["params"]["flips"] == [[i, j]]
    assert not np.array_equal(load(a).xy, load(b).xy)


def test_priority_and_jitter_options(tmp_path):
    out = tmp_path / "p.json"
    assert main(["grow", STONES, "--count", "60", "--priority", "gray_stone=3", "--jitter-scale", "0.1",
                 "--jitter-color", "0.2", "-q", "--out", str(out)]) == 0
    arr = load(out)
    assert arr.meta["params"]["priority"] == {"gray_stone": 3.0}
    assert "color" in arr


def _write(tmp_path, xy):
    xy = np.asarray(xy, dtype=float)
    arr = Arrangement({"dot": Shape.circle(0.4)}, np.zeros(len(xy), dtype=int), xy[:, 0], xy[:, 1])
    p = tmp_path / "ex.json"
    save(arr, p)
    return str(p)


@pytest.mark.parametrize(
    "xy, message",
    [
        ([(0, 0), (1, 0), (0, 1)], "at least four elements"),
        ([(0, 0), (1, 1), (2, 2), (3, 3)], "collinear"),
        ([(0, 0), (5, 0), (0, 5), (5, 5), (0, 5)], "duplicate positions"),
    ],
)
def test_bad_exemplars_exit_2(tmp_path, capsys, xy, message):
    ex = _write(tmp_path, xy)
    out = tmp_path / "o.json"
    assert main(["grow", ex, "--count", "10", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and message in err
    assert not out.exists()


@pytest.mark.parametrize(
    "extra, message",
    [
        ([], "give count, or a region"),
        (["--count", "5", "--flip", "0,999"], "out of range"),
        (["--count", "5", "--flip", "x"], "--flip"),
        (["--count", "5", "--priority", "scale"], "KIND=P"),
        (["--count", "5", "--priority", "nope=1"], "unknown kind"),
        (["--count", "5", "--mode", "flow"], "flow field"),
        (["--count", "5", "--spray-radius", "3"], "--spray-radius: given without spray"),
        (["--size", "50x50", "--start", "500,500"], "outside the region"),
        (["--count", "5", "--flow", "missing.json"], "no such file"),
    ],
)
def test_bad_options_exit_2(tmp_path, capsys, extra, message):
    out = tmp_path / "o.json"
    assert main(["grow", HEX, *extra, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and message in err
    assert not out.exists()


def test_start_kind_option(tmp_path):
    out = tmp_path / "k.json"
    assert main(["grow", STONES, "--count", "10", "--start-kind", "small_stone", "-q", "--out", str(out)]) == 0
    assert load(out).kind_names[0] == "small_stone"


def test_svg_exemplar_and_svg_strokes(tmp_path):
    svg = tmp_path / "walls.svg"
    svg.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="300" height="200" viewBox="0 0 300 200">'
        '<path d="M 0 100 L 300 100" fill="none" stroke="blue" transform="translate(0 20)"/></svg>'
    )
    out = tmp_path / "s.json"
    args = ["grow", str(example_path("exemplars", "tiles.svg")), "--size", "300x200", "--start", "150,40",
            "--boundary", str(svg), "-q", "--out", str(out)]
    assert main(args) == 0
    arr = load(out)
    assert len(arr) > 20
    assert np.all(arr.y < 120)  # the wall at y = 100 + 20 (transform applied) stops growth


def test_exemplar_out_carries_the_edited_connectivity(tmp_path):
    ref = analyze(load(TILES))
    for i, j in ref.edges.tolist():
        try:
            flipped = ref.flip(i, j)
        except Exception:
            continue
        break
    ex_out = tmp_path / "ex.json"
    out = tmp_path / "g.json"
    assert main(["grow", TILES, "--count", "20", "--flip", f"{i},{j}", "--exemplar-out", str(ex_out), "-q", "--out", str(out)]) == 0
    doc = json.loads(ex_out.read_text())
    assert doc["connectivity"]["edges"] == flipped.edges.tolist()
    assert doc["connectivity"]["interior"] == flipped.interior.tolist()
    # the written exemplar reproduces the run without --flip
    out2 = tmp_path / "g2.json"
    assert main(["grow", str(ex_out), "--count", "20", "-q", "--out", str(out2)]) == 0
    assert np.array_equal(load(out).xy, load(out2).xy)
    # it must be JSON
    bad = tmp_path / "ex.svg"
    assert main(["grow", TILES, "--count", "5", "--exemplar-out", str(bad), "--out", str(tmp_path / "x.json")]) == 2
    assert not (tmp_path / "x.json").exists()

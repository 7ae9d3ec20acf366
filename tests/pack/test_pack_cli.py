"""``strew pack`` through strew.cli.main: outputs, summary, determinism, exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from strew import Arrangement, Shape, load, save
from strew.cli import main
from strew.metrics import outside, overlaps

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _shape_file(tmp_path: Path, name: str, shapes: dict) -> str:
    path = tmp_path / name
    save(Arrangement(shapes, np.zeros(0, int), [], []), path)
    return str(path)


@pytest.fixture
def hook(tmp_path):
    return _shape_file(tmp_path, "hook.json", {"hook": Shape.polygon([(0, 0), (30, 0), (30, 8), (10, 8), (10, 22), (30, 22), (30, 30), (0, 30)])})


def _one_line_error(capsys, text):
    err = capsys.readouterr().err.strip().splitlines()
    errors = [line for line in err if line.startswith("strew: error:")]
    assert len(errors) == 1, err
    assert text in errors[0], errors[0]


def test_pack_writes_outputs_and_prints_count_coverage_and_time(tmp_path, capsys, hook):
    out = tmp_path / "out.json"
    svg = tmp_path / "out.svg"
    rc = main(["pack", hook, "--size", "200x160", "--scale", "0.5:0.7", "--seed", "3", "-o", str(out), "-o", str(svg)])
    assert rc == 0
    stdout = capsys.readouterr().out
    arr = load(out)
    assert f"packed {len(arr)} elements" in stdout and "coverage" in stdout and " s, fill-gap" in stdout
    assert len(overlaps(arr)[0]) == 0 and len(outside(arr)) == 0
    assert np.all((arr.scale >= 0.5) & (arr.scale <= 0.7))
    assert arr.meta["method"] == "pack" and arr.meta["seed"] == 3
    assert arr.meta["params"]["method"] == "fill-gap"
    assert svg.read_text().lstrip().startswith("<")


def test_several_files_several_kinds_region_with_hole_and_per_kind_options(tmp_path, capsys):
    out = tmp_path / "mix.json"
    rc = main([
        "pack", str(EXAMPLES / "pack" / "mix.json"), str(EXAMPLES / "pack" / "hook.json"),
        "--region", str(EXAMPLES / "pack" / "blob_with_hole.json"),
        "--scale", "0.5:0.6", "--rotate", "0:90", "--rotate", "leaf=10:20", "--margin", "star=1",
        "--seed", "1", "-q", "-o", str(out),
    ])
    assert rc == 0
    arr = load(out)
    assert set(arr.kinds) == {"leaf", "crescent", "star", "hook"}
    assert set(arr.kind_names) == set(arr.kinds)
    leaf = arr.kind_names == "leaf"
    assert np.all(np.degrees(arr.rotation[leaf]) <= 20 + 1e-9) and np.all(np.degrees(arr.rotation[leaf]) >= 10 - 1e-9)
    assert np.all(np.degrees(arr.rotation[~leaf]) <= 90 + 1e-9)
    assert len(overlaps(arr)[0]) == 0 and len(outside(arr)) == 0
    assert capsys.readouterr().out == ""  # --quiet


def test_naive_method_and_weights(tmp_path, capsys, hook):
    out = tmp_path / "naive.json"
    rc = main(["pack", hook, str(EXAMPLES / "pack" / "leaf.json"), "--size", "150x120", "--method", "naive",
               "--max-failures", "300", "--scale", "0.5:0.5", "--weight", "leaf=0", "-o", str(out)])
    assert rc == 0
    arr = load(out)
    assert set(arr.kind_names) == {"hook"}
    assert arr.meta["pack"]["stopped"] == "300 consecutive cancellations"
    assert "naive" in capsys.readouterr().out


def test_same_command_same_bytes(tmp_path, monkeypatch, hook):
    outs = []
    for sub in ("a", "b"):
        d = tmp_path / sub
        d.mkdir()
        monkeypatch.chdir(d)
        assert main(["pack", hook, "--size", "160x120", "--scale", "0.4:0.6", "--seed", "9", "-q", "-o", "p.json", "-o", "p.svg"]) == 0
        outs.append(((d / "p.json").read_bytes(), (d / "p.svg").read_bytes()))
    assert outs[0] == outs[1]


def test_svg_shapes_and_region(tmp_path):
    shapes = EXAMPLES / "shapes" / "concave.svg"
    region = EXAMPLES / "regions" / "blob_with_hole.svg"
    if not (shapes.exists() and region.exists()):
        pytest.skip("SVG examples not present")
    out = tmp_path / "svg.json"
    assert main(["pack", str(shapes), "--region", str(region), "--scale", "0.3:0.4", "-q", "-o", str(out)]) == 0
    arr = load(out)
    assert len(arr) > 10 and len(overlaps(arr)[0]) == 0 and len(outside(arr)) == 0


# -- bad input: exit 2, one line naming the problem, no output file ------------------------
def test_zero_area_shape(tmp_path, capsys):
    flat = _shape_file(tmp_path, "flat.json", {"flat": Shape.polygon([(0, 0), (10, 0), (20, 0)])})
    out = tmp_path / "o.json"
    assert main(["pack", flat, "--size", "50x50", "-o", str(out)]) == 2
    _one_line_error(capsys, "shape 'flat': exclusive region has zero area")
    assert not out.exists()


def test_self_intersecting_shape_is_repaired_with_a_warning(tmp_path, capsys):
    bow = _shape_file(tmp_path, "bow.json", {"bowtie": Shape.polygon([(0, 0), (10, 10), (10, 0), (0, 10)])})
    out = tmp_path / "o.json"
    assert main(["pack", bow, "--size", "60x60", "-o", str(out)]) == 0
    err = capsys.readouterr().err
    assert "strew: warning: shape 'bowtie': path 0 intersects itself" in err
    arr = load(out)
    assert len(arr) > 0 and len(overlaps(arr)[0]) == 0


@pytest.mark.parametrize("method", ["fill-gap", "naive"])
def test_region_smaller_than_every_shape(tmp_path, capsys, hook, method):
    out = tmp_path / "o.json"
    assert main(["pack", hook, "--size", "12x12", "--method", method, "-o", str(out)]) == 2
    _one_line_error(capsys, "no shape fits")
    assert not out.exists()


@pytest.mark.parametrize(
    "args, text",
    [
        (["--rotate", "90:10"], "--rotate: inverted range '90:10'"),
        (["--scale", "2:1"], "--scale: inverted range '2:1'"),
        (["--rotate", "hook=5:1"], "--rotate hook: inverted range '5:1'"),
        (["--scale", "0:1"], "scale[hook]: scales must be positive"),
        (["--scale", "a:b"], "--scale: expected A:B"),
        (["--margin", "wide"], "--margin: expected a number"),
        (["--weight", "nope=1"], "--weight: unknown kind 'nope'"),
        (["--max-failures", "0"], "--max-failures: must be a positive integer"),
        (["--method", "magic"], "magic"),
    ],
)
def test_bad_options(tmp_path, capsys, hook, args, text):
    out = tmp_path / "o.json"
    assert main(["pack", hook, "--size", "100x100", *args, "-o", str(out)]) == 2
    _one_line_error(capsys, text)
    assert not out.exists()


def test_missing_domain_and_missing_file(tmp_path, capsys, hook):
    out = tmp_path / "o.json"
    assert main(["pack", hook, "-o", str(out)]) == 2
    _one_line_error(capsys, "--region FILE or --size WxH")
    assert main(["pack", str(tmp_path / "nope.json"), "--size", "10x10", "-o", str(out)]) == 2
    _one_line_error(capsys, "no such file")
    assert not out.exists()


def test_help_lists_pack(capsys):
    assert main(["--help"]) == 0
    assert "pack" in capsys.readouterr().out
    assert main(["pack", "--help"]) == 0
    text = capsys.readouterr().out
    assert "--max-failures" in text and "--margin" in text and "fill-gap" in text


def test_kind_and_scale_choice_options_reach_the_library(tmp_path):
    mix = str(EXAMPLES / "pack" / "mix.json")
    cyc, fit = tmp_path / "cycle.json", tmp_path / "fit.json"
    assert main(["pack", mix, "--size", "150x130", "--scale", "0.4:0.8", "--kind-choice", "cycle", "-q", "-o", str(cyc)]) == 0
    assert main(["pack", mix, "--size", "150x130", "--scale", "0.4:0.8", "--scale-choice", "fit", "-q", "-o", str(fit)]) == 0
    a, b = load(cyc), load(fit)
    assert np.array_equal(a.kind, np.arange(len(a)) % 3)  # the paper's cycle (§3.2)
    assert a.meta["params"]["kind_choice"] == "cycle" and b.meta["params"]["scale_choice"] == "fit"
    assert b.meta["pack"]["kind_choice"] == "fit" and b.meta["pack"]["scale_choice"] == "fit"
    assert len(overlaps(b)[0]) == 0 and np.all((b.scale >= 0.4) & (b.scale <= 0.8))
    assert main(["pack", mix, "--size", "150x130", "--kind-choice", "best", "-q", "-o", str(fit)]) == 2

"""The foundation commands: render, info, --version, --help, exit codes and atomic writes."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import strew
from strew import metrics
from strew.cli import main
from strew.io.document import dumps


@pytest.fixture
def doc_path(tmp_path, two_kind_arrangement):
    p = tmp_path / "in.json"
    p.write_text(dumps(two_kind_arrangement))
    return p


def test_version(capsys):
    assert main(["--version"]) == 0
    assert capsys.readouterr().out.strip() == f"strew {strew.__version__}"


def test_render_json_to_json_is_exact(doc_path, tmp_path):
    out = tmp_path / "out.json"
    assert main(["render", str(doc_path), "--out", str(out), "-q"]) == 0
    assert out.read_bytes() == doc_path.read_bytes()


def test_render_to_several_formats(doc_path, tmp_path):
    outs = [tmp_path / "a.svg", tmp_path / "a.png", tmp_path / "b.json"]
    args = ["render", str(doc_path), "-q"]
    for o in outs:
        args += ["--out", str(o)]
    assert main(args) == 0
    assert outs[0].read_text().count("<use ") == 4
    assert outs[1].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert strew.load(outs[2]).equals(strew.load(doc_path))


def test_render_json_svg_json_keeps_elements(doc_path, tmp_path):
    svg, back = tmp_path / "a.svg", tmp_path / "back.json"
    assert main(["render", str(doc_path), "--out", str(svg), "-q"]) == 0
    assert main(["render", str(svg), "--out", str(back), "-q"]) == 0
    a, b = strew.load(doc_path), strew.load(back)
    assert len(a) == len(b)
    assert b.kind_names.tolist() == a.kind_names.tolist()
    for col in ("x", "y", "rotation", "scale"):
        np.testing.assert_allclose(b[col], a[col], atol=1e-4)


def test_info_prints_counts_bounds_and_metrics(doc_path, capsys):
    assert main(["info", str(doc_path)]) == 0
    out = capsys.readouterr().out
    for word in ("dot", "bar", "bounds", "overlaps", "coverage", "nearest neighbour"):
        assert word in out
    assert main(["info", str(doc_path), "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["counts"] == {"dot": 2, "bar": 2} and s["count"] == 4
    # the density CV is printed exactly when it can be computed (4 elements: too few cells)
    assert ("density CV" in out) == (s["density_cv"] is not None)


def test_info_json_is_strict_json_and_leaves_out_what_cannot_be_computed(capsys):
    # the stones exemplar has no region, so its density CV is undefined
    stones = Path(__file__).resolve().parents[2] / "examples" / "exemplars" / "stones.svg"
    assert main(["info", str(stones), "--json"]) == 0
    text = capsys.readouterr().out
    s = json.loads(text, parse_constant=lambda c: pytest.fail(f"non-standard JSON constant {c}"))
    assert s["density_cv"] is None and s["count"] == 30
    assert main(["info", str(stones)]) == 0
    out = capsys.readouterr().out
    assert "nan" not in out.lower() and "coverage" in out


def _doc(**elements):
    base = {"kind": ["a", "a"], "x": [0, 1], "y": [0, 1], "rotation": [0, 0], "scale": [1, 1]}
    base.update(elements)
    return json.dumps(
        {
            "format": "strew.arrangement",
            "version": 1,
            "shapes": {"a": {"paths": [{"points": [[0, 0], [1, 0], [0, 1]], "closed": True}]}},
            "elements": base,
        }
    )


BAD = {
    "malformed.json": ("{ this is not json", "malformed JSON"),
    "nan.json": (_doc(x=[0, float("nan")]), "elements.x[1]: NaN or inf"),
    "inf.json": (_doc(y=[float("inf"), 0]), "elements.y[0]: NaN or inf"),
    "mismatch.json": (_doc(y=[0]), "elements.y: length 1 does not match"),
    "unknown.json": (_doc(kind=["a", "b"]), "elements.kind[1]: unknown kind 'b'"),
    "version.json": (_doc().replace('"version": 1', '"version": 7'), "version: unsupported version 7"),
    "noshapes.svg": ('<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><text>hi</text></svg>', "no shapes"),
}


@pytest.mark.parametrize("name", sorted(BAD))
@pytest.mark.parametrize("fmt", ["json", "svg", "png"])
def test_bad_input_exits_2_with_one_line_and_no_output(name, fmt, tmp_path, capsys):
    text, message = BAD[name]
    src = tmp_path / name
    src.write_text(text)
    out = tmp_path / f"out.{fmt}"
    code = main(["render", str(src), "--out", str(out)])
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1 and err.startswith("strew: error:")
    assert message in err
    assert not out.exists()
    assert [p.name for p in tmp_path.iterdir()] == [name]  # no temporary leftovers


@pytest.mark.parametrize(
    "args, message",
    [
        (["render", "missing.json", "--out", "x.json"], "no such file"),
        (["render", "IN", "--out", "x.txt"], "unsupported extension '.txt'"),
        (["render", "IN", "--out", "nofolder/x.json"], "does not exist"),
        (["render", "IN"], "--out"),
        (["nonsense"], "No such command"),
        (["info", "IN", "--bogus"], "No such option"),
    ],
)
def test_usage_errors_exit_2(args, message, doc_path, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    args = [str(doc_path) if a == "IN" else a for a in args]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1


def test_failed_write_keeps_old_file(doc_path, tmp_path, monkeypatch):
    out = tmp_path / "keep.json"
    out.write_text("old")

    def boom(*a, **k):
        raise strew.InputError("cannot render")

    monkeypatch.setattr("strew.io.document.dumps", boom)
    assert main(["render", str(doc_path), "--out", str(out), "-q"]) == 2
    assert out.read_text() == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.json", "keep.json"]


def test_help_imports_no_heavy_module():
    code = (
        "import sys\n"
        "from strew.cli import main\n"
        "rc = main(['--help'])\n"
        "heavy = [m for m in ('numpy', 'shapely', 'scipy', 'numba', 'svgelements', 'matplotlib', 'rich') if m in sys.modules]\n"
        "print('HEAVY', heavy)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert "HEAVY []" in out
    assert "render" in out and "info" in out and "demo" in out


def test_summaries_give_the_visible_count_like_info_and_the_gallery(tmp_path, capsys):
    """One count everywhere (issue 23 point 9): void elements are not counted."""
    import re

    from strew_testing import fidelity_suite

    ex = fidelity_suite().make_exemplar("sparse_voids", np.random.default_rng(1))
    assert ex.columns["void"].any()
    strew.save(ex, tmp_path / "ex.json")
    out = tmp_path / "out.json"
    assert main(["synth", str(tmp_path / "ex.json"), "--size", "300x300", "--keep-voids", "--seed", "1", "-o", str(out)]) == 0
    said = int(re.search(r"synth: (\d+) elements", capsys.readouterr().out).group(1))
    arr = strew.load(out)
    assert arr.columns["void"].any()  # voids were kept in the document ...
    assert said == metrics.visible_count(arr) < len(arr)  # ... and the summary leaves them out

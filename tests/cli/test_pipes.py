"""``-`` reads standard input and ``--out -`` writes standard output (issue 22 point 2)."""

from __future__ import annotations

import gzip
import json
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import strew

ROOT = Path(__file__).resolve().parents[2]
STONES = ROOT / "examples" / "exemplars" / "stones.svg"


def strew_cli(*args: str, stdin: bytes | None = None, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "strew", *args], input=stdin if stdin is not None else b"",
                          capture_output=True, timeout=300, cwd=cwd)


@pytest.fixture(scope="module")
def packed(tmp_path_factory):
    d = tmp_path_factory.mktemp("pipes")
    r = strew_cli("pack", str(STONES), "--size", "200x150", "--seed", "4", "-o", str(d / "p.json"), "-q")
    assert r.returncode == 0, r.stderr
    return d / "p.json"


def test_out_dash_writes_the_same_elements_as_a_file(packed):
    r = strew_cli("pack", str(STONES), "--size", "200x150", "--seed", "4", "-o", "-", "--format", "svg")
    assert r.returncode == 0, r.stderr
    root = ET.fromstring(r.stdout)  # stdout holds the SVG and nothing else: the summary went to stderr
    assert root.tag.endswith("svg")
    assert b"packed" in r.stderr
    tmp = packed.parent / "from_stdout.svg"
    tmp.write_bytes(r.stdout)
    piped = strew.load(tmp)
    ref = strew.load(packed)
    assert len(piped) == len(ref) > 10
    np.testing.assert_allclose(np.sort(piped.x), np.sort(ref.x), atol=1e-6)


@pytest.mark.parametrize("encoding", ["json", "svg", "svgz"])
def test_dash_reads_standard_input_in_every_input_format(packed, encoding):
    ref = strew.load(packed)
    if encoding == "json":
        data = packed.read_bytes()
    else:
        svg = packed.parent / "p.svg"
        strew.save(ref, svg)
        data = svg.read_bytes() if encoding == "svg" else gzip.compress(svg.read_bytes())
    r = strew_cli("render", "-", "-o", "-", "--format", "json", stdin=data)
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    assert len(doc["elements"]["x"]) == len(ref)


def test_png_to_standard_output_and_a_file_at_once(packed, tmp_path):
    r = strew_cli("render", "-", "-o", str(tmp_path / "a.svg"), "-o", "-", "--format", "png", "--width", "64", stdin=packed.read_bytes())
    assert r.returncode == 0, r.stderr
    assert r.stdout[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "a.svg").exists()


def test_a_pipeline_synth_into_info():
    a = strew_cli("synth", str(STONES), "--size", "250x200", "--seed", "2", "-o", "-", "--format", "json", "-q")
    assert a.returncode == 0, a.stderr
    b = strew_cli("info", "-", "--json", stdin=a.stdout)
    assert b.returncode == 0, b.stderr
    assert json.loads(b.stdout)["elements"] == len(json.loads(a.stdout)["elements"]["x"]) > 20


@pytest.mark.parametrize(
    ("args", "stdin", "message"),
    [
        (["render", "IN", "-o", "-"], None, "--out -: give --format json, svg or png"),
        (["render", "IN", "-o", "OUT.svg", "--format", "svg"], None, "--format: only for --out -"),
        (["render", "IN", "-o", "-", "-o", "-", "--format", "svg"], None, "standard output can be given once"),
        (["render", "-", "-o", "OUT.svg"], b"", "standard input is empty"),
        (["render", "-", "-o", "OUT.svg"], b"hello, not a drawing", "neither a strew document (JSON) nor an SVG"),
        (["render", "-", "-o", "OUT.svg"], b"{\"format\": \"strew.arrangement\", \"version\": 1, ", "malformed JSON"),
        (["compare", "-", "-"], b"{}", "standard input can be read once"),
    ],
)
def test_bad_pipes_exit_2_with_one_line_and_write_nothing(packed, tmp_path, args, stdin, message):
    argv = [str(packed) if a == "IN" else str(tmp_path / "OUT.svg") if a == "OUT.svg" else a for a in args]
    r = strew_cli(*argv, stdin=stdin)
    err = r.stderr.decode()
    assert r.returncode == 2, err
    assert message in err and err.count("\n") == 1 and "Traceback" not in err
    assert r.stdout == b"" and not (tmp_path / "OUT.svg").exists()

"""Library messages name the Python parameter; the CLI shows its flag (issue 15)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import strew
from strew import InputError
from strew.cli import main
from strew.region import Region

SRC = Path(strew.__file__).parent
# flags whose messages came from inside the library before issue 15
FLAG_START = re.compile(r"InputError\(\s*f?\"--(flip|start|seed-point|style|brush-radius|field|repeat|size)\b")


def test_library_messages_start_with_no_cli_flag():
    found = []
    for f in sorted(SRC.rglob("*.py")):
        rel = f.relative_to(SRC).as_posix()
        if rel.startswith(("cli/", "studio/")):
            continue
        for n, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1):
            if FLAG_START.search(line):
                found.append(f"{rel}:{n}: {line.strip()}")
    assert not found, "\n".join(found)


def test_python_names_the_parameter():
    from strew.io._svg_export import _repeat_counts
    from strew.synth import brush_points

    with pytest.raises(InputError, match=r"^size: expected WxH"):
        Region.from_size("10by3")
    with pytest.raises(InputError, match=r"^brush_radius: must be positive"):
        brush_points([[[0.0, 0.0], [1.0, 0.0]]], -1.0)
    with pytest.raises(InputError, match=r"^repeat: needs at least 1x1"):
        _repeat_counts("0x3")


def test_cli_answers_with_the_flag(tmp_path, capsys):
    ex = Path(__file__).resolve().parents[2] / "examples" / "synth"
    out = str(tmp_path / "o.json")
    assert main(["pack", str(ex / "stones.json"), "--size", "60y60", "-o", out]) == 2
    assert "--size: expected WxH" in capsys.readouterr().err
    args = ["synth", str(ex / "stones.json"), "--size", "60x60", "--brush", str(ex / "stroke.json"), "--brush-radius", "-3", "-o", out]
    assert main(args) == 2
    assert "--brush-radius: must be positive" in capsys.readouterr().err

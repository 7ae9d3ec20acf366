"""The README's code runs as written, from a clone, on files the repository ships.

Every fenced ``bash`` and ``python`` block and every ``strew ...`` command of the methods
table is extracted and run in a scratch folder that sees the repository's ``examples/``.
A few lines are not run here, each for a stated reason (:data:`NOT_RUN_HERE`); any other
line that is added to the README is run, so a new example cannot go stale unseen.
"""

from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from strew.cli import main

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")

# line prefix -> why it is not run by this test
NOT_RUN_HERE = {
    "pip install": "installs packages (the Quickstart; CI runs it)",
    "bash scripts/test.sh": "runs this very suite",
    "python benchmarks/": "benchmarks take minutes; they are not tests",
    "strew demo": "tests/cli/test_demo.py runs the gallery",
    "strew studio": "starts a server; tests/studio drives it",
}


def _blocks(lang: str) -> list[str]:
    return re.findall(rf"^```{lang}\n(.*?)^```", README, re.S | re.M)


def _commands(text: str) -> list[str]:
    out = []
    for line in text.splitlines():
        line = line.split("  #")[0].strip()  # drop trailing comments
        if line and not line.startswith("#"):
            out.append(line)
    return out


def _split(command: str) -> list[list[str]]:
    """A line of ``a && b`` gives ``[a, b]``; skipped parts are dropped."""
    parts = []
    for part in command.split("&&"):
        part = part.strip()
        if any(part.startswith(p) for p in NOT_RUN_HERE):
            continue
        parts.append(shlex.split(part))
    return parts


@pytest.fixture
def clone(tmp_path, monkeypatch):
    (tmp_path / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_readme_has_blocks_and_every_skip_is_used():
    bash = [c for b in _blocks("bash") for c in _commands(b)]
    assert len(_blocks("python")) >= 1 and len(bash) >= 5
    for prefix in NOT_RUN_HERE:
        assert any(prefix in c for c in bash + _table_commands()), f"NOT_RUN_HERE entry {prefix!r} matches no README line"


@pytest.mark.slow
def test_readme_bash_blocks_run(clone):
    ran = 0
    for block in _blocks("bash"):
        for command in _commands(block):
            for argv in _split(command):
                assert argv[0] == "strew", f"README command {command!r}: only strew commands can be run here"
                assert main(argv[1:] + (["-q"] if argv[1] in _QUIET else [])) == 0, command
                ran += 1
    assert ran >= 4
    # what the commands promise is there
    assert (clone / "stones.json").exists() and (clone / "stones.png").read_bytes()[:4] == b"\x89PNG"
    assert (clone / "more-stones.svg").stat().st_size > 0


@pytest.mark.slow
def test_readme_python_blocks_run(clone):
    for block in _blocks("python"):
        proc = subprocess.run([sys.executable, "-c", block], cwd=clone, capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, proc.stderr[-2000:]
    written = [p for p in clone.iterdir() if p.suffix in {".svg", ".json", ".png"}]
    assert written, "the Python example should write a file"
    from strew import load

    for p in written:
        if p.suffix != ".png":
            assert len(load(p)) > 0, f"{p.name} holds no element"


_QUIET = {"synth", "grow", "pack", "ornament", "run"}


def _table_commands() -> list[str]:
    table = README[README.index("## Methods") :]
    table = table[: table.index("\n## ", 1)]
    return re.findall(r"^\| `(strew [^`]+)`", table, re.M)


def test_methods_table_lists_every_method():
    commands = " ".join(_table_commands())
    for name in ("pack", "ornament", "run", "grow", "synth", "studio"):
        assert f"strew {name} " in commands


@pytest.mark.slow
@pytest.mark.parametrize("command", _table_commands())
def test_methods_table_commands_run(command, clone):
    for argv in _split(command):
        assert main(argv[1:] + ["-q"]) == 0, command
        out = argv[argv.index("-o") + 1]
        from strew import load

        assert len(load(out)) > 0, f"{command!r} wrote an empty arrangement"

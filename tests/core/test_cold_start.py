"""Issue 16: a command run on an empty numba cache (a fresh install) succeeds, and says
once on stderr (a terminal) that it is compiling; a second run on the filled cache says
nothing.

A cold compile of every method takes over a minute on the shared 2-core machine (synth
about 30 s of CPU, pack fill-gap about 22 s, ornament about 17 s, grow about 3 s), so
these tests cold-start the two cheapest methods (grow, ornament) and the kernel-free
naive pack; the per-method first-run times belong to ``benchmarks/cold_start.py``.
"""

from __future__ import annotations

import json
import os
import pty
import subprocess
import sys
from pathlib import Path

import pytest

from strew._kernel_cache import kernels_cached

EX = Path(__file__).resolve().parents[2] / "examples"
MESSAGE = "compiling kernels, first run only"


def _strew(args: list[str], cache: Path) -> tuple[int, str]:
    """Exit code and stderr of a strew command whose stderr is a terminal (the compile
    message, like the progress bar, is for people watching one)."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), COLUMNS="200")
    master, slave = pty.openpty()
    proc = subprocess.Popen([sys.executable, "-m", "strew", *args], env=env, stdout=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    chunks = []
    while True:  # read while it runs (a full terminal buffer would block it)
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the command has exited and the terminal is drained
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(master)
    proc.wait(timeout=300)
    return proc.returncode, b"".join(chunks).decode(errors="replace")


@pytest.mark.slow
@pytest.mark.parametrize(
    ("method", "args", "compiles"),
    [
        ("grow", ["grow", str(EX / "exemplars/scales.svg"), "--count", "40", "--seed", "1"], True),
        ("ornament", ["ornament", "dots", "--size", "40x40", "--seed", "1"], True),
        ("pack (naive)", ["pack", str(EX / "shapes/concave.svg"), "--size", "100x80", "--method", "naive", "--seed", "1"], False),
    ],
)
def test_first_run_on_empty_cache_succeeds_and_says_so_once(tmp_path, method, args, compiles):
    cache = tmp_path / "numba-cache"
    cache.mkdir()
    out = tmp_path / "out.json"
    code, err = _strew([*args, "-o", str(out)], cache)
    assert code == 0, err
    assert len(json.loads(out.read_text())["elements"]) > 0
    assert err.count(MESSAGE) == (1 if compiles else 0)
    if compiles:
        code, err = _strew([*args, "-o", str(out)], cache)
        assert code == 0, err
        assert MESSAGE not in err


def test_quiet_or_logged_run_prints_no_compile_message(tmp_path):
    # quiet, or stderr not a terminal (a log, where errors stay one line): no message
    args = ["grow", str(EX / "exemplars/scales.svg"), "--count", "5", "--seed", "1", "-o", str(tmp_path / "o.json")]
    code, err = _strew([*args, "-q"], tmp_path / "c1")
    assert code == 0 and err == ""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "c2"))
    run = subprocess.run([sys.executable, "-m", "strew", *args], env=env, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0 and MESSAGE not in run.stderr


def test_kernel_cache_look_follows_numba_cache_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path))
    for method in ("pack", "synth", "grow", "ornament", "gallery", "program"):
        assert not kernels_cached(method)
    assert kernels_cached("pack (naive)")  # compiles nothing
    assert kernels_cached("no such method")


@pytest.mark.parametrize("cached", [False, True])
def test_studio_status_bar_says_compiling_once_per_session(tmp_path, monkeypatch, cached):
    # point 3: the studio's first spray on an empty cache shows the notice in its status
    # bar (the status message's text), once per session; a filled cache shows nothing
    import strew._kernel_cache as kc
    from strew.studio._session import Session

    asked = []
    monkeypatch.setattr(kc, "kernels_cached", lambda method: asked.append(method) or cached)
    s = Session(tmp_path, size=(300, 200))
    s.handle({"type": "load_exemplar", "example": "scales.svg"})
    seen = []
    for _ in range(2):  # two strokes
        out = s.handle({"type": "stroke_start", "tool": "spray", "radius": 30, "points": [[60.0, 100.0]]}, seen.append)
        out += s.handle({"type": "stroke_move", "points": [[120.0, 110.0]]}, seen.append)
        out += s.handle({"type": "stroke_end"}, seen.append)
        seen.extend(out)
    notices = [m for m in seen if m.get("type") == "status" and m.get("message") == MESSAGE]
    assert asked == ["grow"]  # the spray grows (Ijiri): grow's kernels, looked up once
    assert len(notices) == (0 if cached else 1)
    assert s._scene_count() > 0

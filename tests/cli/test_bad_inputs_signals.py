"""Ctrl-C (issue 17, point 6) and the all-or-none outputs (point 1).

Ctrl-C exits 130 with one line on stderr and leaves no output, whether it arrives while
a method runs (it polls ``should_cancel``), inside a compiled kernel, or elsewhere.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from strew.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture
def doc(tmp_path, two_kind_arrangement):
    from strew.io.document import dumps

    p = tmp_path / "in.json"
    p.write_text(dumps(two_kind_arrangement))
    return p


def _no_output(folder: Path, keep: set[str]) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name not in keep)


def test_keyboard_interrupt_exits_130_with_one_line(doc, tmp_path, capfd, monkeypatch):
    def interrupted(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr("strew.io.load", interrupted)
    assert main(["render", str(doc), "--out", str(tmp_path / "a.json")]) == 130
    err = capfd.readouterr().err
    assert err.strip() == "strew: error: interrupted"
    assert _no_output(tmp_path, {"in.json"}) == []


def test_interrupt_inside_a_compiled_kernel_is_an_interrupt(doc, tmp_path, capfd, monkeypatch):
    # numba re-raises a KeyboardInterrupt as SystemError("... returned a result with an exception set")
    def kernel(*a, **k):
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as exc:
            raise SystemError("CPUDispatcher(<function k>) returned a result with an exception set") from exc

    monkeypatch.setattr("strew.io.load", kernel)
    assert main(["render", str(doc), "--out", str(tmp_path / "a.json")]) == 130
    err = capfd.readouterr().err
    assert err.strip() == "strew: error: interrupted" and "Traceback" not in err


def test_a_cancelled_run_writes_nothing_even_if_the_library_finished(doc, tmp_path, capfd):
    from strew._errors import Cancelled
    from strew.cli._common import progress_bar

    before = signal.getsignal(signal.SIGINT)  # default_int_handler, or SIG_IGN when started in the background
    with pytest.raises(Cancelled):
        with progress_bar("x", quiet=True) as (_, should_cancel):
            assert signal.getsignal(signal.SIGINT) is not before
            os.kill(os.getpid(), signal.SIGINT)  # the first Ctrl-C only sets the flag
            time.sleep(0.05)
            assert should_cancel()
    # the handler is restored afterwards
    assert signal.getsignal(signal.SIGINT) is before


@pytest.mark.parametrize(
    "argv",
    [
        ["ornament", "dots", "--size", "4000x4000"],
        ["synth", str(EXAMPLES / "synth" / "stones.json"), "--size", "6000x6000"],
    ],
    ids=["ornament", "synth"],
)
def test_sigint_to_a_running_command(argv, tmp_path):
    out = tmp_path / "out.json"
    proc = subprocess.Popen(
        [sys.executable, "-m", "strew", *argv, "--out", str(out), "--out", str(tmp_path / "out.svg"), "-q"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    time.sleep(4.0)  # imports and the start of the work
    assert proc.poll() is None, proc.communicate()
    proc.send_signal(signal.SIGINT)
    try:
        _, err = proc.communicate(timeout=30)
    except subprocess.TimeoutExpired:  # pragma: no cover - the failure being tested
        proc.kill()
        pytest.fail("still running 30 s after Ctrl-C")
    assert proc.returncode == 130, err
    assert err.strip() == "strew: error: interrupted"
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_several_outputs_all_or_none(doc, tmp_path, capfd, monkeypatch):
    """A failure while writing the second output leaves neither file (nor temporaries)."""
    import strew.io._atomic as atomic

    real = os.replace
    calls = []

    def flaky(src, dst):
        calls.append(dst)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")
        return real(src, dst)

    # the first rename succeeds, the second fails: the first is undone
    monkeypatch.setattr(atomic.os, "replace", flaky)
    a, b = tmp_path / "a.json", tmp_path / "b.svg"
    code = main(["render", str(doc), "--out", str(a), "--out", str(b), "-q"])
    err = capfd.readouterr().err
    assert code == 2 and "No space left" in err and str(b) in err
    assert len(err.strip().splitlines()) == 1
    assert _no_output(tmp_path, {"in.json"}) == []
    # an existing first target gets its old contents back
    a.write_text("old")
    calls.clear()
    assert main(["render", str(doc), "--out", str(a), "--out", str(b), "-q"]) == 2
    assert a.read_text() == "old"
    assert _no_output(tmp_path, {"in.json", "a.json"}) == []


def test_payload_errors_leave_no_output(doc, tmp_path, capfd, monkeypatch):
    """Encoding every output happens before any file is created."""

    from strew import InputError

    def boom(*a, **k):
        raise InputError("cannot render PNG")

    monkeypatch.setattr("strew.io.png.to_png", boom)
    code = main(["render", str(doc), "--out", str(tmp_path / "a.json"), "--out", str(tmp_path / "b.png"), "-q"])
    assert code == 2 and "cannot render PNG" in capfd.readouterr().err
    assert _no_output(tmp_path, {"in.json"}) == []


def test_unwritable_and_long_outputs_are_refused_before_work(doc, tmp_path, capfd):
    long = tmp_path / ("y" * 240 + ".json")
    for target, token in ((Path("/proc/strew-x.json"), "cannot write"), (long, "too long")):
        code = main(["render", str(doc), "--out", str(tmp_path / "first.json"), "--out", str(target), "-q"])
        err = capfd.readouterr().err
        assert code == 2 and token in err and "--out" in err, err
        assert _no_output(tmp_path, {"in.json"}) == []

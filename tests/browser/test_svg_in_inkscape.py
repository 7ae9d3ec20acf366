"""Exported SVG survives a trip through Inkscape: it opens without warnings and, saved
again by Inkscape, imports back with the same elements. Runs where Inkscape is
installed (``apt-get install inkscape``); scripts/test.sh does not install it."""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest

import strew
from strew._resources import example_path

INKSCAPE = shutil.which("inkscape")


@pytest.mark.skipif(INKSCAPE is None, reason="inkscape is not installed")
@pytest.mark.parametrize("name", ["stones", "leaves"])
def test_inkscape_round_trip(name, tmp_path):
    a = strew.load(example_path("exemplars", f"{name}.svg"))
    src = tmp_path / "a.svg"
    strew.save(a, src)
    out = tmp_path / "inkscape.svg"
    proc = subprocess.run(
        [INKSCAPE, str(src), "--export-type=svg", f"--export-filename={out}"],
        capture_output=True,
        text=True,
        timeout=120,
        env={"HOME": str(tmp_path), "PATH": "/usr/bin:/bin"},
    )
    assert proc.returncode == 0
    warnings = [line for line in proc.stderr.splitlines() if "WARNING" in line and "Gtk" not in line]
    assert warnings == []
    b = strew.load(out)
    assert b.kind_names.tolist() == a.kind_names.tolist()
    for col in ("x", "y", "scale"):
        np.testing.assert_allclose(b[col], a[col], atol=1e-4)
    np.testing.assert_allclose(np.angle(np.exp(1j * (b.rotation - a.rotation))), 0, atol=1e-4)

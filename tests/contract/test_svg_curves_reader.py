"""program.import_svg reads through strew.io.svg (issue 15 point 5): no SVG parsing of its own."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import strew
from strew._resources import example_path
from strew.io.svg import read_svg_curves
from strew.program import import_svg


def test_no_program_module_parses_svg_itself():
    for f in (Path(strew.__file__).parent / "program").rglob("*.py"):
        assert "svgelements" not in f.read_text(encoding="utf-8"), f.name


def test_import_svg_is_the_io_reading():
    f = example_path("program", "wiggles.svg")
    curves, points = read_svg_curves(f, tolerance=3.0)
    got = import_svg(f, tolerance=3.0)
    assert got.points == points and set(points) >= {"start", "end"}
    assert len(got.curves) == len(curves) == 3
    for c, (xy, closed, label) in zip(got.curves, curves):
        assert np.array_equal(c.points, xy) and c.closed == closed and c.labels == frozenset([label])

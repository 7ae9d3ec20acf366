"""The example scripts of examples/program against the paper (issue 21, points 7-9):
puzzle tabs on both sides, non-empty panels at every size, a warning for empty ones."""

from __future__ import annotations

import runpy
import textwrap
from pathlib import Path

import numpy as np
import pytest

from strew.cli import main
from strew.program import run_script, run_size

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "program"


def _panels():
    out = []
    for script in sorted(EXAMPLES.glob("fig*.py")):
        g = runpy.run_path(str(script))
        for name in g.get("demo_panels", ["arrangement"]):
            out.append((script.name, name))
    return out


def _tab_sides(arr) -> np.ndarray:
    """Side (+1 / -1) of each tab curve's bulge about its chord, the chord pointed along
    +x (or +y when it is closer to vertical): a geometric side, whatever the direction
    the curve was drawn in."""
    sides = []
    for i in np.flatnonzero(arr["cell"] == "edge"):
        if "tab" not in str(arr["labels"][i]).split():
            continue
        p = arr.shapes[arr.kind_names[i]].paths[0].points
        u = p[-1] - p[0]
        u = u if (u[0] > 0 if abs(u[0]) >= abs(u[1]) else u[1] > 0) else -u
        cross = u[0] * (p[:, 1] - p[0, 1]) - u[1] * (p[:, 0] - p[0, 0])
        sides.append(np.sign(cross[np.argmax(np.abs(cross))]))
    return np.asarray(sides)


def test_puzzle_tabs_take_both_orientations():
    # MatchPoints is orientation-preserving (Table 3), so the example turns a tab over by
    # matching its start to the edge's target, not by rotating it first
    _, arr = run_script(EXAMPLES / "fig07_mappers.py", size=800, seed=0, name="puzzle")
    sides = _tab_sides(arr)
    assert len(sides) > 50
    assert 0.3 < np.mean(sides > 0) < 0.7


def _sized():
    """The scripts that scale with ``run_size`` (fig06, fig07: empty or nearly so at small
    sizes before) at 400, 600 and 2000; the others draw fixed lengths, only more of them
    on a larger square, at 400 (the smallest) once each, except the slowest to build."""
    out = []
    for script, name in _panels():
        if script in ("fig06_borders.py", "fig07_mappers.py"):
            out.extend((script, name, size) for size in (400, 600, 2000))
        elif script != "fig03_two_scales.py":
            out.append((script, name, 400))
    return out


@pytest.mark.parametrize("script, name, size", _sized())
def test_examples_are_not_empty_at_other_sizes(script, name, size):
    pm, arr = run_script(EXAMPLES / script, size=size, seed=0, name=name)
    assert len(arr) > 10 and pm.n_edges > 10
    x0, y0, x1, y1 = arr.bounds  # the drawing spans a good part of the square
    assert max(x1 - x0, y1 - y0) > 0.4 * size


def _script(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "s.py"
    path.write_text(textwrap.dedent(text))
    return path


def test_run_size_is_the_size_a_script_is_run_at(tmp_path):
    s = _script(tmp_path, """
        from strew.program import *
        from strew.program import pi, run_size
        w = run_size(2000) / 4
        arrangement = grid_partition(stripes_properties(0, w), stripes_properties(pi / 2, w), CROP_ADD_BOUNDARY)
    """)
    for size in (400, 1300):
        pm, _ = run_script(s, size=size)
        assert len(pm.bounded_faces) == 16
    assert run_size(123) == 123.0  # outside a run: the script's own default


def test_run_warns_on_an_empty_arrangement(tmp_path, capsys):
    s = _script(tmp_path, """
        from strew.program import *
        from strew.program import pi
        arrangement = grid_partition(stripes_properties(0, 5000), stripes_properties(pi / 2, 5000), KEEP_INSIDE)
    """)
    out = tmp_path / "o.json"
    assert main(["run", str(s), "--size", "400", "-q", "-o", str(out)]) == 0
    err = capsys.readouterr().err
    assert "warning" in err and "empty" in err and "--size" in err
    assert main(["run", str(s), "--size", "12000", "-q", "-o", str(out)]) == 0
    assert "empty" not in capsys.readouterr().err


def _relative_luminance(color: str) -> float:
    rgb = [int(color[i : i + 2], 16) / 255 for i in (1, 3, 5)]
    lin = [c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4 for c in rgb]
    return 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2]


def test_edge_colours_read_on_white_and_on_their_faces():
    # issue 23 point 8: labelled edges were light lavender / orange, hard to see
    from strew.program._script import _PALETTE, _STROKE_PALETTE

    assert len(_STROKE_PALETTE) == len(_PALETTE)
    for c in _STROKE_PALETTE:
        assert (1.05) / (_relative_luminance(c) + 0.05) >= 4.5, c  # WCAG contrast against white
    for fill, stroke in zip(_PALETTE, _STROKE_PALETTE):
        # the face is drawn at opacity 0.45 over white
        seen = "#" + "".join(f"{round(0.45 * int(fill[i : i + 2], 16) + 0.55 * 255):02x}" for i in (1, 3, 5))
        assert (_relative_luminance(seen) + 0.05) / (_relative_luminance(stroke) + 0.05) >= 3.0, (fill, stroke)

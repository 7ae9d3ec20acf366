"""program.import_svg reads through strew.io.svg (issue 15 point 5): no SVG parsing of its
own, and one reading of SVG in strew.io: ``read_svg_curves`` walks and flattens the
document as the exemplar reader ``read_svg`` does (same user units, clones, hidden
layers, limits), and differs only in what it makes of the drawn parts."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely

import strew
from strew._errors import Cancelled
from strew._resources import example_path
from strew.io.svg import read_svg, read_svg_curves
from strew.program import curve_labeled, import_svg, point_labeled

# A drawing whose viewBox does not start at 0 and whose size is in mm (the viewport maps
# user units by 2 mm/unit and moves them by (40, 30)), with nested transforms, a clone of
# a path and a clone of a symbol, a curve, a labelled point and a hidden layer.
DRAWING = """<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"
  xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" viewBox="-40 -30 200 100" width="400mm" height="200mm">
 <defs><symbol id="tri"><path d="M 0 0 L 6 0 L 3 5 Z"/></symbol></defs>
 <g inkscape:groupmode="layer" inkscape:label="Layer 1" transform="translate(10 5)">
  <g transform="rotate(30) scale(2)"><path id="tab" d="M 0 0 L 10 0 L 10 4 L 0 4 Z"/></g>
  <path id="stroke" fill="none" d="M 20 0 C 30 -10 40 10 50 0"/>
  <use xlink:href="#tab" x="40" y="20"/>
  <use xlink:href="#tri" transform="translate(-20 30) rotate(-45)"/>
  <path id="path812" d="M 60 -10 L 80 -10"/>
 </g>
 <g inkscape:groupmode="layer" inkscape:label="sketch" style="display:none">
  <path id="guide" d="M -30 -20 L 100 -20"/>
 </g>
 <circle id="start" cx="-5" cy="7" r="1" transform="translate(3 3)"/>
</svg>"""


def _exemplar_paths(arr) -> list[tuple[np.ndarray, bool]]:
    """Every path of every element of ``read_svg``'s arrangement, placed in the world."""
    out = []
    for i, name in enumerate(arr.kind_names):
        if name == "start":
            continue
        c, s = np.cos(arr.rotation[i]) * arr.scale[i], np.sin(arr.rotation[i]) * arr.scale[i]
        for p in arr.shapes[name].paths:
            q = p.points
            out.append((np.c_[arr.x[i] + c * q[:, 0] - s * q[:, 1], arr.y[i] + s * q[:, 0] + c * q[:, 1]], bool(p.closed)))
    return out


def _line(xy: np.ndarray, closed: bool):
    return shapely.LineString(np.r_[xy, xy[:1]] if closed else xy)


@pytest.mark.parametrize("hidden", ["skip", "include"])
def test_curves_are_the_exemplar_readers_geometry(hidden):
    tol = 0.01
    curves, points = read_svg_curves(DRAWING, tolerance=tol, hidden=hidden)
    want = _exemplar_paths(read_svg(DRAWING, tolerance=tol, hidden=hidden))
    assert len(curves) == len(want) == (6 if hidden == "include" else 5)
    # in document order, the same paths: straight ones point for point, the curve within
    # the two flattenings' tolerances of each other
    for (xy, closed, _), (exp, exp_closed) in zip(curves, want):
        assert closed == exp_closed
        if len(xy) == len(exp) and np.allclose(xy, exp, rtol=0, atol=1e-9):
            continue
        assert _line(xy, closed).hausdorff_distance(_line(exp, closed), densify=0.01) <= 2 * tol
    # user units, not the viewport's millimetres: the point is where the file puts it
    assert points == {"start": pytest.approx((-2.0, 10.0))}


def test_labels_transforms_and_clones():
    curves, _ = read_svg_curves(DRAWING, tolerance=0.01, hidden="include")
    labels = [label for _, _, label in curves]
    # own label or id; an automatic id (path812) gives none; the symbol's clone takes the
    # symbol's id; the hidden layer's path its own
    assert labels == ["tab", "stroke", "tab", "tri", None, "guide"]
    tab, clone = curves[0][0], curves[2][0]
    # the layer's translate, then the group's rotate(30) scale(2)
    a = np.radians(30)
    corner = np.array([10 + 2 * 10 * np.cos(a), 5 + 2 * 10 * np.sin(a)])
    assert np.allclose(tab[:2], [[10, 5], corner])
    # the clone of the path alone: the layer's translate and the use's x, y (not the group's rotation)
    assert np.allclose(clone, [[50, 25], [60, 25], [60, 29], [50, 29]])
    stroke = curves[1][0]
    assert np.allclose(stroke[[0, -1]], [[30, 5], [60, 5]]) and len(stroke) > 10


def test_tolerance_is_the_largest_distance_to_the_curve():
    svg = '<svg xmlns="http://www.w3.org/2000/svg"><path id="c" d="M 13 0 A 13 13 0 1 1 -13 0 A 13 13 0 1 1 13 0 Z"/></svg>'
    for tol in (0.5, 0.04, 0.001):
        (xy, closed, label), = read_svg_curves(svg, tolerance=tol)[0]
        assert closed and label == "c"
        # chord midpoints lie farthest inside the circle: within tol, but not needlessly near
        mid = 0.5 * (xy + np.roll(xy, -1, axis=0))
        dev = 13 - np.hypot(mid[:, 0], mid[:, 1])
        assert np.allclose(np.hypot(xy[:, 0], xy[:, 1]), 13)
        assert tol / 4 < dev.max() <= tol
    # the default: 1/2000 of the drawing's diagonal (the circle's box: 26 x 26)
    (xy, _, _), = read_svg_curves(svg)[0]
    mid = 0.5 * (xy + np.roll(xy, -1, axis=0))
    assert (13 - np.hypot(mid[:, 0], mid[:, 1])).max() <= 26 * np.sqrt(2) / 2000


def test_examples_are_read_in_their_user_units():
    # cross.svg and petal.svg draw around (0, 0) in a viewBox from (-50, -50): the centre
    # is at 0 in the script (it was at (50, 50), the viewport's coordinates)
    cross = import_svg(example_path("program", "cross.svg"))
    assert point_labeled(cross, "center").tolist() == [0.0, 0.0]
    assert {tuple(np.abs(c.points).max(axis=0)) for c in cross} == {(20.0, 0.0), (0.0, 20.0)}
    # the petal at the scripts' tolerance: a circle of 42 points, as at its old step of 2
    petal = curve_labeled(import_svg(example_path("program", "petal.svg"), tolerance=0.04), "petal")
    pts = petal.curves[0].points
    assert len(pts) == 42 and np.allclose(np.hypot(pts[:, 0], pts[:, 1]), 13)


def test_limits_and_guards_are_the_exemplar_readers(tmp_path):
    many = tmp_path / "many.svg"
    many.write_text('<svg xmlns="http://www.w3.org/2000/svg">' + '<path d="M 0 0 L 10 0"/>' * 30 + "</svg>")
    with strew.limits(paths=20), pytest.raises(strew.InputError, match=r"^import_svg: many.svg: .*paths, over the limit of 20"):
        import_svg(many)
    assert len(import_svg(many)) == 30
    with strew.limits(file_size=100), pytest.raises(strew.InputError, match=r"^import_svg: many.svg: file of .* bytes, over the limit"):
        read_svg_curves(many, what="import_svg")
    big = tmp_path / "huge.svg"
    big.write_text('<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 1e300 0"/></svg>')
    with pytest.raises(strew.InputError, match=r"^import_svg: huge.svg: .*coordinate magnitude"):
        import_svg(big)
    xxe = tmp_path / "xxe.svg"
    xxe.write_text('<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>'
                   '<svg xmlns="http://www.w3.org/2000/svg"><path id="&xxe;" d="M0 0 L10 0"/></svg>')
    with pytest.raises(strew.InputError, match=r"^import_svg: xxe.svg: "):
        import_svg(xxe)
    with pytest.raises(strew.InputError, match="tolerance: must be a positive number"):
        read_svg_curves(DRAWING, tolerance=0)
    with pytest.raises(Cancelled):
        read_svg_curves(DRAWING, should_cancel=lambda: True)


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

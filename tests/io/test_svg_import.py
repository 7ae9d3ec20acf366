"""SVG import: Inkscape-style exemplars, shapes from any SVG, regions, errors and the examples."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

import strew
from strew import InputError
from strew._resources import example_path
from strew.io.svg import read_svg, read_svg_region, read_svg_shapes

HEAD = (
    '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
    'xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" viewBox="0 0 400 300" width="800" height="600">'
)
LEAF = "M -10,0 C -5,-6 5,-6 10,0 C 5,6 -5,6 -10,0 Z"  # symmetric about its origin
HOOK = [(0, 0), (10, 0), (10, 3), (3, 3), (3, 12), (0, 12)]  # an L: no symmetry


def rot(deg: float) -> np.ndarray:
    t = math.radians(deg)
    return np.array([[math.cos(t), -math.sin(t), 0], [math.sin(t), math.cos(t), 0], [0, 0, 1.0]])


def tr(x: float, y: float) -> np.ndarray:
    return np.array([[1, 0, x], [0, 1, y], [0, 0, 1.0]])


def sc(s: float) -> np.ndarray:
    return np.diag([s, s, 1.0])


def apply(m: np.ndarray, pts) -> np.ndarray:
    pts = np.asarray(pts, dtype=float)
    return pts @ m[:2, :2].T + m[:2, 2]


def assert_same_geometry(a: shapely.Geometry, b: shapely.Geometry, tol: float) -> None:
    assert shapely.hausdorff_distance(a, b, densify=0.05) <= tol


# -- clones ---------------------------------------------------------------------------
def inkscape_two_symbols() -> tuple[str, list[tuple[str, np.ndarray]]]:
    """Clones of two symbols in nested, transformed groups; returns (svg, [(kind, matrix)])."""
    svg = (
        HEAD
        + '<defs><symbol id="leaf" inkscape:label="leaf" style="overflow:visible">'
        f'<path d="{LEAF}" style="fill:#3a3;stroke:#121;stroke-width:0.5"/></symbol>'
        '<symbol id="sym-sq" data-kind="square"><rect x="-2" y="-2" width="4" height="4" fill="#c33"/></symbol></defs>'
        '<g inkscape:groupmode="layer" inkscape:label="Layer 1" transform="translate(100 50)">'
        '<use xlink:href="#leaf" transform="translate(10 0) rotate(30)"/>'
        '<g transform="rotate(90)"><g transform="translate(5 5)">'
        '<use xlink:href="#leaf" transform="rotate(-45)" x="2" y="1"/>'
        '<use xlink:href="#sym-sq" transform="translate(20 0) rotate(10) scale(1.5)"/>'
        "</g></g></g>"
        '<use href="#sym-sq" transform="translate(300,200) rotate(-170)"/>'
        "</svg>"
    )
    layer = tr(100, 50)
    inner = layer @ rot(90) @ tr(5, 5)
    expected = [
        ("leaf", layer @ tr(10, 0) @ rot(30)),
        ("leaf", inner @ rot(-45) @ tr(2, 1)),
        ("square", inner @ tr(20, 0) @ rot(10) @ sc(1.5)),
        ("square", tr(300, 200) @ rot(-170)),
    ]
    return svg, expected


def test_inkscape_clones_of_two_symbols():
    svg, expected = inkscape_two_symbols()
    arr = read_svg(svg)
    assert len(arr) == 4
    assert sorted(arr.kinds) == ["leaf", "square"]
    assert arr.kind_names.tolist() == [k for k, _ in expected]
    for i, (_, m) in enumerate(expected):
        x, y = m[:2, 2]
        s = math.sqrt(abs(np.linalg.det(m[:2, :2])))
        t = math.atan2(m[1, 0], m[0, 0])
        assert arr.x[i] == pytest.approx(x, abs=1e-9)
        assert arr.y[i] == pytest.approx(y, abs=1e-9)
        assert arr.scale[i] == pytest.approx(s, abs=1e-9)
        assert math.remainder(arr.rotation[i] - t, 2 * math.pi) == pytest.approx(0, abs=1e-9)
    assert arr.shapes["square"].area == pytest.approx(16)
    assert arr.shapes["leaf"].style == {"fill": "#3a3", "stroke": "#121", "stroke_width": 0.5}
    # the world geometry of every clone is the symbol drawn with the clone's full transform
    leaf_local = read_svg_shapes(f'<svg xmlns="http://www.w3.org/2000/svg"><path d="{LEAF}"/></svg>', tolerance=0.01)
    local = next(iter(leaf_local.values())).geometry
    for i, (k, m) in enumerate(expected):
        want = shapely.transform(local if k == "leaf" else shapely.box(-2, -2, 2, 2), lambda p, m=m: apply(m, p))
        assert_same_geometry(arr.geometry[i], want, 0.2)


nested = st.lists(
    st.tuples(
        st.floats(-200, 200), st.floats(-200, 200), st.floats(-180, 180), st.floats(0.2, 5)
    ),
    min_size=1,
    max_size=3,
)


@settings(max_examples=30)
@given(nested, st.floats(-50, 50), st.floats(-50, 50))
def test_clone_transform_decomposes_into_pose(groups, ux, uy):
    """Any chain of translate/rotate/uniform-scale groups, and a use's x/y, give x, y, rotation, scale."""
    open_tags = "".join(f'<g transform="translate({x!r} {y!r}) rotate({r!r}) scale({s!r})">' for x, y, r, s in groups)
    svg = (
        HEAD
        + f'<defs><symbol id="hook"><path d="M{" L".join(f"{x},{y}" for x, y in HOOK)} Z"/></symbol></defs>'
        + open_tags
        + f'<use xlink:href="#hook" x="{ux!r}" y="{uy!r}"/>'
        + "</g>" * len(groups)
        + "</svg>"
    )
    m = np.eye(3)
    for x, y, r, s in groups:
        m = m @ tr(x, y) @ rot(r) @ sc(s)
    m = m @ tr(ux, uy)
    arr = read_svg(svg)
    assert len(arr) == 1 and arr.kinds == ("hook",)
    centre = np.array([5.0, 6.0])  # bounding-box centre of the hook: its local origin
    np.testing.assert_allclose(arr.xy[0], apply(m, centre[None])[0], atol=1e-6)
    s, t = float(arr.scale[0]), float(arr.rotation[0])
    lin = s * np.array([[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]])
    np.testing.assert_allclose(lin, m[:2, :2], atol=1e-9 * max(1.0, s))
    np.testing.assert_allclose(arr.shapes["hook"].points, np.array(HOOK) - centre, atol=1e-12)


def test_mirrored_clone_gets_a_mirrored_kind():
    svg = (
        HEAD + f'<defs><symbol id="hook"><path d="M{" L".join(f"{x},{y}" for x, y in HOOK)} Z"/></symbol></defs>'
        '<use xlink:href="#hook" transform="translate(50 50)"/>'
        '<use xlink:href="#hook" transform="translate(100 50) scale(-1 1)"/></svg>'
    )
    arr = read_svg(svg)
    assert arr.kind_names.tolist() == ["hook", "hook-mirrored"]
    want = shapely.Polygon(apply(tr(100, 50) @ np.diag([-1.0, 1, 1]), HOOK))
    assert_same_geometry(arr.geometry[1], want, 1e-9)


def test_clone_of_an_object_shares_its_kind():
    svg = (
        HEAD + '<g inkscape:groupmode="layer" transform="translate(10 10)">'
        f'<path id="orig" inkscape:label="hook" transform="translate(40 40)" d="M{" L".join(f"{x},{y}" for x, y in HOOK)} Z"/>'
        "</g>"
        '<use xlink:href="#orig" transform="translate(100 0) rotate(90)"/></svg>'
    )
    arr = read_svg(svg)
    assert arr.kind_names.tolist() == ["hook", "hook"]
    original = shapely.Polygon(apply(tr(50, 50), HOOK))
    clone = shapely.Polygon(apply(tr(100, 0) @ rot(90) @ tr(40, 40), HOOK))
    assert_same_geometry(arr.geometry[0], original, 1e-9)
    assert_same_geometry(arr.geometry[1], clone, 1e-9)
    assert arr.rotation[1] == pytest.approx(math.pi / 2)


def test_symbol_labels_and_hidden_clones():
    svg = (
        HEAD + '<defs><symbol id="stem"><path d="M0,0 L0,-10" fill="none" stroke="#000"/>'
        '<circle data-label="start" cx="0" cy="0" r="0" display="none"/>'
        '<circle data-label="end" cx="0" cy="-10" r="0" display="none"/></symbol></defs>'
        '<use xlink:href="#stem" x="5"/><use xlink:href="#stem" x="9" display="none"/></svg>'
    )
    arr = read_svg(svg)
    assert len(arr) == 2
    assert arr["void"].tolist() == [False, True]
    shape = arr.shapes["stem"]
    assert shape.labels == {"start": (0.0, 5.0), "end": (0.0, -5.0)}
    assert shape.line_geometry.length == pytest.approx(10)


def test_symbol_viewbox_scales_to_the_use_size():
    svg = (
        HEAD + '<defs><symbol id="box" viewBox="0 0 10 10"><rect x="0" y="0" width="10" height="10"/></symbol></defs>'
        '<use xlink:href="#box" x="100" y="0" width="20" height="20"/></svg>'
    )
    arr = read_svg(svg)
    assert arr.scale[0] == pytest.approx(2)
    assert (arr.x[0], arr.y[0]) == pytest.approx((110, 10))
    assert_same_geometry(arr.geometry[0], shapely.box(100, 0, 120, 20), 1e-9)


def test_hidden_layer_is_read_and_marked_or_skipped_hidden_object_is_void():
    svg = (
        HEAD + '<g inkscape:groupmode="layer" style="display:none"><rect width="5" height="5"/></g>'
        '<rect x="10" width="5" height="5"/><rect x="20" width="5" height="5" style="display:none"/></svg>'
    )
    arr = read_svg(svg)  # default: hidden="include" (issue 22: 331 -> 221 elements was data loss)
    assert len(arr) == 3
    assert arr["hidden"].tolist() == [True, False, False]
    assert arr["void"].tolist() == [False, False, True]
    assert arr.x.tolist() == pytest.approx([2.5, 12.5, 22.5])
    arr = read_svg(svg, hidden="skip")  # a sketch or reference layer, left out
    assert len(arr) == 2
    assert arr["void"].tolist() == [False, True]
    assert arr.x.tolist() == pytest.approx([12.5, 22.5])
    with pytest.raises(InputError, match="hidden: expected one of include, skip"):
        read_svg(svg, hidden="maybe")


def test_missing_clone_target_is_named():
    # nothing else to read: the 'no shapes' error names the skipped clone
    with pytest.raises(InputError, match="no shapes found.*missing #nothing"):
        read_svg(HEAD + '<use xlink:href="#nothing"/></svg>')


# -- shapes from any SVG ----------------------------------------------------------------
@pytest.mark.parametrize("radius, tol", [(5.0, 0.1), (50.0, 0.1), (400.0, 0.05), (3.0, 0.01)])
@pytest.mark.parametrize("form", ["path-arcs", "circle", "path-scaled"])
def test_curves_flatten_within_tolerance(radius, tol, form):
    if form == "path-arcs":
        body = f'<path d="M {radius},0 A {radius},{radius} 0 0 1 {-radius},0 A {radius},{radius} 0 0 1 {radius},0 Z"/>'
    elif form == "circle":
        body = f'<circle cx="0" cy="0" r="{radius}"/>'
    else:  # a small circle scaled up by its group: the tolerance holds after the transform
        body = f'<g transform="scale(4)"><circle cx="0" cy="0" r="{radius / 4}"/></g>'
    shapes = read_svg_shapes(f'<svg xmlns="http://www.w3.org/2000/svg">{body}</svg>', tolerance=tol)
    (shape,) = shapes.values()
    pts = shape.points
    r = np.hypot(pts[:, 0], pts[:, 1])
    np.testing.assert_allclose(r, radius, atol=1e-9 * radius)
    # every point of every edge lies within tol of the true circle
    dense = shapely.get_coordinates(shapely.segmentize(shape.geometry.exterior, radius / 500))
    gap = radius - np.hypot(dense[:, 0], dense[:, 1])
    assert gap.max() <= tol * (1 + 1e-9)
    assert shape.area == pytest.approx(math.pi * radius**2, abs=2 * math.pi * radius * tol)
    assert shape.area < math.pi * radius**2


def test_cubic_bezier_flattens_within_tolerance():
    p = np.array([[0.0, 0.0], [30.0, 80.0], [70.0, -60.0], [100.0, 10.0]])
    tol = 0.05
    shapes = read_svg_shapes(
        f'<svg xmlns="http://www.w3.org/2000/svg"><path d="M0,0 C30,80 70,-60 100,10" fill="none" stroke="#000"/></svg>',
        tolerance=tol,
    )
    (shape,) = shapes.values()
    t = np.linspace(0, 1, 4001)[:, None]
    exact = (1 - t) ** 3 * p[0] + 3 * (1 - t) ** 2 * t * p[1] + 3 * (1 - t) * t**2 * p[2] + t**3 * p[3]
    exact = exact - exact.min(axis=0) - (exact.max(axis=0) - exact.min(axis=0)) / 2  # centred like the shape
    line = shape.line_geometry
    assert shapely.distance(line, shapely.points(exact)).max() <= tol * 1.01
    assert len(shape.points) < 200  # not absurdly fine either


def test_basic_shapes():
    svg = (
        '<svg xmlns="http://www.w3.org/2000/svg">'
        '<rect id="brick" x="10" y="20" width="30" height="10"/>'
        '<rect id="pill" x="100" y="20" width="30" height="10" rx="5"/>'
        '<circle id="disc" cx="0" cy="0" r="8"/>'
        '<ellipse id="egg" cx="50" cy="50" rx="12" ry="6"/>'
        '<line id="rod" x1="0" y1="100" x2="30" y2="140" stroke="#000"/>'
        '<polyline id="zigzag" points="0,200 10,210 20,200 30,210" fill="none" stroke="#000"/>'
        '<polygon id="tri" points="200,200 230,200 200,240"/>'
        "</svg>"
    )
    shapes = read_svg_shapes(svg, tolerance=0.01)
    assert set(shapes) == {"brick", "pill", "disc", "egg", "rod", "zigzag", "tri"}
    assert shapes["brick"].area == pytest.approx(300)
    assert shapes["brick"].bounds == pytest.approx((-15, -5, 15, 5))
    assert shapes["pill"].area == pytest.approx(20 * 10 + math.pi * 25, abs=0.5)
    assert shapes["disc"].area == pytest.approx(math.pi * 64, abs=0.6)
    assert shapes["egg"].area == pytest.approx(math.pi * 72, abs=0.6)
    assert shapes["egg"].bounds == pytest.approx((-12, -6, 12, 6), abs=1e-9)
    assert shapes["rod"].area == 0 and shapes["rod"].line_geometry.length == pytest.approx(50)
    assert shapes["zigzag"].line_geometry.length == pytest.approx(3 * math.sqrt(200))
    assert shapes["tri"].area == pytest.approx(600)


def test_nested_group_transforms_on_objects():
    svg = (
        HEAD + '<g transform="translate(100 100)"><g transform="rotate(90)"><g transform="scale(2)">'
        '<rect x="0" y="0" width="10" height="5"/></g></g></g></svg>'
    )
    arr = read_svg(svg)
    assert len(arr) == 1
    want = shapely.Polygon(apply(tr(100, 100) @ rot(90) @ sc(2), [(0, 0), (10, 0), (10, 5), (0, 5)]))
    assert_same_geometry(arr.geometry[0], want, 1e-9)
    cx, cy = want.envelope.centroid.coords[0]
    assert (arr.x[0], arr.y[0]) == pytest.approx((cx, cy))


@st.composite
def similarity(draw):
    return (draw(st.floats(-300, 300)), draw(st.floats(-300, 300)), draw(st.floats(-180, 180)), draw(st.floats(0.3, 4)))


@settings(max_examples=25)
@given(st.lists(similarity(), min_size=1, max_size=4))
def test_identical_geometry_is_one_kind(copies):
    """Copies drawn with their coordinates baked in (as Inkscape stores them) are one kind."""
    ref = np.array(HOOK, dtype=float) + (500, 500)
    paths = [ref]
    for x, y, r, s in copies:
        paths.append(apply(tr(x, y) @ rot(r) @ sc(s), HOOK))
    other = apply(tr(-400, -400), [(0, 0), (20, 0), (20, 20), (0, 20)])
    body = "".join(f'<path d="M{" L".join(f"{float(a)!r},{float(b)!r}" for a, b in p)} Z"/>' for p in paths)
    body += f'<path d="M{" L".join(f"{a},{b}" for a, b in other)} Z"/>'
    arr = read_svg(HEAD + body + "</svg>", tolerance=0.01)
    assert len(arr) == len(paths) + 1
    assert len(arr.kinds) == 2
    assert len(set(arr.kind[: len(paths)].tolist())) == 1
    assert arr.kind[-1] != arr.kind[0]
    for i, p in enumerate(paths):
        assert_same_geometry(arr.geometry[i], shapely.Polygon(p), 0.02 + 1e-6 * float(np.abs(p).max()))
    for i, (_, _, r, s) in enumerate(copies, start=1):
        assert arr.scale[i] == pytest.approx(s, rel=1e-3)
        assert math.remainder(arr.rotation[i] - math.radians(r), 2 * math.pi) == pytest.approx(0, abs=1e-3)


CURVY = [
    LEAF,
    "M -9,0 A 7,5.5 0 0 1 5,-4 L 10,0 L 5,4 A 7,5.5 0 0 1 -9,0 Z",
    "M -9,-4 C -8,-9 0,-8 2,-5 C 4,-2 6,-8 9,-4 C 12,1 7,7 0,7 C -7,7 -11,2 -9,-4 Z",
    "M 0,0 L 10,0 L 10,10 L 0,10 Z",
    "M 0,0 L 10,0 L 10,10.3 L 0,10.3 Z",  # nearly the square: must stay a kind of its own
]


@settings(max_examples=10)
@given(st.lists(st.tuples(st.integers(0, len(CURVY) - 1), similarity()), min_size=2, max_size=25))
def test_copies_of_curved_shapes_group_exactly(copies):
    body = "".join(
        f'<path d="{CURVY[k]}" transform="translate({x!r} {y!r}) rotate({r!r}) scale({s!r})"/>' for k, (x, y, r, s) in copies
    )
    arr = read_svg(HEAD + body + "</svg>", tolerance=0.05)
    truth = [k for k, _ in copies]
    assert len(arr) == len(copies)
    # the kinds found are exactly the drawn ones, relabelled
    assert len({(t, int(g)) for t, g in zip(truth, arr.kind)}) == len(set(truth)) == len(arr.kinds)
    for i, (k, (x, y, r, s)) in enumerate(copies):
        # each element's world outline is the drawn one, read on its own (no matching)
        alone = read_svg(HEAD + f'<path d="{CURVY[k]}" transform="translate({x!r} {y!r}) rotate({r!r}) scale({s!r})"/></svg>', tolerance=0.001)
        assert_same_geometry(arr.geometry[i], alone.geometry[0], 0.1)


def test_round_copies_of_a_circle_keep_rotation_zero():
    svg = HEAD + '<circle cx="10" cy="10" r="3"/><circle cx="50" cy="10" r="3"/><ellipse cx="90" cy="10" rx="6" ry="6"/></svg>'
    arr = read_svg(svg, tolerance=0.01)
    assert arr.kinds == ("shape",)
    np.testing.assert_allclose(arr.rotation, 0)
    np.testing.assert_allclose(arr.scale, [1, 1, 2], rtol=1e-3)
    np.testing.assert_allclose(arr.xy, [[10, 10], [50, 10], [90, 10]], atol=1e-9)


def test_data_kind_and_label_group_objects():
    square = "M0,0 L4,0 L4,4 L0,4 Z"
    svg = (
        HEAD
        + f'<path data-kind="tile" id="a1" d="{square}" transform="translate(10 10)"/>'
        + f'<path data-kind="tile" id="a2" d="{square}" transform="translate(30 10)"/>'
        + f'<path inkscape:label="marker" d="{square}" transform="translate(50 10)"/>'
        + f'<path id="stone-1" d="M0,0 L6,0 L3,5 Z" transform="translate(10 40)"/>'
        + f'<path id="stone-2" d="M0,0 L6,0 L3,5 Z" transform="translate(30 40) rotate(40)"/>'
        + f'<path id="stone-3" d="M0,0 L9,0 L0,2 Z" transform="translate(50 40)"/>'
        + "</svg>"
    )
    arr = read_svg(svg)
    assert arr.kind_names.tolist() == ["tile", "tile", "marker", "stone", "stone", "stone-2"]
    assert arr.rotation[4] == pytest.approx(math.radians(40))


def test_touching_group_is_one_object_separate_group_is_not():
    svg = (
        HEAD
        + '<g id="g1" transform="translate(50 50)"><path d="M-10,0 C-5,-6 5,-6 10,0 C5,6 -5,6 -10,0 Z"/>'
        '<path d="M-9,0 L9,0" fill="none" stroke="#000"/></g>'
        '<g id="g2"><rect x="0" y="100" width="5" height="5"/><rect x="20" y="100" width="5" height="5"/>'
        '<rect x="40" y="100" width="5" height="5"/></g></svg>'
    )
    arr = read_svg(svg)
    assert len(arr) == 4
    assert arr.kind_names.tolist()[1:] == [arr.kind_names[1]] * 3
    assert arr.kind_names[0] != arr.kind_names[1]
    assert (arr.x[0], arr.y[0]) == pytest.approx((50, 50), abs=1e-6)


def test_shape_d_is_exact_in_local_coordinates():
    svg = f'<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(40 30) rotate(25)"><path id="leaf" d="{LEAF} M 0,-20 A 5,3 10 0 1 8,-18"/></g></svg>'
    (shape,) = read_svg_shapes(svg, tolerance=0.01).values()
    assert shape.d is not None
    again = read_svg_shapes(f'<svg xmlns="http://www.w3.org/2000/svg"><path d="{shape.d}"/></svg>', tolerance=0.01)
    (flat,) = again.values()
    # the exact d of the centred shape flattens to the centred shape itself
    x0, y0, x1, y1 = shapely.bounds(shapely.multipoints(np.concatenate([p.points for p in flat.paths])))
    shift = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    np.testing.assert_allclose(shift, 0, atol=0.02)
    assert_same_geometry(flat.geometry, shape.geometry, 0.03)


def test_source_may_be_text_bytes_or_path(tmp_path):
    svg, _ = inkscape_two_symbols()
    (tmp_path / "a.svg").write_text(svg, encoding="utf-8")
    from_text = read_svg(svg)
    from_bytes = read_svg(svg.encode())
    from_path = read_svg(tmp_path / "a.svg")
    from_str_path = read_svg(str(tmp_path / "a.svg"))
    for other in (from_bytes, from_path, from_str_path):
        np.testing.assert_array_equal(other.xy, from_text.xy)
        assert other.kind_names.tolist() == from_text.kind_names.tolist()
    assert from_path.meta["svg_import"] == {"source": "a.svg", "tolerance": 0.1}


# -- regions ----------------------------------------------------------------------------
def test_region_with_a_hole():
    svg = '<svg xmlns="http://www.w3.org/2000/svg"><path fill-rule="evenodd" d="M0,0 H100 V80 H0 Z M20,20 H50 V50 H20 Z"/></svg>'
    region = read_svg_region(svg)
    assert region.area == pytest.approx(100 * 80 - 30 * 30)
    assert region.contains([[35, 35], [10, 10], [60, 60], [150, 10]]).tolist() == [False, True, True, False]


def test_region_picks_the_region_element_and_unites_the_rest():
    ring = "M0,0 H100 V80 H0 Z M20,20 H50 V50 H20 Z"
    svg = f'<svg xmlns="http://www.w3.org/2000/svg"><rect x="500" y="0" width="10" height="10"/><path id="region" d="{ring}"/></svg>'
    assert read_svg_region(svg).area == pytest.approx(7100)
    # without a region element: every closed path, united
    svg2 = '<svg xmlns="http://www.w3.org/2000/svg"><rect x="0" y="0" width="10" height="10"/><circle cx="100" cy="0" r="5"/></svg>'
    assert read_svg_region(svg2, tolerance=0.01).area == pytest.approx(100 + math.pi * 25, abs=0.2)


def test_region_layer_is_not_an_element():
    svg = HEAD + '<g inkscape:groupmode="layer" inkscape:label="region"><rect width="50" height="40"/></g><circle cx="10" cy="10" r="2"/></svg>'
    arr = read_svg(svg)
    assert len(arr) == 1
    assert arr.region is not None and arr.region.area == pytest.approx(2000)


# -- errors -----------------------------------------------------------------------------
@pytest.mark.parametrize("reader", [read_svg, read_svg_shapes])
def test_no_shapes_names_the_file(tmp_path, reader):
    path = tmp_path / "empty-drawing.svg"
    path.write_text(HEAD + "<defs><rect id='hidden' width='3' height='3'/></defs><text>hi</text></svg>")
    with pytest.raises(InputError, match=r"empty-drawing\.svg: no shapes found"):
        reader(path)


@pytest.mark.parametrize("reader", [read_svg, read_svg_shapes, read_svg_region])
def test_malformed_xml_names_the_file(tmp_path, reader):
    path = tmp_path / "broken.svg"
    path.write_text('<svg xmlns="http://www.w3.org/2000/svg"><g><path d="M0,0 L1,1 Z"></svg>')
    with pytest.raises(InputError, match=r"broken\.svg: malformed XML"):
        reader(path)


def test_other_bad_input():
    with pytest.raises(InputError, match="not an SVG document"):
        read_svg("<html><body/></html>")
    with pytest.raises(InputError, match="no closed path"):
        read_svg_region('<svg xmlns="http://www.w3.org/2000/svg"><path d="M0,0 L10,10" stroke="#000"/></svg>')
    with pytest.raises(InputError, match="tolerance"):
        read_svg_shapes('<svg xmlns="http://www.w3.org/2000/svg"><rect width="1" height="1"/></svg>', tolerance=0)
    with pytest.raises(InputError, match="no such file"):
        read_svg("/nonexistent/drawing.svg")
    with pytest.raises(InputError, match="cannot read its geometry"):
        read_svg('<svg xmlns="http://www.w3.org/2000/svg"><path id="p1" d="M 0 0 L foo"/></svg>')


@pytest.mark.parametrize(
    "text, problem",
    [
        (HEAD + "</svg>", "no shapes found"),
        ('<svg xmlns="http://www.w3.org/2000/svg"><g>', "malformed XML"),
    ],
)
def test_cli_bad_svg_exits_2_without_output(tmp_path, monkeypatch, capsys, text, problem):
    from strew.cli import main

    monkeypatch.chdir(tmp_path)
    (tmp_path / "in.svg").write_text(text)
    code = main(["render", "in.svg", "--out", "out.json", "--quiet"])
    assert code == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "in.svg" in err and problem in err
    assert not (tmp_path / "out.json").exists()


# -- the example files ------------------------------------------------------------------
EXEMPLARS = {
    "scales": {"scale": 36},
    "tiles": {"tile-long": 18, "tile-square": 27},
    "stones": {"stone-bean": 10, "stone-kidney": 10, "stone-wedge": 10},
    "leaves": {"leaf-oval": 16, "leaf-round": 13},
}


@pytest.mark.parametrize("name", sorted(EXEMPLARS))
def test_example_exemplars_load(name):
    arr = strew.load(example_path("exemplars", f"{name}.svg"))
    assert arr.counts() == EXEMPLARS[name]
    assert arr.region is None
    pairs = arr.sindex.query(arr.geometry, predicate="intersects")
    assert int((pairs[0] < pairs[1]).sum()) == 0, "exemplar elements overlap"
    for shape in arr.shapes.values():
        x0, y0, x1, y1 = shape.bounds
        assert (x0 + x1) / 2 == pytest.approx(0, abs=1e-9) and (y0 + y1) / 2 == pytest.approx(0, abs=1e-9)


def test_example_stones_are_randomly_rotated_and_leaves_have_curves():
    stones = strew.load(example_path("exemplars", "stones.svg"))
    assert np.ptp(stones.rotation) > math.pi
    leaves = strew.load(example_path("exemplars", "leaves.svg"))
    assert all(shape.d is not None for shape in leaves.shapes.values())
    scales = strew.load(example_path("exemplars", "scales.svg"))
    # a hexagonal lattice: every row is offset by half the spacing from the next
    rows = np.unique(np.round(scales.y, 6))
    assert len(rows) == 6
    xs = [np.sort(scales.x[np.isclose(scales.y, r)]) for r in rows]
    assert all(np.allclose(np.diff(x), 22) for x in xs)
    assert xs[1][0] - xs[0][0] == pytest.approx(11)


@pytest.mark.parametrize("name", ["elongated", "concave", "tree"])
def test_example_shapes_load(name):
    shapes = strew.load_shapes(example_path("shapes", f"{name}.svg"))
    assert list(shapes) == [name]
    shape = shapes[name]
    area = shape.area_geometry
    assert area.geom_type == "Polygon" and area.is_valid
    assert area.area < 0.9 * area.convex_hull.area  # concave, or thin and curved
    if name == "elongated":
        x0, y0, x1, y1 = shape.bounds
        assert (x1 - x0) > 3 * (y1 - y0)


def test_example_region_has_a_hole():
    region = strew.load_region(example_path("regions", "blob_with_hole.svg"))
    assert region.geometry.geom_type == "Polygon"
    assert len(region.geometry.interiors) == 1
    x0, y0, x1, y1 = region.bounds
    assert 550 < x1 - x0 <= 600 and 470 < y1 - y0 <= 520
    hole = shapely.Polygon(region.geometry.interiors[0])
    assert region.area == pytest.approx(shapely.Polygon(region.geometry.exterior).area - hole.area)
    assert not region.contains([hole.representative_point().coords[0]])[0]


def _many_paths(n: int) -> str:
    return '<svg xmlns="http://www.w3.org/2000/svg">' + "".join(f'<path d="M{3 * i} 0 l1 0 l0 {1 + i % 7} Z"/>' for i in range(n)) + "</svg>"


@pytest.mark.parametrize("reader", [read_svg, read_svg_shapes, read_svg_region])
@pytest.mark.parametrize("after", [0, 1, 37])
def test_should_cancel_stops_the_import_within_one_object(reader, after):
    from strew._errors import Cancelled

    polls = []

    def should_cancel():
        polls.append(1)
        return len(polls) > after

    with pytest.raises(Cancelled, match="cancelled"):
        reader(_many_paths(60), should_cancel=should_cancel)
    assert len(polls) == after + 1  # it stops at the first poll that says so
    # polled at least once per object: a never-cancelling hook is asked more than 60 times
    count = []
    reader(_many_paths(60), should_cancel=lambda: bool(count.append(1)))
    assert len(count) > 60


def test_should_cancel_must_be_callable():
    with pytest.raises(InputError, match="should_cancel"):
        read_svg(_many_paths(2), should_cancel=True)


def _random_drawing(rng: np.random.Generator, n: int) -> str:
    """Objects of every route through kind detection, shuffled: distinct polygons (some
    self-intersecting), exact and moved copies of an L and of a curved leaf, rects,
    circles, a touching group, a path with a hole and an open polyline."""
    parts = []
    for _ in range(n):
        x, y = rng.uniform(0, 400, 2)
        a, s = rng.uniform(0, 360), rng.uniform(0.5, 2)
        pick = int(rng.integers(9))
        if pick == 0:  # distinct polygon (random vertex order: sometimes self-intersecting)
            k = int(rng.integers(3, 9))
            pts = rng.uniform(-5, 5, (k, 2)) + (x, y)
            parts.append('<polygon points="' + " ".join(f"{p:.3f},{q:.3f}" for p, q in pts) + '"/>')
        elif pick == 1:  # a copy under a transform
            parts.append(f'<path transform="translate({x:.2f} {y:.2f}) rotate({a:.1f}) scale({s:.2f})" d="{LEAF}"/>')
        elif pick == 2:  # a moved copy with baked coordinates
            pts = apply(tr(x, y) @ rot(a) @ sc(s), HOOK)
            parts.append('<path d="M' + " L".join(f"{p:.5f},{q:.5f}" for p, q in pts) + ' Z"/>')
        elif pick == 3:
            parts.append(f'<rect x="{x:.2f}" y="{y:.2f}" width="{3 * s:.2f}" height="{2 * s:.2f}"/>')
        elif pick == 4:
            parts.append(f'<circle cx="{x:.2f}" cy="{y:.2f}" r="{s:.2f}"/>')
        elif pick == 5:  # a group of two touching parts: one object
            parts.append(f'<g transform="translate({x:.2f} {y:.2f}) rotate({a:.1f})"><rect width="4" height="1"/><rect width="1" height="4"/></g>')
        elif pick == 6:  # a hole
            parts.append(f'<path transform="translate({x:.2f} {y:.2f})" d="M0,0 H6 V6 H0 Z M2,2 H4 V4 H2 Z"/>')
        elif pick == 7:  # open polyline
            pts = rng.uniform(-5, 5, (4, 2)) + (x, y)
            parts.append('<polyline points="' + " ".join(f"{p:.3f},{q:.3f}" for p, q in pts) + '"/>')
        else:  # a distinct curved shape
            c = rng.uniform(-4, 4, 4)
            parts.append(f'<path transform="translate({x:.2f} {y:.2f})" d="M0,0 C{c[0]:.2f},{c[1]:.2f} {c[2]:.2f},{c[3]:.2f} 6,0 Q3,-3 0,0 Z"/>')
    return HEAD + "".join(parts) + "</svg>"


@settings(max_examples=12, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(1, 90))
def test_batched_signatures_match_one_by_one(seed, n):
    """Issue 17.3: signatures computed ahead in batches give the kinds, their order, the
    poses (1e-9 relative) and the shapes of reading every object on its own."""
    from strew.io import _svg_import

    text = _random_drawing(np.random.default_rng(seed), n)
    batched = read_svg(text)
    with pytest.MonkeyPatch.context() as m:
        m.setattr(_svg_import, "_MAX_BATCH", 1)
        single = read_svg(text)
    assert batched.kinds == single.kinds
    assert np.array_equal(batched.kind, single.kind)
    for f in ("x", "y", "scale"):
        u, v = getattr(batched, f), getattr(single, f)
        assert np.all(np.abs(u - v) <= 1e-9 * np.maximum(1.0, np.abs(v))), f
    assert np.all(np.abs(np.angle(np.exp(1j * (batched.rotation - single.rotation)))) <= 1e-9)
    for k in batched.kinds:
        pa, pb = batched.shapes[k].paths, single.shapes[k].paths
        assert len(pa) == len(pb)
        for p, q in zip(pa, pb):
            assert p.closed == q.closed and p.points.shape == q.points.shape
            assert np.allclose(p.points, q.points, rtol=0, atol=1e-9 * max(1.0, float(np.abs(q.points).max())))


def test_batch_grows_only_while_signatures_are_used():
    """Distinct shapes are all read ahead, in one bulk (``_Reader.prepare``; before it, in
    batches growing past 64); a file of copies reads ahead none but the first."""
    from strew.io import _svg_import

    rng = np.random.default_rng(5)
    angles = np.sort(rng.uniform(0, 2 * np.pi, (200, 6)), axis=1)
    pts = rng.uniform(2, 6, (200, 6, 1)) * np.stack([np.cos(angles), np.sin(angles)], axis=2)  # star-shaped: simple
    distinct = HEAD + "".join(
        '<polygon points="' + " ".join(f"{i * 20 + p:.3f},{q:.3f}" for p, q in poly) + '"/>' for i, poly in enumerate(pts)) + "</svg>"
    doc = _svg_import._Doc(distinct, 0.05)
    reader = _svg_import._Reader(doc)
    reader.read(all_symbols=False)
    assert len(reader.kinds) == 200 and len(reader._prep_index) == 200 and not reader._prepared
    copies = HEAD + "".join(f'<path transform="translate({i * 20} 0)" d="{LEAF}"/>' for i in range(200)) + "</svg>"
    doc = _svg_import._Doc(copies, 0.05)
    reader = _svg_import._Reader(doc)
    reader.read(all_symbols=False)
    assert len(reader.kinds) == 1 and reader._batch <= 2 and not reader._sigs and len(reader._prep_index) <= 1

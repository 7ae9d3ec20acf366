"""The array reader of SVG geometry (``strew.io._svg_flatten``) against svgelements.

The reference below is the importer's flattening as it was before issue 17 point 3: one
svgelements segment object at a time, sampled with ``npoint``. Random path data, basic
shapes and transforms must give the same polygons within 1e-9 relative.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import svgelements as se
from hypothesis import given, settings
from hypothesis import strategies as st

from strew.io._svg_flatten import flatten, from_svgelements, parse_path, parse_transform, shape_segments


def reference_flatten(segments: list, tol: float) -> list[tuple[np.ndarray, bool, bool]]:
    """The importer's flattening before issue 17.3 (svgelements segments, one at a time)."""
    out: list[tuple[np.ndarray, bool, bool]] = []
    cur: list[np.ndarray] = []
    curved = closed = False

    def finish() -> None:
        nonlocal cur, curved, closed
        if cur:
            pts = np.concatenate(cur)
            keep = np.r_[True, np.any(np.abs(np.diff(pts, axis=0)) > 1e-12, axis=1)]
            pts = pts[keep]
            ends_meet = np.allclose(pts[0], pts[-1], atol=1e-9)
            is_closed = closed or (len(pts) >= 4 and ends_meet)
            if is_closed and len(pts) > 1 and ends_meet:
                pts = pts[:-1]
            if len(pts) >= 2:
                out.append((pts, bool(is_closed), curved))
        cur, curved, closed = [], False, False

    for seg in segments:
        if isinstance(seg, se.Move):
            finish()
            if seg.end is not None:
                cur = [np.array([[seg.end.x, seg.end.y]], dtype=float)]
            continue
        if isinstance(seg, se.Close):
            closed = True
            finish()
            continue
        if seg.start is None or seg.end is None:
            continue
        if not cur:
            cur = [np.array([[seg.start.x, seg.start.y]], dtype=float)]
        if isinstance(seg, se.Line):
            cur.append(np.array([[seg.end.x, seg.end.y]], dtype=float))
            continue
        if isinstance(seg, se.QuadraticBezier):
            p = np.array([[seg.start.x, seg.start.y], [seg.control.x, seg.control.y], [seg.end.x, seg.end.y]])
            bound = 2 * np.linalg.norm(p[0] - 2 * p[1] + p[2])
        elif isinstance(seg, se.CubicBezier):
            p = np.array([[seg.start.x, seg.start.y], [seg.control1.x, seg.control1.y], [seg.control2.x, seg.control2.y], [seg.end.x, seg.end.y]])
            bound = 6 * max(np.linalg.norm(p[0] - 2 * p[1] + p[2]), np.linalg.norm(p[1] - 2 * p[2] + p[3]))
        else:
            bound = float(seg.sweep) ** 2 * max(float(seg.rx), float(seg.ry))
        n = int(min(20000, max(1, math.ceil(math.sqrt(bound / (8 * tol))))))
        cur.append(np.asarray(seg.npoint(np.linspace(0.0, 1.0, n + 1)[1:]), dtype=float).reshape(-1, 2))
        curved = True
    finish()
    return out


def assert_same(segs, tol, ref, rel: float = 1e-9) -> None:
    """Same subpaths, flags and point counts; points within ``rel`` of the drawing's size.

    Both ways of :func:`flatten` are checked: arrays (``small=0``) and plain floats.
    """
    for small in (0, 10**9):
        _assert_same(flatten(segs, tol, small=small), ref, rel)


def _assert_same(fast, ref, rel: float) -> None:
    assert len(fast) == len(ref)
    for (p, c, cv), (q, d, dv) in zip(fast, ref):
        assert (c, cv) == (d, dv)
        assert p.shape == q.shape
        np.testing.assert_allclose(p, q, rtol=0, atol=rel * max(1.0, float(np.abs(q).max())))


coord = st.integers(-500, 500).map(lambda v: v / 4)
radius = st.integers(1, 400).map(lambda v: v / 4)
big_radius = st.integers(800, 2000).map(lambda v: v / 2)  # larger than half of any chord here


def arc_is_scaled(d: str) -> bool:
    """Whether an arc of ``d`` has radii too small for its chord (svgelements scales them up)."""
    return any(isinstance(s, se.Arc) and s.sweep != 0 and abs(abs(float(s.sweep)) - math.pi) < 1e-6 for s in se.Path(d).segments())


@st.composite
def path_data(draw, radius=big_radius) -> str:
    parts = [f"M{draw(coord)},{draw(coord)}"]
    for _ in range(draw(st.integers(1, 8))):
        cmd = draw(st.sampled_from("LlHhVvCcSsQqTtAaZzM"))
        if cmd in "Zz":
            parts.append(cmd)
            continue
        n = {"L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "M": 2}.get(cmd.upper())
        if cmd in "Aa":
            vals = [draw(radius), draw(radius), draw(st.integers(-180, 360)), draw(st.sampled_from([0, 1])), draw(st.sampled_from([0, 1])), draw(coord), draw(coord)]
        else:
            vals = [draw(coord) for _ in range(n * draw(st.integers(1, 2)))]
        parts.append(cmd + " ".join(f"{v:g}" for v in vals))
    return " ".join(parts)


@settings(max_examples=60)
@given(path_data(), st.sampled_from([0.01, 0.1, 1.0]))
def test_path_data_flattens_as_svgelements_does(d, tol):
    segs = parse_path(d)
    assert segs is not None
    ref = reference_flatten(list(se.Path(d).segments()), tol)
    assert_same(segs, tol, ref)
    # svgelements' segments converted to the table flatten the same way too (the fallback)
    assert_same(from_svgelements(list(se.Path(d).segments())), tol, ref)


@settings(max_examples=40)
@given(path_data(radius=radius), st.sampled_from([0.01, 0.1, 1.0]))
def test_arcs_with_scaled_radii_match_within_svgelements_rounding(d, tol):
    """Where an arc's radii are scaled up to reach its end point, its centre is the chord's
    midpoint; svgelements puts it sqrt(rounding error) (~1e-8 of the radius) away, so the
    comparison allows 1e-7 there and 1e-9 everywhere else."""
    segs = parse_path(d)
    assert segs is not None
    ref = reference_flatten(list(se.Path(d).segments()), tol)
    assert_same(segs, tol, ref, 1e-7 if arc_is_scaled(d) else 1e-9)


@pytest.mark.parametrize(
    "d",
    [
        "M0,0 L10,0 10,10z",  # implicit lines, lower-case close
        "m1,1 10,0 0,10 z m5,5 h3 v3 h-3 z",  # relative moves after a close
        "M0,0 C1,2 3,4 5,0 S9,-4 10,0 T20,0",  # S after C, T after S (svgelements reflects)
        "M0,0 Q5,5 10,0 T20,0 S25,5 30,0",
        "M0-1.5.5e1-3", "M0,0 L1e2,1E-1",  # packed numbers, exponents
        "M0,0 A5,3 30 1,0 10,0 a0,3 0 0 1 5,5 A4,4 0 0 1 15,5",  # zero radius, equal ends
        "M0,0 A1,1 0 0 1 10,0",  # radius too small: scaled up
        "M0,0 A-5,-5 0 0 1 10,0",  # negative radii
        "M0,0 L10,0 L10,10 L0,10 L0,0",  # ends meet: closed without Z
        "M0,0 L10,0 Z L5,5",  # a segment after Z starts at the last move
    ],
)
def test_path_data_edge_cases(d):
    segs = parse_path(d)
    assert segs is not None
    for tol in (0.01, 0.5):
        assert_same(segs, tol, reference_flatten(list(se.Path(d).segments()), tol), 1e-7 if arc_is_scaled(d) else 1e-9)


@pytest.mark.parametrize("d", ["M0,0 a1 1 0 01 5 5", "M0,0 L1,1 z 2", "L1,1", "M0,0 L1", "M0,0 Lz"])
def test_odd_path_data_is_left_to_svgelements(d):
    assert parse_path(d) is None


@settings(max_examples=60)
@given(st.sampled_from(["circle", "ellipse", "rect", "line", "polygon", "polyline"]), coord, coord, radius, radius, st.sampled_from([0.01, 0.1, 1.0]))
def test_basic_shapes_flatten_as_svgelements_does(tag, x, y, a, b, tol):
    num = {"cx": x, "cy": y, "r": a, "x": x, "y": y, "width": a, "height": b, "x1": x, "y1": y, "x2": a, "y2": b}
    if tag == "ellipse":
        num.update(rx=a, ry=b)
    points = f"{x},{y} {a},{b} {x + a},{y - b}"
    shape = {
        "circle": lambda: se.Circle(cx=x, cy=y, r=a),
        "ellipse": lambda: se.Ellipse(cx=x, cy=y, rx=a, ry=b),
        "rect": lambda: se.Rect(x=x, y=y, width=a, height=b),
        "line": lambda: se.SimpleLine(x1=x, y1=y, x2=a, y2=b),
        "polygon": lambda: se.Polygon({"points": points}),
        "polyline": lambda: se.Polyline({"points": points}),
    }[tag]()
    ref = reference_flatten(list(se.Path(shape).segments()), tol)
    assert_same(shape_segments(tag, num, points), tol, ref)


transform_step = st.one_of(
    st.tuples(coord, coord).map(lambda v: f"translate({v[0]:g} {v[1]:g})"),
    coord.map(lambda v: f"translate({v:g})"),
    st.integers(-720, 720).map(lambda v: f"rotate({v / 2:g})"),
    st.tuples(st.integers(-360, 360), coord, coord).map(lambda v: f"rotate({v[0]},{v[1]:g},{v[2]:g})"),
    st.tuples(radius, radius).map(lambda v: f"scale({v[0]:g},{v[1]:g})"),
    radius.map(lambda v: f"scale({-v:g})"),
    st.integers(-60, 60).map(lambda v: f"skewX({v})"),
    st.integers(-60, 60).map(lambda v: f"skewY({v})"),
    st.lists(coord, min_size=6, max_size=6).map(lambda v: "matrix(" + ",".join(f"{a:g}" for a in v) + ")"),
)


@settings(max_examples=100)
@given(st.lists(transform_step, min_size=1, max_size=4), st.sampled_from([" ", ", ", ""]))
def test_transforms_read_as_svgelements_does(steps, sep):
    text = sep.join(steps)
    m = parse_transform(text)
    assert m is not None
    sm = se.Matrix(text)
    want = np.array([[sm.a, sm.c, sm.e], [sm.b, sm.d, sm.f]], dtype=float)
    scale = max(1.0, float(np.abs(want).max()))
    np.testing.assert_allclose(m, want, rtol=0, atol=1e-9 * scale)


@pytest.mark.parametrize("text", ["rotate(45deg)", "translate(1mm 2mm)", "translateX(4)", "scale()", "rotate(1 2)", "junk"])
def test_odd_transforms_are_left_to_svgelements(text):
    assert parse_transform(text) is None


# -- the importer's shortcuts (issue 17.3) --------------------------------------------------
HEAD = '<svg xmlns="http://www.w3.org/2000/svg">'
HOOK_D = "M0,0 L10,0 L10,3 L3,3 L3,12 L0,12 Z"


def test_copies_of_one_path_text_take_the_transform_as_pose():
    from strew.io.svg import read_svg

    body = "".join(f'<path d="{HOOK_D}" transform="translate({10 * i} 5) rotate({17 * i}) scale({1 + i / 4})"/>' for i in range(6))
    arr = read_svg(HEAD + body + "</svg>")
    assert arr.kinds == ("shape",)
    np.testing.assert_allclose(np.angle(np.exp(1j * (arr.rotation - np.radians(17 * np.arange(6))))), 0, atol=1e-9)
    np.testing.assert_allclose(arr.scale, 1 + np.arange(6) / 4, rtol=1e-12)


def test_mirrored_or_skewed_copies_of_one_path_text_are_matched_not_copied():
    from strew.io.svg import read_svg

    body = (f'<path d="{HOOK_D}"/><path d="{HOOK_D}" transform="translate(40 0) scale(-1 1)"/>'
            f'<path d="{HOOK_D}" transform="translate(80 0) skewX(20)"/><path d="{HOOK_D}" transform="translate(120 0) rotate(90)"/>')
    arr = read_svg(HEAD + body + "</svg>")
    # a mirror image and a skewed copy are other shapes; the turned copy is the hook
    assert arr.kind.tolist() == [0, 1, 2, 0]
    assert arr.rotation[3] == pytest.approx(math.pi / 2)


def test_kind_grid_finds_matches_among_many_distinct_kinds():
    """Beyond 64 kinds candidates come from a grid on moment invariants: it must not lose any."""
    from strew.io.svg import read_svg

    rng = np.random.default_rng(5)
    shapes = []
    for _ in range(90):
        t = np.sort(rng.uniform(0, 2 * np.pi, 7))
        shapes.append(np.c_[np.cos(t), np.sin(t)] * rng.uniform(2, 6, 7)[:, None])

    def d(p: np.ndarray) -> str:
        return "M" + " L".join(f"{float(x)!r},{float(y)!r}" for x, y in p) + " Z"

    body = "".join(f'<path d="{d(p + (20 * (i % 10), 20 * (i // 10)))}"/>' for i, p in enumerate(shapes))
    copies = [5, 70, 89, 70]
    for j, i in enumerate(copies):  # baked coordinates (as Inkscape stores moved copies): matched by geometry
        a = 0.3 + j
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        body += f'<path d="{d(1.5 * shapes[i] @ rot.T + (300, 40 * j))}"/>'
    arr = read_svg(HEAD + body + "</svg>")
    assert len(arr.kinds) == 90
    assert arr.kind[90:].tolist() == [arr.kind[i] for i in copies]
    np.testing.assert_allclose(arr.scale[90:], 1.5, rtol=1e-6)


def baked_path(points: np.ndarray, curve: bool = False) -> str:
    f = [f"{float(v):.5f}" for v in points.ravel()]
    if curve:  # M p0 C p1 p2 p3 Q p4 p5 Z
        return f'<path d="M{f[0]},{f[1]} C{f[2]},{f[3]} {f[4]},{f[5]} {f[6]},{f[7]} Q{f[8]},{f[9]} {f[10]},{f[11]} Z"/>'
    return '<path d="M' + " L".join(f"{f[i]},{f[i + 1]}" for i in range(0, len(f), 2)) + ' Z"/>'


@settings(max_examples=20)
@given(st.lists(st.tuples(st.floats(-200, 200), st.floats(-200, 200), st.floats(-math.pi, math.pi), st.floats(0.3, 3)), min_size=2, max_size=6))
def test_baked_copies_are_one_kind_with_exact_poses(poses):
    """Copies moved in Inkscape (numbers rewritten in the path data) share the first one's
    kind, with the pose of the move to the file's rounding (1e-5 here)."""
    from strew.io.svg import read_svg

    ctrl = np.array([[0, 0], [2, 3], [5, 3], [6, 0], [3, -2], [0, 0]], dtype=float)
    body = ""
    for x, y, a, s in poses:
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        body += baked_path(s * ctrl @ rot.T + (x, y), curve=True)
    arr = read_svg(HEAD + body + "</svg>")
    assert arr.kinds == ("shape",)
    a0, s0 = poses[0][2], poses[0][3]
    for i, (_, _, a, s) in enumerate(poses):
        assert arr.scale[i] / arr.scale[0] == pytest.approx(s / s0, rel=1e-4)
        assert math.remainder(arr.rotation[i] - arr.rotation[0] - (a - a0), 2 * math.pi) == pytest.approx(0, abs=1e-4)


def test_baked_near_copies_stay_other_kinds():
    from strew.io.svg import read_svg

    square = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], dtype=float)
    tall = np.array([[0, 0], [10, 0], [10, 10.3], [0, 10.3]], dtype=float)
    rot = np.array([[0.6, -0.8], [0.8, 0.6]])
    body = baked_path(square) + baked_path(tall + 30) + baked_path(2 * square @ rot.T + 60) + baked_path(2 * tall @ rot.T + 90)
    arr = read_svg(HEAD + body + "</svg>")
    assert arr.kind.tolist() == [0, 1, 0, 1]


def test_too_many_objects_are_refused_before_parsing():
    """The path-count limit is checked on the text: an over-limit file is refused without
    being parsed (this one is not even well-formed), naming the limit and how to raise it."""
    import strew
    from strew import InputError
    from strew.io.svg import read_svg

    paths = [f'<path d="M{i},0 l1,0 l0,1 z"/>' for i in range(150)]
    body = "".join(paths)
    with strew.limits(paths=100):
        with pytest.raises(InputError, match=r"151 paths, over the limit of 100 \(raise it with `strew --limit-paths N"):
            read_svg(HEAD + body)  # no </svg>
        # comments and declarations are not counted
        ok = '<?xml version="1.0"?><!-- <<<< -->' + HEAD + "<!-- x -->" * 120 + "".join(paths[:40]) + "</svg>"
        assert len(read_svg(ok)) == 40

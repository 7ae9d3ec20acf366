"""Round trips through SVG: JSON -> SVG -> JSON keeps every element; the SVG is well formed and renders."""

from __future__ import annotations

import math
import struct
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

import strew
from strew import Arrangement, Region, Shape

coord = st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False)
angle = st.floats(-math.pi, math.pi, allow_nan=False, exclude_min=True)
scale = st.floats(0.1, 10.0, allow_nan=False)
kind_name = st.text(alphabet="abcXYZ _-<>&'\"é0123", min_size=1, max_size=8).filter(lambda s: s.strip() == s and s)


@st.composite
def shapes_(draw) -> Shape:
    """A polygon, a circle or a shape with its origin away from its centre, with labels."""
    which = draw(st.sampled_from(["polygon", "circle", "offset", "line"]))
    w = draw(st.floats(0.5, 5))
    h = draw(st.floats(0.5, 5))
    if which == "polygon":
        shape = Shape.polygon([(-w, -h), (w, -h), (0.3 * w, h), (-w, 0.2 * h)])
    elif which == "circle":
        shape = Shape.circle(w, segments=draw(st.integers(5, 40)))
    elif which == "offset":
        # origin at the base of the shape, as a tree's would be
        shape = Shape.polygon([(0, 0), (w, -h), (0, -3 * h), (-w, -h)])
    else:
        shape = Shape(({"points": [(0, 0), (w, h), (2 * w, 0)], "closed": False},))
    labels = {"tip": (w, h)} if draw(st.booleans()) else {}
    return Shape(shape.paths, None, {"fill": "#abc"} if draw(st.booleans()) else {}, labels)


@st.composite
def arrangements(draw) -> Arrangement:
    names = draw(st.lists(kind_name, min_size=1, max_size=3, unique=True))
    shapes = {name: draw(shapes_()) for name in names}
    n = draw(st.integers(0, 15))
    kind = draw(st.lists(st.integers(0, len(names) - 1), min_size=n, max_size=n))
    columns = {}
    if draw(st.booleans()):
        columns["color"] = draw(st.lists(st.sampled_from(["#fff", "#a0b", "red"]), min_size=n, max_size=n))
    if draw(st.booleans()):
        columns["sub_id"] = draw(st.lists(st.integers(0, 1000), min_size=n, max_size=n))
    if draw(st.booleans()):
        columns["weight"] = draw(st.lists(st.floats(-100, 100, allow_nan=False), min_size=n, max_size=n))
    if draw(st.booleans()):
        columns["void"] = draw(st.lists(st.booleans(), min_size=n, max_size=n))
    region = Region.rectangle(draw(st.floats(1, 500)), draw(st.floats(1, 500))) if draw(st.booleans()) else None
    return Arrangement(
        shapes,
        np.array(kind, dtype=int),
        draw(st.lists(coord, min_size=n, max_size=n)),
        draw(st.lists(coord, min_size=n, max_size=n)),
        draw(st.lists(angle, min_size=n, max_size=n)),
        draw(st.lists(scale, min_size=n, max_size=n)),
        columns=columns,
        region=region,
        meta={"method": "test", "seed": draw(st.integers(0, 99)), "params": {"a": 0.5}, "note": "héllo <&>"},
    )


def _roundtrip(arr: Arrangement) -> tuple[Arrangement, Arrangement]:
    """JSON -> SVG -> JSON through strew.save / strew.load; returns (from JSON, from SVG via JSON)."""
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        strew.save(arr, d / "a.json")
        first = strew.load(d / "a.json")
        strew.save(first, d / "b.svg")
        strew.save(strew.load(d / "b.svg"), d / "c.json")
        return first, strew.load(d / "c.json")


@settings(max_examples=40)
@given(arrangements())
def test_json_svg_json_keeps_every_element(arr):
    first, back = _roundtrip(arr)
    assert first.equals(arr)
    assert len(back) == len(arr)
    assert back.kinds == arr.kinds
    assert back.kind_names.tolist() == arr.kind_names.tolist()
    np.testing.assert_allclose(back.x, arr.x, rtol=0, atol=1e-4)
    np.testing.assert_allclose(back.y, arr.y, rtol=0, atol=1e-4)
    np.testing.assert_allclose(back.rotation, arr.rotation, rtol=0, atol=1e-4)
    np.testing.assert_allclose(back.scale, arr.scale, rtol=0, atol=1e-4)
    # An SVG stores columns as data-* attributes on its <use> elements, so an empty
    # arrangement's (empty) columns have nowhere to live.
    assert set(back.columns) == (set(arr.columns) if len(arr) else set())
    for name, col in arr.columns.items() if len(arr) else ():
        if col.dtype.kind == "f":
            np.testing.assert_allclose(back[name].astype(float), col, rtol=1e-9, atol=1e-9)
        else:
            assert back[name].tolist() == col.tolist(), name
    for key, value in arr.meta.items():
        assert back.meta[key] == value
    for name, shape in arr.shapes.items():
        got = back.shapes[name]
        assert got.labels.keys() == shape.labels.keys()
        for label, pt in shape.labels.items():
            np.testing.assert_allclose(got.labels[label], pt, atol=1e-6)
        assert [p.closed for p in got.paths] == [p.closed for p in shape.paths]
        np.testing.assert_allclose(got.points, shape.points, atol=1e-6)
    if arr.region is None:
        assert back.region is None
    else:
        assert back.region is not None
        assert back.region.area == pytest.approx(arr.region.area, rel=1e-8)
        assert back.region.bounds == pytest.approx(arr.region.bounds, abs=1e-6)


@settings(max_examples=15)
@given(arrangements())
def test_world_geometry_survives_svg(arr):
    """Stronger than the columns: every element's world geometry is where it was."""
    _, back = _roundtrip(arr)
    for a, b in zip(arr.geometry, back.geometry):
        ca = shapely.get_coordinates(a)
        cb = shapely.get_coordinates(b)
        assert ca.shape == cb.shape
        np.testing.assert_allclose(cb, ca, atol=1e-3)


def test_saved_svg_is_well_formed_and_renders(tmp_path, two_kind_arrangement):
    from strew.io.png import svg_to_png

    path = tmp_path / "a.svg"
    strew.save(two_kind_arrangement.with_columns(void=[False, True, False, False]), path)
    root = ET.parse(path).getroot()
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    uses = list(root.iter("{http://www.w3.org/2000/svg}use"))
    assert len(uses) == len(two_kind_arrangement)
    png = svg_to_png(path.read_text(encoding="utf-8"), width=321)
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", png[16:24])
    assert width == 321 and height > 0
    # strew.save(.png) renders the same document
    strew.save(strew.load(path), tmp_path / "a.png")
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_svg_round_trip_is_deterministic(tmp_path, two_kind_arrangement):
    strew.save(two_kind_arrangement, tmp_path / "a.svg")
    one = strew.load(tmp_path / "a.svg")
    two = strew.load(tmp_path / "a.svg")
    assert one.equals(two)
    strew.save(one, tmp_path / "b.svg")
    strew.save(two, tmp_path / "c.svg")
    assert (tmp_path / "b.svg").read_bytes() == (tmp_path / "c.svg").read_bytes()


def test_void_elements_and_extra_columns_come_back(tmp_path, two_kind_arrangement):
    arr = two_kind_arrangement.with_columns(void=[True, False, False, True], tag=["a", "b", "c", "d"])
    strew.save(arr, tmp_path / "a.svg")
    back = strew.load(tmp_path / "a.svg")
    assert len(back) == 4
    assert back["void"].tolist() == [True, False, False, True]
    assert back["tag"].tolist() == ["a", "b", "c", "d"]
    assert back["color"].tolist() == arr["color"].tolist()
    np.testing.assert_allclose(back["weight"].astype(float), arr["weight"])


def test_background_is_not_an_element(tmp_path, two_kind_arrangement):
    strew.save(two_kind_arrangement, tmp_path / "a.svg", background="#fafafa")
    back = strew.load(tmp_path / "a.svg")
    assert back.kind_names.tolist() == two_kind_arrangement.kind_names.tolist()


def test_kind_named_region_is_not_the_region(tmp_path):
    arr = Arrangement({"region": Shape.circle(1)}, ["region", "region"], [0, 5], [0, 0], region=Region.rectangle(8, 3))
    strew.save(arr, tmp_path / "a.svg")
    back = strew.load(tmp_path / "a.svg")
    assert back.counts() == {"region": 2}
    assert back.region is not None and back.region.area == pytest.approx(24)


def test_cli_render_json_to_svg_to_json(tmp_path, monkeypatch, two_kind_arrangement):
    from strew.cli import main

    monkeypatch.chdir(tmp_path)
    strew.save(two_kind_arrangement, "a.json")
    assert main(["render", "a.json", "--out", "a.svg", "--quiet"]) == 0
    assert main(["render", "a.svg", "--out", "b.json", "--quiet"]) == 0
    back = strew.load("b.json")
    assert back.kind_names.tolist() == two_kind_arrangement.kind_names.tolist()
    np.testing.assert_allclose(back.xy, two_kind_arrangement.xy, atol=1e-4)
    np.testing.assert_allclose(back.rotation, two_kind_arrangement.rotation, atol=1e-4)
    np.testing.assert_allclose(back.scale, two_kind_arrangement.scale, atol=1e-4)

"""Arrangement: columns, immutability, select, concat, spatial index."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import Arrangement, InputError, Region, Shape, concat


def test_columns_are_read_only(two_kind_arrangement):
    a = two_kind_arrangement
    for name in ("kind", "x", "y", "rotation", "scale", "color"):
        with pytest.raises(ValueError):
            a[name][0] = a[name][1]


def test_inputs_are_copied():
    xs = np.array([0.0, 1.0])
    a = Arrangement({"d": Shape.circle(1)}, [0, 0], xs, [0, 0])
    xs[0] = 99
    assert a.x[0] == 0


def test_kind_by_name_and_index_agree():
    shapes = {"a": Shape.circle(1), "b": Shape.rectangle(1, 1)}
    by_name = Arrangement(shapes, ["b", "a"], [0, 1], [0, 0])
    by_index = Arrangement(shapes, [1, 0], [0, 1], [0, 0])
    assert by_name.equals(by_index)
    assert by_name.kind_names.tolist() == ["b", "a"]


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(kind=["a", "zz"]), "elements.kind[1]: unknown kind 'zz'"),
        (dict(kind=[0, 5]), "elements.kind[1]: unknown kind index 5"),
        (dict(x=[0.0]), "elements.x: length 1 does not match elements.kind length 2"),
        (dict(y=[0.0, np.nan]), "elements.y[1]: NaN or inf"),
        (dict(rotation=[np.inf, 0.0]), "elements.rotation[0]: NaN or inf"),
        (dict(columns={"color": ["red"]}), "elements.color: length 1 does not match"),
    ],
)
def test_constructor_validation_names_the_field(kwargs, message):
    args = dict(shapes={"a": Shape.circle(1)}, kind=["a", "a"], x=[0.0, 1.0], y=[0.0, 1.0])
    args.update(kwargs)
    with pytest.raises(InputError) as err:
        Arrangement(**args)
    assert message in str(err.value)


def test_select_by_mask_indices_and_slice(two_kind_arrangement):
    a = two_kind_arrangement
    m = a.select(a.kind == a.kinds.index("bar"))
    assert len(m) == 2 and set(m.kind_names) == {"bar"}
    assert m["color"].tolist() == ["#222", "#444"]
    i = a.select([3, 0])
    assert i.x.tolist() == [5.0, 1.0] and i["weight"].tolist() == [3.5, 0.5]
    s = a.select(slice(1, 3))
    assert s.x.tolist() == [5.0, 9.0]
    assert s.region == a.region and s.meta == a.meta
    with pytest.raises(InputError, match="mask has shape"):
        a.select(np.array([True, False]))


def test_concat_merges_libraries_and_fills_missing_columns():
    a = Arrangement({"dot": Shape.circle(1)}, [0, 0], [0, 1], [0, 0], columns={"w": [1.0, 2.0], "tag": ["x", "y"]})
    b = Arrangement({"sq": Shape.rectangle(1, 1), "dot": Shape.circle(1)}, ["sq", "dot"], [5, 6], [0, 0])
    c = concat([a, b])
    assert c.kinds == ("dot", "sq")
    assert c.kind_names.tolist() == ["dot", "dot", "sq", "dot"]
    assert c.x.tolist() == [0, 1, 5, 6]
    assert np.isnan(c["w"][2:]).all() and c["w"][:2].tolist() == [1.0, 2.0]
    assert c["tag"].tolist() == ["x", "y", None, None]
    assert a.concat(b).equals(c)


def test_concat_rejects_conflicting_shapes():
    a = Arrangement({"k": Shape.circle(1)}, [0], [0], [0])
    b = Arrangement({"k": Shape.circle(2)}, [0], [0], [0])
    with pytest.raises(InputError, match="kind 'k' names different shapes"):
        concat([a, b])


def test_sindex_finds_neighbours(two_kind_arrangement):
    a = two_kind_arrangement
    hits = a.sindex.query(shapely.box(0, 0, 2, 2), predicate="intersects")
    assert 0 in hits and 2 not in hits


def test_with_columns_and_replace(two_kind_arrangement):
    a = two_kind_arrangement
    b = a.with_columns(x=a.x + 1, layer=[1, 2, 3, 4])
    assert (b.x == a.x + 1).all() and b["layer"].tolist() == [1, 2, 3, 4]
    assert "layer" not in a
    assert a.without_columns("color").columns.keys() == {"weight"}
    with pytest.raises(TypeError, match="unknown field"):
        a.replace(bogus=1)


def test_empty_arrangement_behaves(two_kind_arrangement):
    e = two_kind_arrangement.select(np.zeros(4, dtype=bool))
    assert len(e) == 0
    assert e.bounds == two_kind_arrangement.region.bounds
    assert len(e.geometry) == 0
    assert e.counts() == {"dot": 0, "bar": 0}
    assert "<svg" in e._repr_svg_()


def test_repr_svg_is_an_svg(two_kind_arrangement):
    svg = two_kind_arrangement._repr_svg_()
    assert svg.count("<use ") == 4 and svg.count("<symbol ") == 2


def test_region_holes_and_queries():
    outer = [(0, 0), (10, 0), (10, 10), (0, 10)]
    hole = [(4, 4), (6, 4), (6, 6), (4, 6)]
    r = Region.from_paths([outer, hole])
    assert r.area == pytest.approx(96)
    assert r.contains([[1, 1], [5, 5], [11, 1]]).tolist() == [True, False, False]
    mask, (x0, y0, cell) = r.rasterize(1.0)
    assert mask.shape == (10, 10) and mask.sum() == 96 and not mask[4:6, 4:6].any()
    assert r.distance_to_boundary([[5, 2]])[0] == pytest.approx(2)
    assert Region.from_dict(r.to_dict()) == r


def test_region_rejects_degenerate_input():
    with pytest.raises(InputError, match="no area"):
        Region(shapely.Polygon([(0, 0), (1, 1), (2, 2)]))
    with pytest.raises(InputError, match="^size: expected WxH"):
        Region.from_size("10by3")
    with pytest.raises(InputError, match="positive"):
        Region.from_size("0x3")


def test_shape_even_odd_and_strokes():
    ring = Shape([[(0, 0), (4, 0), (4, 4), (0, 4)], [(1, 1), (3, 1), (3, 3), (1, 3)]])
    assert ring.area == pytest.approx(12)
    stroke = Shape([{"points": [(0, 0), (3, 4)], "closed": False}])
    assert stroke.area == 0 and stroke.geometry.length == pytest.approx(5)
    assert Shape.from_dict(ring.to_dict()) == ring
    with pytest.raises(InputError, match="paths\\[0\\].points: NaN or inf"):
        Shape([[(0, 0), (np.nan, 1), (1, 1)]])

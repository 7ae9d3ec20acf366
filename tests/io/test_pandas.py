"""Arrangements as data frames, and notebook display of large arrangements."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given

from strew import Arrangement, InputError, Region, Shape

from strew_testing import arrangements

pd = pytest.importorskip("pandas")


@given(arrangements())
def test_pandas_round_trip_is_exact(arr):
    df = arr.to_pandas()
    assert len(df) == len(arr)
    assert list(df.columns[:5]) == ["kind", "x", "y", "rotation", "scale"]
    assert df["kind"].astype(str).tolist() == arr.kind_names.tolist()
    back = Arrangement.from_pandas(df)
    assert back.equals(arr)


def test_frame_edits_come_back(two_kind_arrangement):
    df = two_kind_arrangement.to_pandas()
    df = df[df["kind"] == "bar"].copy()
    df["x"] += 10.0
    back = Arrangement.from_pandas(df)
    assert back.counts() == {"dot": 0, "bar": 2}
    np.testing.assert_allclose(back.x, two_kind_arrangement.x[two_kind_arrangement.kind_names == "bar"] + 10.0)
    assert back.region is not None and back.meta["seed"] == 3
    assert back["color"].tolist() == ["#222", "#444"]


def test_frame_made_by_hand_needs_shapes():
    df = pd.DataFrame({"kind": ["dot", "dot"], "x": [0.0, 4.0], "y": [1.0, 1.0]})
    with pytest.raises(InputError, match="shape library"):
        Arrangement.from_pandas(df)
    a = Arrangement.from_pandas(df, {"dot": Shape.circle(1)}, region=Region.rectangle(10, 10))
    assert len(a) == 2 and a.scale.tolist() == [1.0, 1.0] and a.region is not None


@pytest.mark.parametrize(
    "frame, message",
    [
        ({"x": [0.0], "y": [0.0]}, "column 'kind' is missing"),
        ({"kind": ["dot"], "x": [0.0]}, "column 'y' is missing"),
        ({"kind": ["nope"], "x": [0.0], "y": [0.0]}, "unknown kind 'nope'"),
        ({"kind": ["dot"], "x": [float("nan")], "y": [0.0]}, "x"),
    ],
)
def test_bad_frames_name_the_problem(frame, message):
    with pytest.raises(InputError, match=message):
        Arrangement.from_pandas(pd.DataFrame(frame), {"dot": Shape.circle(1)})


def test_not_a_frame():
    with pytest.raises(InputError, match="expected a pandas DataFrame"):
        Arrangement.from_pandas([1, 2, 3], {"dot": Shape.circle(1)})


def test_large_arrangements_show_as_png_in_notebooks(monkeypatch):
    rng = np.random.default_rng(0)
    n = 50
    a = Arrangement({"dot": Shape.circle(0.5)}, np.zeros(n, int), rng.uniform(0, 100, n), rng.uniform(0, 100, n))
    assert a._repr_svg_().lstrip().startswith("<") and a._repr_png_() is None and a._repr_html_() is None
    monkeypatch.setattr(Arrangement, "REPR_SVG_MAX_ELEMENTS", 10)
    assert a._repr_svg_() is None
    assert a._repr_png_()[:4] == b"\x89PNG"
    html = a._repr_html_()
    assert html.startswith('<img src="data:image/png;base64,') and "over 10 elements" in html

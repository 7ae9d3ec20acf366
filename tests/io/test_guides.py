"""Tool strokes drawn over a picture (``extra["guides"]``, issue 23 point 8): the SVG shows
them in their own layer, the PNG shows them, and neither import nor metrics count them."""

from __future__ import annotations

import io
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import strew
from strew import Arrangement, Region, Shape, metrics

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture
def guided():
    arr = Arrangement({"sq": Shape.rectangle(4, 4)}, [0] * 4, [10, 30, 50, 70], [20] * 4, region=Region.rectangle(80, 40))
    wall = [[40.0, 0.0], [40.0, 40.0]]
    return arr.replace(extra={"guides": [wall]})


def test_guides_layer_is_drawn_over_the_elements(guided):
    root = ET.fromstring(guided.to_svg())
    layers = [g.get("id") for g in root.iter(f"{SVG}g") if g.get("id", "").startswith("strew-")]
    assert layers[-1] == "strew-guides"
    path = next(g for g in root.iter(f"{SVG}g") if g.get("id") == "strew-guides").find(f"{SVG}path")
    assert path.get("d").startswith("M40,0 L40,40")
    assert "strew-guides" not in guided.to_svg(show_guides=False)


def test_guides_survive_json_and_are_not_elements_after_svg(tmp_path, guided):
    strew.save(guided, tmp_path / "g.json")
    strew.save(guided, tmp_path / "g.svg")
    back = strew.load(tmp_path / "g.json")
    assert back.extra["guides"] == guided.extra["guides"]
    from_svg = strew.load(tmp_path / "g.svg")
    assert len(from_svg) == len(guided) == metrics.visible_count(guided)


def test_guides_show_in_the_png(guided):
    from PIL import Image

    plain = np.asarray(Image.open(io.BytesIO(strew.io.encode(guided.replace(extra={}), "x.png", width=800))).convert("RGB"), float)
    drawn = np.asarray(Image.open(io.BytesIO(strew.io.encode(guided, "x.png", width=800))).convert("RGB"), float)
    col = drawn.shape[1] // 2  # x = 40 of 80 lies at the middle of the picture
    red = (drawn[:, col - 2:col + 3, 0] - drawn[:, col - 2:col + 3, 2]).max()
    assert red > 80 and np.abs(plain[:, col - 2:col + 3] - drawn[:, col - 2:col + 3]).max() > 80

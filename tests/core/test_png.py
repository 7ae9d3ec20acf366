"""PNG rendering through resvg."""

from __future__ import annotations

import io

import numpy as np
import pytest

import strew
from strew import Arrangement, InputError, Shape
from strew.io.png import svg_to_png, to_png


def test_png_size_and_pixels(two_kind_arrangement):
    from PIL import Image

    data = to_png(two_kind_arrangement, width=300)
    img = Image.open(io.BytesIO(data))
    assert img.size[0] == 300
    assert np.asarray(img.convert("L")).min() < 128  # something dark was drawn


@pytest.mark.parametrize("size", ['width="100mm" height="50mm"', 'width="4in" height="2in"', 'width="100%"'])
def test_inkscape_units_render(size):
    svg = f'<svg xmlns="http://www.w3.org/2000/svg" {size} viewBox="0 0 100 50"><rect width="50" height="20"/></svg>'
    assert svg_to_png(svg, width=200)[:8] == b"\x89PNG\r\n\x1a\n"


def test_bad_svg_and_width():
    with pytest.raises(InputError, match="cannot render SVG"):
        svg_to_png("<svg")
    with pytest.raises(InputError, match="width: must be positive"):
        svg_to_png("<svg/>", width=0)


def test_kind_names_that_xml_cannot_hold_are_rejected():
    with pytest.raises(InputError, match="control characters"):
        Arrangement({"bad\x01name": Shape.circle(1)}, [0], [0], [0])


def test_save_png_by_extension(tmp_path, two_kind_arrangement):
    p = tmp_path / "x.png"
    strew.save(two_kind_arrangement, p, width=64)
    assert p.read_bytes()[:4] == b"\x89PNG"
